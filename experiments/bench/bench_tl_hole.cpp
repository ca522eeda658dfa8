// Scene benchmark: the Ismail 2009 Section 5.4.4 sheet with a hole (ismail2009/scenes/hole.hpp, same CHOSEN
// parameters as ismail2009_fig5_13to5_15_hole.cpp) at increasing resolution, up to the study's 201 x 201. Writes <out>/bench_tl_hole.csv
// with the common bench columns; the SPH matrices, ghost interpolation rows and the sparse LU factorisations of
// the boundary systems are reported in their own rows (variant = matrix_build, steps = 0), the time loop in
// variant = time_loop. Error = |smoothed max principal stress at (0, R) - Kirsch/Heywood| / Kirsch/Heywood.
#include <omp.h>

#include <cmath>
#include <vector>

#include "frame/driver.hpp"
#include "ismail2009/scenes/hole.hpp"

int main(int argc, char** argv) {
  sph::Driver d("bench_tl_hole", "bench", "2D total Lagrangian SPH sheet with a hole: time loop and matrix build");
  std::vector<int> ns{21, 81, 201};  // 201 x 201: the resolution the I-hole study ends at
  d.param("n", ns, "particles along a side").positive().quick({21});
  return d.run(argc, argv, [&] {
    auto out = d.csv("bench_tl_hole.csv", {"scene", "variant", "particles", "steps", "threads", "wall_s",
                                           "particle_steps_per_s", "error_name", "error"});
    for (int n : ns) {
      scenes::HoleParams p;
      p.n = n;
      p.variational = false;
      const auto r = scenes::run_hole(p);
      const double ref = scenes::heywood_gross_concentration(p.R / p.a) * p.traction;
      const double err = r.finite ? std::abs(r.smoothed_sigma1_hole_top - ref) / ref : NAN;
      const int threads = omp_get_max_threads();
      out.row("tl_hole_2d", "matrix_build", r.particles, 0, threads, r.build_s, 0.0, "rel_err_sigma1_hole_vs_heywood", err);
      out.row("tl_hole_2d", "time_loop", r.particles, r.steps, threads, r.wall_s,
              r.particles * static_cast<double>(r.steps) / r.wall_s, "rel_err_sigma1_hole_vs_heywood", err);
    }
  });
}
