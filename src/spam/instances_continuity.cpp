// Instantiations of the SPAM runner for continuity densities.
#include "spam/runner.hpp"

namespace sph {

std::unique_ptr<SpamSolver> make_spam_continuity(const SpamOptions& o, const SpamParams& p, const SpamState& y0) {
  return spam_detail::with_advection<SpamDensity::Continuity, false>(o, p, y0);
}

}  // namespace sph
