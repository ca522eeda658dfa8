// Ismail 2009 (thesis), Section 5.4.4: the resolution study the thesis asks for ('a convergence analysis with
// increasing numbers of particles should be completed') on the sheet of ismail2009_fig5_13to5_15_hole.cpp
// (same CHOSEN geometry and load, ismail2009/scenes/hole.hpp), to 201 x 201 particles on the quarter sheet.
//
// What limits it, measured (reference/I-hole.csv): the ghost-reflection boundary scheme has a weak instability
// at the loaded and free edges (a particle-scale sawtooth along an edge, which the plain SPH gradient cannot
// see, and modes at the corners of the loaded edge), growing at a rate between omega and 2 omega. With the
// mass-proportional damping at 2 omega (critical for the slowest mode) it outruns the damping at fine
// resolution: runs at 201 longer than 6/omega become non-finite, and the largest particle speed rises at rest
// in the linear (Hooke, 1% load) runs: x27 over the last 2.4 ms at the loaded edge at 161, x18 at the corner
// (a, a) at 81 run to 12/omega. So it is linear, not the large strain. (Speeds of particles on Dirichlet
// components read a dt of their reaction before TlSolver2D::step pinned them at the end of the step as well;
// the speeds quoted here are of free particles.) Kelvin-Voigt viscosity does not touch it
// (the gradient does not see the sawtooth), a zero-energy-mode control (TlConfig2D::hourglass, after
// Ganzenmueller 2015) only moves it (gamma = 0.01, 0.02 at 201: to the top edge), an even point reflection at
// the corners and a traction solve on the mirror point's gradient make it worse (non-finite). CHOSEN (issue 15 b):
// damping 6.5 omega (HoleParams::damping), the least that holds the mode at the finest resolution (twice its
// undamped rate at 201, 2.97 omega: 5.93; 'damping_over_least_finest', checked) with 10% (the c/2 rule holds to
// 4-9% at 41-81 per side, tests/test_hole_edge.cpp; the rate is measured unloaded), checked in the runs themselves
// ('speed_rise_finest': the largest speed falls to the end, 1.37 at the earlier 4 omega), and settle = 10/omega,
// which takes the overdamped slowest mode down as far as 6/omega did at the earlier 4 omega (decay omega (c -
// sqrt(c^2 - 1)), c = damping / 2: 0.158 against 0.268 omega); at rest the damping exerts no force, so it changes
// the time to rest, not the answer (n = 81: the hole stress at 6.5 omega and 10/omega is 2e-5 below the run at 4
// omega and 12/omega). The control at gamma = 0.005. Without the control the sheet does not come to rest at 201:
// while its hole stress settles, a particle on the symmetry line just above the hole keeps drifting
// ('plain_rest_speed_ratio_finest'); with it the largest speed falls 1e4-fold (checked). The control's bias grows
// with gamma and shrinks with h (the gamma sweep at 81; against the plain scheme at 201:
// 'control_bias_at_plain_finest', checked). 'speed_rise' (end over the minimum after the ramp) and 'growth_rate' (d
// ln of the largest speed / dt over the last 3/omega) are written too.
//
// Runs, all written to resolution.csv with their series:
//   controlled  n = 21, 41, 81, 161, 201 at gamma = 0.005 (the study);
//   plain       n = 21, 41, 81, 161, 201 without the control (the thesis's scheme);
//   gamma       n = 81 with gamma = 0 ... 0.05 (the control's bias);
//   linear      n = 161, Hooke at 1% of the load: the linear-elastic concentration of this square sheet, to
//               split the distance from Heywood's (long-strip, linear) value into geometry and nonlinearity.
//   edge        (issue 15 b) the edge instability by its growth rate (HoleResult::growth_rate, in omega),
//               linear (Hooke, 1%), undamped, without the control, to 12/omega: n = 41, 81, 161, 201 at the default
//               step, and at n = 81 a third of the step, the ghosts and gradient iterated 3 times per step,
//               nu = 0.3 and the variational closure (edge_stability.csv; ~2 minutes). Measured (the notes of
//               issue 15): the mode sits at the corner of the loaded and the free edge; its rate rises with n
//               (1.48, 1.85, 2.50, 2.97 omega at 41, 81, 161, 201), RISES as the step falls (2.29 at a third, 4.12 at a
//               quarter) and with the iteration (5.10 with 3 passes, 7.38 with 5): not a lag, which only slows it; the
//               closure's un-lagged fixed point is unstable. It needs nu near 1/2 (0.08 at 0.3) and is absent from
//               the variational closure (-0.02). Mass-proportional damping c takes c/2 off the rate: the least
//               that holds the finest mode is twice its rate (edge_least_damping_finest: 5.0 omega at 161, above
//               the 4 chosen: there the mode still grows at 0.5 omega, e^3 = 20x over the 6/omega settle).
//               The spectrum (--edge-eigen-n, 21; scenes::edge_spectrum): the eigenvalues of the linearised
//               operator of u'' = J u with the closure converged. Complex pairs in the operator itself: at n = 21,
//               45% of the eigenvalues grow, the fastest at 2.14 omega (lambda = (-73.7 +- 37.9 i) omega^2), one
//               spacing from the corner of the loaded and the free top edge; the run with the closure iterated 30
//               times per step measures 2.15 (at n = 41: 4.23 against 4.25, by hand, 4 minutes per spectrum). The
//               un-lagged operator grows at nu = 0.3 too (0.81 at 21, 1.56 at 41), which the lagged closure does not
//               show; the variational closure's fastest is 0.07 (a slow pair near the symmetry edge x = 0).
// fem.csv: the same square quarter sheet by Q4 plane-stress finite elements (scenes/fem_hole.hpp), meshes
// m = 32 ... 256: the linear reference (Heywood's long-strip formula is 11% below this geometry's value).
// history.csv: the smoothed hole stress, the largest particle stress and speed against time for every run.
// About 14 minutes of single-threaded runs (850 s at 2026-12-04, the 201 runs 102-165 s each). --quick: 11 and 21 per side.
#include <map>
#include <string>
#include <vector>

#include "frame/driver.hpp"
#include "frame/run_jobs.hpp"
#include "ismail2009/scenes/hole.hpp"
#include "ismail2009/scenes/hole_files.hpp"
#include "ismail2009/scenes/hole_study.hpp"

int main(int argc, char** argv) {
  sph::Driver d("ismail2009_fig5_13to5_15_hole_resolution", "I-hole", "sheet with a hole: resolution study to 201 x 201");
  std::vector<int> ns{21, 41, 81, 161, 201}, plain_ns{21, 41, 81, 161, 201};
  std::vector<double> gammas{0, 0.002, 0.005, 0.01, 0.02, 0.05};
  int gamma_n = 81, linear_n = 161;
  std::vector<int> fem_m{32, 64, 128, 256};
  std::vector<int> edge_ns{41, 81, 161, 201};
  int edge_n = 81;
  int eigen_n = 21;
  scenes::HoleParams p;
  p.variational = false;
  p.settle = 10;  // the slowest mode's decay of 6/omega at 4 omega, at the damping of 6.5 (see the header)
  p.hourglass = 0.005;
  d.param("n", ns, "particles along a side of the controlled runs, one run each").positive().quick({11, 21});
  d.param("plain-n", plain_ns, "particles along a side of the runs without the control").positive().quick({11, 21});
  d.param("gammas", gammas, "control strengths of the gamma sweep").non_negative().quick({0, 0.005, 0.02});
  d.param("gamma-n", gamma_n, "particles along a side of the gamma sweep").positive().quick(21);
  d.param("linear-n", linear_n, "particles along a side of the linear (Hooke) run; 0 = none").non_negative().quick(21);
  d.param("edge-n", edge_ns, "particles along a side of the edge-stability runs at the default step; 0 = none").non_negative().quick({21});
  d.param("edge-eigen-n", eigen_n, "particles along a side of the spectrum of the linearised operator (dense: ~6 s at 21, ~4 min at 41); 0 = none").non_negative();
  d.param("edge-variants-n", edge_n, "particles along a side of the edge-stability variants (step, passes, nu, closure)").positive().quick(21);
  d.param("fem-m", fem_m, "finite element meshes of the linear reference: 2m x m elements (m along the radius)").positive();
  d.param("hourglass", p.hourglass, "zero-energy-mode control gamma of the study (TlConfig2D::hourglass; CHOSEN)").non_negative();
  d.param("settle", p.settle, "settling time after the ramp in 1/omega (CHOSEN)").non_negative();
  d.param("damping", p.damping, "mass-proportional damping in units of omega (CHOSEN)").non_negative();
  d.param("variational", p.variational, "boundary scheme: variational (true) or ghost reflection (false)");
  const sph::RunJobs jobs(d);  // --step-runs, --list-runs
  return d.run(argc, argv, [&] {
    const scenes::HoleStudySpec spec{ns, plain_ns, gammas, gamma_n, linear_n, edge_ns, edge_n, eigen_n, p};
    // The study's runs, named (the unit of a job: Makefile run_rules). Every run is stepped here (or read from its
    // run job's folder, --runs-from) before the outputs, which are then written in the study's order.
    const scenes::HoleStudyPlan plan = scenes::plan_hole_study(spec);
    const auto& runs = plan.runs;
    if (jobs.handled(plan.names(), [&](std::size_t i) { scenes::write_hole_run(d, "hole", scenes::run_hole(runs[i].second)); }))
      return;
    std::map<std::string, scenes::HoleResult> result;
    for (const auto& [name, q] : runs)
      result.emplace(name, jobs.result(name, [](const sph::RunFolder& f) { return scenes::read_hole_run(f, "hole"); },
                                       [&q = q] { return scenes::run_hole(q); }));

    scenes::HoleStudyOutput out(d, spec, plan, result);  // resolution.csv, history.csv
    // The linear-elastic concentration of this geometry by finite elements, refined to convergence. Its --quick
    // meshes are set after resolution.csv and history.csv are opened, whose headers record the default fem-m.
    if (d.quick() && !d.given("fem-m")) fem_m = {16, 32, 64};
    const std::vector<double> kf = out.fem_reference(fem_m);
    out.series(kf);
    out.edges();
  });
}
