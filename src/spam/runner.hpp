// The SPAM runner template and the run-time -> compile-time dispatch chain, shared by the translation units
// that instantiate it (spam_instances_*.cpp: split so the ~90 model instantiations compile in parallel).
#pragma once

#include <memory>
#include <stdexcept>

#include "core/blow_up.hpp"
#include "core/rk4.hpp"
#include "spam/model.hpp"
#include "spam/spam_solver.hpp"

namespace sph {
namespace spam_detail {

template <class P>
class SpamRunner final : public SpamSolver {
 public:
  SpamRunner(const SpamOptions& o, const SpamParams& p, const SpamState& y0)
      : options_(o), model_(p, y0.size()), y_(y0) {}

  void step(double dt) override {
    rk_.step(y_, t_, dt, [this](double, const SpamState& y, SpamState& dy) { model_.derivative(y, dy); });
    t_ += dt;
    ++steps_;
    check_state();
    if constexpr (P::closest_approach) reflect();
  }
  double time() const override { return t_; }
  long steps() const override { return steps_; }
  const SpamState& state() const override { return y_; }
  SpamState& state() override { return y_; }
  void derivative(SpamState& dy) override { resize_fields(dy, y_.size()); model_.derivative(y_, dy); }
  void density(std::vector<double>& rho) override { model_.density(y_, rho); }
  const SpamWork& work() const override { return model_.work(); }
  const SpamOptions& options() const override { return options_; }
  const SpamParams& params() const override { return model_.work().params; }
  long reflections() const override { return reflections_; }

 private:
  // A non-finite position or velocity ends the run (the body has blown apart).
  void check_state() const {
    const std::size_t bad = first_bad_particle(y_.size(), [this](std::size_t i) { return !(y_.x[i].allFinite() && y_.v[i].allFinite()); });
    if (bad < y_.size()) throw_blow_up(steps_, t_, bad, y_.x[bad], "non-finite position or velocity");
  }

  // Serial over pairs (i < j): each reflection exchanges the radial velocity components of an equal-mass
  // pair, conserving momentum, energy and angular momentum.
  void reflect() {
    SpamWork& wk = model_.work();
    wk.gather(y_.x);
    const double dmin = wk.params.closest_distance;
    for (std::size_t i = 0; i < y_.size(); ++i) {
      for (std::uint32_t k = wk.pairs.first(i); k < wk.pairs.last(i); ++k) {
        const std::size_t j = wk.pairs.b[k];
        if (j <= i) continue;
        const double r2 = wk.pairs.dx[k].squaredNorm();
        if (r2 >= dmin * dmin) continue;
        const Vec2 nrm = wk.pairs.dx[k] / std::sqrt(r2);
        const double vr = (y_.v[i] - y_.v[j]).dot(nrm);
        if (vr >= 0) continue;  // separating
        y_.v[i] -= vr * nrm;
        y_.v[j] += vr * nrm;
        ++reflections_;
      }
    }
  }

  SpamOptions options_;
  SpamModel<P> model_;
  SpamState y_;
  Rk4<SpamState> rk_;
  double t_ = 0;
  long steps_ = 0, reflections_ = 0;
};

template <SpamDensity D, SpamAdvection A, bool C, SpamTorque T, bool V, bool CA>
std::unique_ptr<SpamSolver> build(const SpamOptions& o, const SpamParams& p, const SpamState& y0) {
  return std::make_unique<SpamRunner<SpamPolicy<D, A, C, T, V, CA>>>(o, p, y0);
}

// The run-time -> compile-time mapping, one option at a time (std::integral_constant carries the choices).

template <SpamDensity D, SpamAdvection A, bool C, SpamTorque T, bool V>
std::unique_ptr<SpamSolver> with_approach(const SpamOptions& o, const SpamParams& p, const SpamState& y0) {
  return o.closest_approach ? build<D, A, C, T, V, true>(o, p, y0) : build<D, A, C, T, V, false>(o, p, y0);
}
template <SpamDensity D, SpamAdvection A, bool C, SpamTorque T>
std::unique_ptr<SpamSolver> with_viscosity(const SpamOptions& o, const SpamParams& p, const SpamState& y0) {
  return o.viscosity ? with_approach<D, A, C, T, true>(o, p, y0) : with_approach<D, A, C, T, false>(o, p, y0);
}
template <SpamDensity D, SpamAdvection A, bool C>
std::unique_ptr<SpamSolver> with_torque(const SpamOptions& o, const SpamParams& p, const SpamState& y0) {
  switch (o.torque) {
    case SpamTorque::None: return with_viscosity<D, A, C, SpamTorque::None>(o, p, y0);
    case SpamTorque::PairScaling: return with_viscosity<D, A, C, SpamTorque::PairScaling>(o, p, y0);
    case SpamTorque::ParticleScaling: return with_viscosity<D, A, C, SpamTorque::ParticleScaling>(o, p, y0);
    case SpamTorque::Gauss: return with_viscosity<D, A, C, SpamTorque::Gauss>(o, p, y0);
  }
  throw std::invalid_argument("make_spam: bad torque option");
}
template <SpamDensity D, SpamAdvection A, bool Chain>
std::unique_ptr<SpamSolver> with_chain_rule(const SpamOptions& o, const SpamParams& p, const SpamState& y0) {
  if constexpr (Chain && !(D == SpamDensity::Continuity && A != SpamAdvection::Velocity)) {
    throw std::invalid_argument("make_spam: the chain-rule continuity equation needs continuity densities "
                                "and an averaged velocity (shepard, monaghan_arith, monaghan_geom)");
  } else {
    return with_torque<D, A, Chain>(o, p, y0);
  }
}
template <SpamDensity D, bool Chain>
std::unique_ptr<SpamSolver> with_advection(const SpamOptions& o, const SpamParams& p, const SpamState& y0) {
  switch (o.advection) {
    case SpamAdvection::Velocity: return with_chain_rule<D, SpamAdvection::Velocity, Chain>(o, p, y0);
    case SpamAdvection::Shepard: return with_chain_rule<D, SpamAdvection::Shepard, Chain>(o, p, y0);
    case SpamAdvection::MonaghanArithmetic: return with_chain_rule<D, SpamAdvection::MonaghanArithmetic, Chain>(o, p, y0);
    case SpamAdvection::MonaghanGeometric: return with_chain_rule<D, SpamAdvection::MonaghanGeometric, Chain>(o, p, y0);
  }
  throw std::invalid_argument("make_spam: bad advection option");
}

}  // namespace spam_detail

/// Built in spam_instances_sum.cpp, spam_instances_cont.cpp, spam_instances_chain.cpp.
std::unique_ptr<SpamSolver> make_spam_summation(const SpamOptions& o, const SpamParams& p, const SpamState& y0);
std::unique_ptr<SpamSolver> make_spam_continuity(const SpamOptions& o, const SpamParams& p, const SpamState& y0);
std::unique_ptr<SpamSolver> make_spam_chain_rule(const SpamOptions& o, const SpamParams& p, const SpamState& y0);

}  // namespace sph
