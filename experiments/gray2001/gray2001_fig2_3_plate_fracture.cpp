// Gray, Monaghan & Swift 2001, Figs 2 and 3 (Section 7.1): the plate with mu = 0.60, V_f = 0.05 and
// H = 2, L = 20, run with the standard algorithm (eps = 0: "the beam breaks where the plate is attached to
// the support ... early in the oscillation") and with the artificial stress (eps = 0.3: "completely
// stable", "continued for as long as desired": checked over --periods theoretical periods).
//
// Parameters: as gray2001_table1_2_plate_periods (clamp, viscosity, time step, dp = 0.1: the tables' resolution,
// n = 20 across H; --dp 0.2 runs 8x faster).
// Fracture is detected automatically: the free particles split into more than one piece at a link
// distance of 1.5 dp (CHOSEN: the nearest-neighbour distance of an intact lattice stretched by 50%),
// checked every 5 time units; the crack position is the largest x reached by the piece that holds the
// clamped end.
#include <cmath>

#include "frame/driver.hpp"
#include "core/fragments.hpp"
#include "core/materials.hpp"
#include "gray2001/scenes/plate_run.hpp"
#include "io/snapshot.hpp"

int main(int argc, char** argv) {
  sph::Driver d("gray2001_fig2_3_plate_fracture", "G-fig2", "Gray et al. 2001 Figs 2-3: plate fracture without, stability with artificial stress");
  double dp = 0.1, clamp = 2.0, Vf = 0.05, periods = 10.0, snapshot_every = 100.0;
  sph::GrayParameters scheme;  // the scheme's defaults (parameters.hpp) but mu:
  scheme.mu = 0.6;             // Figs 2-3
  long max_steps = -1;
  d.param("dp", dp, "particle spacing").positive().quick(0.25);
  d.param("clamp-length", clamp, "plate length held between the fixed layers").non_negative();
  d.param("cfl", scheme.cfl, "time-step factor").positive();
  d.param("mu", scheme.mu, "shear modulus (Gray 2001 Figs 2-3: 0.60)").non_negative();
  d.param("Vf", Vf, "tip speed / c0 (Figs 2-3: 0.05)");
  d.param("periods", periods, "length of the eps = 0.3 run in theoretical periods").positive().quick(1.0);
  d.param("snapshot-every", snapshot_every, "time between snapshots (HDF5; CSV frames during the first period)").positive();
  d.param("max-steps", max_steps, "stop each run after this many steps (smoke test); -1 = no limit");

  return d.run(argc, argv, [&] {
    const double mu = scheme.mu;
    const double T = scenes::plate_theory_period(mu, 2.0, 20.0);
    auto summary = d.csv("summary.csv", {"eps", "t_end", "steps", "wall_s", "fracture_time", "fracture_time_over_T", "crack_x", "fragments_at_end"});
    for (const double eps : {0.0, 0.3}) {
      scenes::PlateRunSpec s;
      s.plate.H = 2.0;
      s.plate.dp = dp;
      s.plate.clamp_length = clamp;
      s.plate.Vf = Vf;
      s.scheme = scheme;
      s.options.artificial_stress = eps > 0;
      s.scheme.eps_artificial = eps;
      s.t_end = eps > 0 ? periods * T : 1.0 * T;  // the standard run breaks well within one period
      s.max_steps = max_steps;
      s.sample_dt = 1.0;
      s.fracture_check_dt = 5.0;
      s.run_after_fracture = eps > 0 ? -1.0 : 100.0;  // show the break, then stop
      const std::string tag = eps > 0 ? "eps0.3" : "eps0";
      sph::SnapshotSeries snaps(d.out_dir() / ("snapshots_" + tag + ".h5"), d.info());
      auto frames = d.csv("frames_" + tag + ".csv", scenes::frame_columns());
      const double frames_until = 1.0 * T;  // the figures show the first oscillation
      double next_snap = 0;
      double crack_x = NAN, next_crack_check = 0;
      auto on_sample = [&](const sph::GraySolver& solver, const sph::ElasticBody& body) {
        if (solver.time() + 1e-9 >= next_snap) {
          next_snap += snapshot_every;
          snaps.write(sph::snapshot_of(solver));
          if (solver.time() <= frames_until + 1e-9) scenes::write_frame(frames, solver, body);
        }
        // Crack position, at the fracture checks' interval until found: the piece holding the clamped end
        // ends where the body broke.
        if (!std::isnan(crack_x) || solver.time() + 1e-9 < next_crack_check) return;
        next_crack_check += s.fracture_check_dt;
        std::vector<bool> free_p(body.size());
        std::size_t root = 0;
        for (std::size_t a = 0; a < body.size(); ++a) {
          free_p[a] = body.motion[a] == sph::Motion::Free;
          if (free_p[a] && body.x[a].x() < body.x[root].x()) root = a;
        }
        const auto f = sph::find_fragments(body.x, body.box, 1.5 * dp, free_p);
        if (f.count > 1 && std::isnan(crack_x)) {
          double xmax = -1e300;
          for (std::size_t a = 0; a < body.size(); ++a)
            if (f.label[a] == f.label[root]) xmax = std::max(xmax, body.x[a].x());
          crack_x = xmax;
        }
      };
      const auto r = scenes::run_plate(s, on_sample, "plate fracture " + tag);
      auto trace = d.csv("tip_" + tag + ".csv", {"t", "y_tip", "kinetic", "elastic", "fragments"});
      for (const auto& smp : r.trace) trace.row(smp.t, smp.y, smp.ke, smp.ee, smp.fragments);
      summary.row(eps, s.t_end, r.steps, r.wall_s, r.fracture_time, r.fracture_time / T, crack_x, r.trace.back().fragments);
      if (!r.blow_up.empty() && eps > 0) throw std::runtime_error("eps = 0.3 run blew up: " + r.blow_up);
      if (max_steps >= 0) continue;
      if (eps == 0) {
        d.value("eps0_fracture_time_over_period", r.fracture_time > 0 ? r.fracture_time / T : 1e9,
                "first split of the plate / theoretical period (1e9: never)");
        d.value("eps0_crack_x", crack_x, "x where the piece holding the clamp ends (clamp edge at x = 0)");
      } else {
        d.value("eps0.3_fragments_at_end", static_cast<double>(r.trace.back().fragments), "pieces after the run");
        d.value("eps0.3_periods_run", r.trace.back().t / T, "theoretical periods simulated");
      }
    }
  });
}
