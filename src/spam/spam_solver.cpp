#include "spam/spam_solver.hpp"

#include <stdexcept>
#include <type_traits>

#include "spam/runner.hpp"

namespace sph {

std::unique_ptr<SpamSolver> make_spam(const SpamOptions& o, const SpamParams& p, const SpamState& y0) {
  if (y0.size() == 0) throw std::invalid_argument("make_spam: no particles");
  if (!(p.h > 0) || !(p.mass > 0)) throw std::invalid_argument("make_spam: need h > 0 and m > 0");
  if (o.density == SpamDensity::Continuity)
    for (double r : y0.rho)
      if (!(r > 0)) throw std::invalid_argument("make_spam: continuity densities need rho(t=0) > 0");
  if (o.density == SpamDensity::Summation) {
    if (o.chain_rule) throw std::invalid_argument("make_spam: the chain-rule continuity equation needs continuity densities");
    return make_spam_summation(o, p, y0);
  }
  return o.chain_rule ? make_spam_chain_rule(o, p, y0) : make_spam_continuity(o, p, y0);
}

Tensor2 SpamSolver::stress(std::size_t i) const {
  const SpamState& y = state();
  Tensor2 s;
  s << y.sxx[i], y.sxy[i], y.sxy[i], y.syy[i];
  return s;
}

std::vector<double> summed_density(const std::vector<Vec2>& x, const SpamParams& params) {
  SpamWork wk(params, x.size());
  wk.gather(x);
  SpamState y(x.size());
  spam_density<SpamPolicy<SpamDensity::Summation, SpamAdvection::Velocity, false, SpamTorque::None, false, false>>(y, wk);
  return std::vector<double>(wk.rho.begin(), wk.rho.end());
}

}  // namespace sph
