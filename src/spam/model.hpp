// One SPAM right-hand side for a compile-time choice of terms (SpamPolicy): the evaluation order is
// neighbours -> density -> advection velocity -> dr/dt, drho/dt -> stress rates -> forces, energy, torque
// treatment. Each group of terms lives in its own header; a term that the policy switches off is not compiled.
#pragma once

#include "spam/forces.hpp"
#include "spam/kinematics.hpp"
#include "spam/work.hpp"
#include "spam/stress_rate.hpp"

namespace sph {

template <class P>
class SpamModel {
 public:
  using policy = P;
  SpamModel(const SpamParams& p, std::size_t n) : work_(p, n) {}

  /// dy = f(y): overwrites every component of dy.
  void derivative(const SpamState& y, SpamState& dy) {
    work_.gather(y.x);
    spam_density<P>(y, work_);
    spam_advection<P>(y, work_);
    spam_kinematics_rates<P>(y, work_, dy);
    spam_stress_rate<P>(y, work_, dy);
    spam_forces<P>(y, work_, dy);
  }
  /// The density in use at state y (summed, or the state's own).
  void density(const SpamState& y, std::vector<double>& rho) {
    work_.gather(y.x);
    spam_density<P>(y, work_);
    rho.assign(work_.rho.begin(), work_.rho.begin() + static_cast<long>(y.size()));
  }
  SpamWork& work() { return work_; }
  const SpamWork& work() const { return work_; }

 private:
  SpamWork work_;
};

}  // namespace sph
