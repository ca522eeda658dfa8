#include "gray2001/scenes/scheme_key.hpp"

#include <sstream>

#include "frame/run_store.hpp"

namespace scenes {

// A field added to one of these structs must be added to the key below: the sizes make the compiler say so.
static_assert(sizeof(sph::GrayParameters) == 96, "GrayParameters changed: update gray_scheme_key");
static_assert(sizeof(sph::GrayOptions) == 5, "GrayOptions changed: update gray_scheme_key");

std::string gray_scheme_key(const sph::GrayParameters& g, const sph::GrayOptions& o) {
  using sph::exact_text;
  std::ostringstream k;
  k << "scheme rho0 " << exact_text(g.rho0) << " c0 " << exact_text(g.c0) << " mu " << exact_text(g.mu) << " h/dp "
    << exact_text(g.h_over_dp) << " eps " << exact_text(g.eps_artificial) << " n " << g.n_artificial << " xsph "
    << exact_text(g.eps_xsph) << " alpha " << exact_text(g.alpha) << " beta " << exact_text(g.beta) << " yield "
    << exact_text(g.yield_stress) << " cfl " << exact_text(g.cfl) << " skin " << exact_text(g.skin_over_h)
    << " options " << o.artificial_stress << o.xsph << o.viscosity << o.summation_density << o.plasticity;
  return k.str();
}

}  // namespace scenes
