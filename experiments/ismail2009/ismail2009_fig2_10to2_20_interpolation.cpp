// Ismail 2009 (thesis), Figs 2.10-2.20: SPH interpolation of known 1D functions and of their first and
// second derivatives, eqs (2.24)-(2.25), for cover sizes of 1.5 to 5.5 particle spacings.
//   Fig 2.10        (x - 0.5)^4 on (0, 1), no extra particles (the boundary "droop")
//   Figs 2.11/2.12  (x - 0.5)^4 with ghost particles, fine / coarse
//   Figs 2.13/2.14  sin x on (0, 3 pi), fine / coarse
//   Figs 2.15/2.16  sin x on (0, pi) with the same particle counts as 2.13/2.14: very fine / intermediate
//   Figs 2.17-2.20  a falling edge (1 -> 0, linear) of very low, low, high gradient, and a step
// The second derivative is the SPH gradient of the SPH first gradient (Section 2.7, below Fig 2.10).
//
// Parameters and their source:
// - Cover function: Ismail's modified mollifier, eq (2.19). The thesis introduces it as "sufficiently close
//   to the Gaussian ... and was thus used" (Section 2.2.2) and its conclusion says it "was used in all the
//   SPH implementations" (Chapter 6); no other cover is named for Section 2.7. Option --kernel.
// - Cover size = support radius (q = r/h < 1 for the mollifiers, eq 2.8: W = 0 for |x - x'| > h). The text
//   confirms it: "with a cover size of 1.5 times the particle spacing only two points are used to evaluate
//   the gradient" (Section 2.7.1): only the neighbours at +-1 ps lie inside |r| < 1.5 ps.
// - Cover sizes: the text names 1.5 and 5.5 spacings and "a large cover size" that "removes the detail";
//   the legends are lost. CHOSEN: 1.5, 2.5, 3.5, 4.5, 5.5 and 7.5 (the last standing for "large").
// - Normalisation: G = 1 / integral of the shape (eq 2.19), the default. The alternative reading
//   (--normalisation discrete: G chosen so that sum_q W dV = 1 at an interior particle of the lattice) is
//   also evaluated for the claims, because at 1.5 spacings the integral normalisation leaves sum W dV = 1.19.
// - Particle placement: x_i = a + i ps including both end points, dV = ps; ghosts continue the lattice with
//   the analytic function "extended beyond the end points" (Section 2.7), 2 cover radii deep so that the
//   first gradient at every ghost used by the second gradient has a full cover.
// - Particle spacings ("ps" in the legends; values lost). CHOSEN, all options:
//     (x - 0.5)^4: fine ps = 0.01 (101 particles), coarse ps = 0.1 (11 particles: "very few particles",
//       Fig 2.12); Fig 2.10 uses the fine spacing so that 2.10 and 2.11 differ only by the ghosts.
//     sin x: 90 spacings (fine, ps = 3 pi / 90 = 0.105) and 15 spacings (coarse, ps = 0.628, 10 per
//       period). Figs 2.15/2.16 keep these counts on (0, pi) as the text says: very fine ps = 0.035 and
//       intermediate ps = 0.209, which lies between fine and coarse (close to their geometric mean 0.257).
//     falling edges: ps = 0.01 on (0, 1), edge widths 40, 12, 3 and 0 spacings (very low: 7 of the largest
//       covers; low: about two 5.5 covers; high: between the two smallest covers; a step), with both corners
//       midway between particles so the exact derivatives at particles are unambiguous (f' = -1/width on
//       the edge, 0 elsewhere; f'' = 0 at every particle; a step has f' = 0 at every particle).
// - Error measures: max and RMS of <g> - g over the real particles (the "interior" of the ghost panels is
//   the whole domain), g = f, f', f''. --quick runs the same (the full run takes well under a second).
// - Claim measures (values file; reference/I-interp.csv): droop = 1 - sum W dV and |<f> - f|/f at the end
//   particle of Fig 2.10; refinement = RMS(coarser)/RMS(finer); rank = RMS of the 1.5 cover over the
//   worst/best other cover; a sweep of edge widths 0..12 spacings for "1.5 best on steep edges"; the
//   compromise = smallest geometric mean over Figs 2.11-2.20 and f, f', f'' of RMS / best RMS. CHOSEN:
//   a cover is "well sampled" when its lattice gradient of a linear function is within 1% of exact.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "frame/driver.hpp"
#include "ismail2009/scenes/interpolation_study.hpp"

using namespace scenes::interpolation;

int main(int argc, char** argv) {
  sph::Driver d("ismail2009_fig2_10to2_20_interpolation", "I-interp",
                "Ismail 2009 Figs 2.10-2.20: SPH interpolation of (x-0.5)^4, sin x and falling edges");
  std::string kernel_name = "modified_mollifier";  // eq (2.19), see the header comment
  std::string normalisation = "integral";          // eq (2.19): G = 1 / integral
  std::vector<double> covers = {1.5, 2.5, 3.5, 4.5, 5.5, 7.5};  // CHOSEN (particle spacings)
  double quartic_ps_fine = 0.01, quartic_ps_coarse = 0.1;      // CHOSEN
  int sin_spacings_fine = 90, sin_spacings_coarse = 15;        // CHOSEN
  double edge_ps = 0.01;                                       // CHOSEN
  std::vector<double> edge_widths = {40, 12, 3, 0};            // CHOSEN, in particle spacings
  int sweep_max_width = 12;                                     // CHOSEN: up to the "low gradient" edge
  double fairly_good_factor = 2.0;  // CHOSEN: "fairly good" = error within this factor of the best cover
  d.param("kernel", kernel_name, "cover function (modified_mollifier, mollifier, lucy, cubic_spline, gaussian)")
      .one_of({"modified_mollifier", "mollifier", "lucy", "cubic_spline", "gaussian"});
  d.param("normalisation", normalisation, "integral (eq 2.19) or discrete (sum W dV = 1 in the interior)")
      .one_of({"integral", "discrete"});
  d.param("covers", covers, "cover sizes (support radius) in particle spacings").positive();
  d.param("quartic-ps-fine", quartic_ps_fine, "particle spacing, (x-0.5)^4, Figs 2.10, 2.11").positive();
  d.param("quartic-ps-coarse", quartic_ps_coarse, "particle spacing, (x-0.5)^4, Fig 2.12").positive();
  d.param("sin-spacings-fine", sin_spacings_fine, "spacings in the domain, Figs 2.13 (0,3pi) and 2.15 (0,pi)").positive();
  d.param("sin-spacings-coarse", sin_spacings_coarse, "spacings in the domain, Figs 2.14 (0,3pi) and 2.16 (0,pi)").positive();
  d.param("edge-ps", edge_ps, "particle spacing of the falling edges on (0, 1), Figs 2.17-2.20").positive();
  d.param("edge-widths", edge_widths, "edge widths in spacings for Figs 2.17, 2.18, 2.19, 2.20").non_negative();
  d.param("sweep-max-width", sweep_max_width, "edge widths 0..this (spacings) in edge_width_sweep.csv").positive();
  d.param("fairly-good-factor", fairly_good_factor, "error ratio to the panel's best cover counted as fairly good");

  return d.run(argc, argv, [&] {
    // --quick: the full run already takes a fraction of a second; nothing to reduce.
    if (normalisation != "integral" && normalisation != "discrete")
      throw std::invalid_argument("--normalisation must be integral or discrete, not '" + normalisation + "'");
    if (covers.empty() || edge_widths.size() != 4) throw std::invalid_argument("need covers and four edge widths");
    if (std::find(covers.begin(), covers.end(), 1.5) == covers.end() ||
        std::find(covers.begin(), covers.end(), 5.5) == covers.end())
      throw std::invalid_argument("--covers must include 1.5 and 5.5 (the sizes the text's claims name)");
    for (double w : edge_widths)
      if (w < 0 || std::abs(w - std::round(w)) > 1e-12) throw std::invalid_argument("edge widths: whole spacings >= 0");
    if (edge_widths[0] < 1) throw std::invalid_argument("the Fig 2.17 edge needs a width of at least one spacing");
    // The edge is centred between the particles at 0.5 and 0.5 + ps: 0.5 must be a particle.
    if (std::abs(0.5 / edge_ps - std::round(0.5 / edge_ps)) > 1e-9)
      throw std::invalid_argument("--edge-ps must divide 0.5 into whole spacings");
    const double pi = M_PI;

    std::vector<Panel> panels = {
        {"fig2_10", "(x-0.5)^4, no extra particles", quartic(), 0, 1, quartic_ps_fine, false},
        {"fig2_11", "(x-0.5)^4, fine", quartic(), 0, 1, quartic_ps_fine, true},
        {"fig2_12", "(x-0.5)^4, coarse", quartic(), 0, 1, quartic_ps_coarse, true},
        {"fig2_13", "sin x on (0,3pi), fine", sine(), 0, 3 * pi, 3 * pi / sin_spacings_fine, true},
        {"fig2_14", "sin x on (0,3pi), coarse", sine(), 0, 3 * pi, 3 * pi / sin_spacings_coarse, true},
        {"fig2_15", "sin x on (0,pi), very fine", sine(), 0, pi, pi / sin_spacings_fine, true},
        {"fig2_16", "sin x on (0,pi), intermediate", sine(), 0, pi, pi / sin_spacings_coarse, true}};
    const char* edge_names[4] = {"very low gradient", "low gradient", "high gradient", "discontinuous"};
    for (int k = 0; k < 4; ++k)
      panels.push_back(edge_panel("fig2_" + std::to_string(17 + k), std::string("falling edge, ") + edge_names[k],
                                  edge_ps, edge_widths[k]));
    write_panels(d, panels);

    // Every panel and cover under both normalisation readings, then the files and the claims' measures.
    const Study study = run_study(kernel_name, panels, covers, edge_ps, sweep_max_width);
    write_curves(d, panels, covers, study, normalisation);
    write_claims(d, kernel_name, panels, covers, study, fairly_good_factor);
  });
}
