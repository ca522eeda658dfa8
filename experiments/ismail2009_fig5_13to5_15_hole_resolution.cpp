// Ismail 2009 (thesis), Section 5.4.4: the resolution study the thesis asks for ('a convergence analysis with
// increasing numbers of particles should be completed') on the sheet of ismail2009_fig5_13to5_15_hole.cpp
// (same CHOSEN parameters, scenes/ismail_hole.hpp): n x n = 21, 41, 81, 161, 201 particles on the quarter
// sheet. Writes resolution.csv (also the work-precision data: wall time against the distance of the hole
// stress from its finest value). Default n = 21, 41, 81, 161 (161 x 161: 24.6k particles, 18.8k steps, ~4 min
// of CPU, 13 min wall on the loaded 2-core machine). NOT 201: with the ghost-reflection boundary scheme the
// free edges carry a slowly growing mode (total_lagrangian_2d.hpp) that the damping holds down up to 161 per
// side (disorder measure 0.08 at 81, 0.13 at 161) but not at 201 (the run becomes non-finite; try --n 201).
// The variational scheme (--variational true) runs 201 x 201 (38 395 particles, 23.5k steps, ~7 min on one
// core) but is biased low and converges slowly: smoothed hole stress 8.5, 9.1, 10.1, 10.9, 11.1 MPa at
// n = 21 ... 201 against Heywood's 16.15.
// --quick runs 11 and 21.
#include <cmath>
#include <vector>

#include "driver.hpp"
#include "scenes/ismail_hole.hpp"

int main(int argc, char** argv) {
  sph::Driver d("ismail2009_fig5_13to5_15_hole_resolution", "I-hole", "sheet with a hole: resolution study to 201 x 201");
  std::vector<int> ns{21, 41, 81, 161};
  scenes::HoleParams p;
  p.variational = false;
  d.param("n", ns, "particles along a side, one run each");
  d.param("variational", p.variational, "boundary scheme: variational (true) or ghost reflection (false)");
  return d.run(argc, argv, [&] {
    if (d.quick() && !d.given("n")) ns = {11, 21};
    auto out = d.csv("resolution.csv", {"n", "particles", "steps", "wall_s", "build_s", "sigma1_hole_top_MPa", "peak_sigma1_MPa",
                                        "peak_sigma1_dynamic_MPa", "smoothed_sigma1_hole_top_MPa", "zigzag"});
    std::vector<double> top;
    for (int n : ns) {
      p.n = n;
      const auto r = scenes::run_hole(p);
      if (!r.finite) throw std::runtime_error("the sheet run became non-finite at n = " + std::to_string(n));
      out.row(n, r.particles, r.steps, r.wall_s, r.build_s, r.sigma1_hole_top / 1e6, r.peak_sigma1 / 1e6, r.peak_sigma1_dynamic / 1e6,
              r.smoothed_sigma1_hole_top / 1e6, r.zigzag);
      top.push_back(r.smoothed_sigma1_hole_top / 1e6);
      if (n == ns.back()) {
        d.value("raw_sigma1_hole_top_MPa_finest", r.sigma1_hole_top / 1e6, "particle stress at (0, R), finest run");
        d.value("zigzag_finest", r.zigzag, "particle-scale disorder, finest run");
      }
    }
    d.value("sigma1_hole_top_MPa_finest", top.back(), "finest run, SPH-smoothed stress at (0, R)");
    d.value("sigma1_hole_top_change_last_refinement", std::abs(top.back() - top[top.size() - 2]) / top.back(),
            "relative change over the last refinement");
    d.value("heywood_MPa_resolution", scenes::heywood_gross_concentration(p.R / p.a) * p.traction / 1e6, "reference");
  });
}
