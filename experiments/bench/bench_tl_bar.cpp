// Scene benchmark: the Ismail 2009 1D validation bar (Section 4.6.3, Algorithm 4.1) at increasing resolution.
// Writes <out>/bench_tl_bar.csv with the common bench columns; the SPH-matrix build (and boundary factors) is
// reported in its own rows (variant = matrix_build, steps = 0) separately from the time loop (variant =
// time_loop). Error = RMS of T11 - (-p(t - x/c)) at x = 0.05, 0.1 m before the reflection, over p0.
// CHOSEN: intermediate pulse (5 us, smoothing 0.5 us), h = 5.5 ps, dt = 0.5 h/c_L, p-wave modulus.
#include <omp.h>

#include <cmath>
#include <vector>

#include "frame/driver.hpp"
#include "ismail2009/scenes/bar.hpp"

int main(int argc, char** argv) {
  sph::Driver d("bench_tl_bar", "bench", "1D total Lagrangian SPH bar: time loop and matrix build");
  std::vector<double> spacings{0.15e-3, 0.075e-3, 0.0375e-3, 0.01875e-3};
  d.param("ps", spacings, "particle spacings, m").positive().quick({0.6e-3, 0.3e-3});
  return d.run(argc, argv, [&] {
    const double L = 0.15, rho = 8000, p0 = 1e5;
    const double C = sph::p_wave_modulus(sph::lame_from_young_poisson(200e9, 0.3)), c = std::sqrt(C / rho);
    const scenes::SmoothedPulse pulse(p0, 5e-6, 0.5e-6);
    auto out = d.csv("bench_tl_bar.csv", {"scene", "variant", "particles", "steps", "threads", "wall_s",
                                          "particle_steps_per_s", "error_name", "error"});
    for (double ps : spacings) {
      sph::TlConfig1D cfg;
      cfg.length = L;
      cfg.ps = ps;
      cfg.modulus = C;
      cfg.density = [rho](double) { return rho; };
      cfg.left.value = [pulse](double t) { return -pulse(t); };
      cfg.right.kind = sph::EndCondition1D::Kind::Displacement;
      sph::TlSolver1D bar(cfg);
      const double t_end = (2 * L - 0.1) / c;
      const auto r = scenes::run_bar(bar, 0.5 * bar.h() / c, t_end, {0.05, 0.1});
      double s2 = 0;
      for (int g : {0, 1}) {
        const double x = r.gauge_x[g];
        const double e = scenes::window_rms_error(r.t, r.T[g], [&](double t) { return -pulse(t - x / c); }, 0.0, t_end - 0.5e-6);
        s2 += e * e / 2;
      }
      const int threads = omp_get_max_threads();
      out.row("tl_bar_1d", "matrix_build", bar.n_real(), 0, threads, r.build_s, 0.0, "rms_T11_over_p0", std::sqrt(s2) / p0);
      out.row("tl_bar_1d", "time_loop", bar.n_real(), r.steps, threads, r.wall_s,
              bar.n_real() * static_cast<double>(r.steps) / r.wall_s, "rms_T11_over_p0", std::sqrt(s2) / p0);
    }
  });
}
