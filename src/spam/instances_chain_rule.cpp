// Instantiations of the SPAM runner for continuity densities with the chain-rule continuity equation.
#include "spam/runner.hpp"

namespace sph {

std::unique_ptr<SpamSolver> make_spam_chain_rule(const SpamOptions& o, const SpamParams& p, const SpamState& y0) {
  return spam_detail::with_advection<SpamDensity::Continuity, true>(o, p, y0);
}

}  // namespace sph
