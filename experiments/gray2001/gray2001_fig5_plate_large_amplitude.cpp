// Gray, Monaghan & Swift 2001, Fig. 5 (Section 7.1): "a highly nonlinear oscillation of a plate with
// H = 2 cm and L = 20 cm, with mu = 0.22, eps = 0.30, V_f = 0.05 ... continued for several oscillations"
// with "no sign of fracture". Checks: the plate stays in one piece for --periods periods; the tip
// trace and HDF5 snapshots (stress sigma_xx) for the configuration plot.
// Parameters: as gray2001_table1_2_plate_periods (clamp, viscosity, time step, dp = 0.1: the tables' resolution,
// n = 20 across H; --dp 0.2 runs 8x faster).
#include <cmath>

#include "frame/driver.hpp"
#include "core/materials.hpp"
#include "gray2001/scenes/plate_run.hpp"
#include "io/snapshot.hpp"

int main(int argc, char** argv) {
  sph::Driver d("gray2001_fig5_plate_large_amplitude", "G-fig5", "Gray et al. 2001 Fig 5: large-amplitude plate oscillation");
  double dp = 0.1, clamp = 2.0, Vf = 0.05, periods = 3.0, snapshot_every = 200.0;
  sph::GrayParameters scheme;  // the scheme's defaults (parameters.hpp): Fig 5's mu = 0.22 and eps = 0.30
  long max_steps = -1;
  d.param("dp", dp, "particle spacing").positive().quick(0.25);
  d.param("clamp-length", clamp, "plate length held between the fixed layers").non_negative();
  d.param("cfl", scheme.cfl, "time-step factor").positive();
  d.param("mu", scheme.mu, "shear modulus (Fig 5: 0.22)").non_negative();
  d.param("Vf", Vf, "tip speed / c0 (Fig 5: 0.05)");
  d.param("eps", scheme.eps_artificial, "artificial stress epsilon (Fig 5: 0.30)").non_negative();
  d.param("periods", periods, "run length in theoretical periods (CHOSEN: 3, 'several oscillations')").positive().quick(1.0);
  d.param("snapshot-every", snapshot_every, "time between HDF5 snapshots").positive();
  d.param("max-steps", max_steps, "stop after this many steps (smoke test); -1 = no limit");

  return d.run(argc, argv, [&] {
    const double mu = scheme.mu;
    const double T = scenes::plate_theory_period(mu, 2.0, 20.0);
    scenes::PlateRunSpec s;
    s.plate.H = 2.0;
    s.plate.dp = dp;
    s.plate.clamp_length = clamp;
    s.plate.Vf = Vf;
    s.scheme = scheme;
    s.options.artificial_stress = scheme.eps_artificial > 0;
    s.t_end = periods * T;
    s.max_steps = max_steps;
    s.sample_dt = 1.0;
    s.fracture_check_dt = 10.0;
    sph::SnapshotSeries snaps(d.out_dir() / "snapshots.h5", d.info());
    auto frames = d.csv("frames.csv", scenes::frame_columns());
    double next_snap = 0;
    auto on_sample = [&](const sph::GraySolver& solver, const sph::ElasticBody& body) {
      if (solver.time() + 1e-9 < next_snap) return;
      next_snap += snapshot_every;
      snaps.write(sph::snapshot_of(solver));
      scenes::write_frame(frames, solver, body);
    };
    const auto r = scenes::run_plate(s, on_sample, "plate large amplitude");
    if (!r.blow_up.empty()) throw std::runtime_error(r.blow_up);
    auto trace = d.csv("tip.csv", {"t", "y_tip", "kinetic", "elastic", "fragments"});
    std::size_t max_pieces = 0;
    for (const auto& smp : r.trace) {
      trace.row(smp.t, smp.y, smp.ke, smp.ee, smp.fragments);
      max_pieces = std::max(max_pieces, smp.fragments);
    }
    if (max_steps >= 0) return;
    const auto ext = scenes::half_cycle_extremes(r.trace);
    d.value("max_fragments", static_cast<double>(max_pieces), "largest number of pieces seen (1 = never broke)");
    d.value("half_cycles_completed", static_cast<double>(ext.size()), "completed half oscillations");
    d.value("max_tip_displacement_over_L", ext.empty() ? NAN : std::abs(ext.front()) / 20.0, "first extreme / L: how nonlinear");
  });
}
