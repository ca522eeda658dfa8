// Instantiations of the SPAM runner for summation densities.
#include "spam/runner.hpp"

namespace sph {

std::unique_ptr<SpamSolver> make_spam_summation(const SpamOptions& o, const SpamParams& p, const SpamState& y0) {
  return spam_detail::with_advection<SpamDensity::Summation, false>(o, p, y0);
}

}  // namespace sph
