// Gray, Monaghan & Swift 2001, Fig. 4 (Section 7.1): the tip y(t) of the plate (H = 2, L = 20,
// mu = 0.22, V_f = 0.01, eps = 0.3) for n = 10, 20, 30 particle spacings across H: "the period and amplitude
// of the oscillations are converging", "the amplitude decreases by approximately 6% per oscillation
// because of dissipation". The paper gives no viscosity constants: this driver also runs the coarsest n
// with a list of alpha (beta = alpha) values to show how the decay depends on that choice.
// Each run also records its wall time, so the same table is the work-precision data (see
// plots/G-fig4.py); G-wp fits the convergence order.
//
// Parameters: as gray2001_table1_2_plate_periods, but each run stops at the tip's second zero crossing: one
// period, two half-cycle extremes (the decay per period is 1 - (second / first)^2).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "frame/driver.hpp"
#include "core/materials.hpp"
#include "gray2001/scenes/plate_run.hpp"
#include "gray2001/scenes/run_files.hpp"
#include "frame/run_jobs.hpp"

int main(int argc, char** argv) {
  sph::Driver d("gray2001_fig4_plate_resolution", "G-fig4", "Gray et al. 2001 Fig 4: plate tip y(t) against resolution");
  std::vector<int> ns{10, 20, 30};
  std::vector<double> alphas{0.5, 2.0};
  double clamp = 2.0, Vf = 0.01, periods = 1.0;
  sph::GrayParameters scheme;  // the scheme's defaults (parameters.hpp); Fig 4's mu = 0.22 is the default
  d.param("n", ns, "particles across H = 2").positive().quick({4, 6, 8});
  d.param("alpha", scheme.alpha, "artificial viscosity alpha (= beta) of the resolution runs").non_negative();
  d.param("alphas-coarse", alphas, "further alpha (= beta) values run at the coarsest n").non_negative().quick({2.0});
  d.param("clamp-length", clamp, "plate length held between the fixed layers").non_negative();
  d.param("cfl", scheme.cfl, "time-step factor").positive();
  d.param("mu", scheme.mu, "shear modulus (Fig 4: 0.22)").non_negative();
  d.param("Vf", Vf, "tip speed / c0 (Fig 4: 0.01)");
  d.param("eps", scheme.eps_artificial, "artificial stress factor (Sec 6: 0.3; 0 = none: the energy study of issue 15)").non_negative();
  d.param("eps-xsph", scheme.eps_xsph, "XSPH factor (Sec 3: 0.5; 0 = particles move with their own velocity)").non_negative();
  d.param("periods", periods, "half the longest run, in theoretical periods (runs stop at the second crossing)").positive();
  const sph::RunJobs jobs(d);  // --step-runs, --list-runs

  return d.run(argc, argv, [&] {
    if (ns.size() < 2) throw std::invalid_argument("need at least two resolutions");
    const double mu = scheme.mu, alpha = scheme.alpha;
    const double T_theory = scenes::plate_theory_period(mu, 2.0, 20.0);
    struct Run { int n; double alpha; };
    std::vector<Run> runs;
    for (int n : ns) runs.push_back({n, alpha});
    for (double a : alphas) runs.push_back({ns.front(), a});
    // Each run named (the unit of a job: Makefile run_rules): stepped here, or read from its run job's folder.
    auto tag_of = [](const Run& run) {
      std::ostringstream tag;
      tag << "n" << run.n << "_alpha" << run.alpha;
      return tag.str();
    };
    auto spec_of = [&](const Run& run) {
      sph::GrayParameters run_scheme = scheme;
      run_scheme.alpha = run_scheme.beta = run.alpha;
      return scenes::fig4_plate_run(run.n, Vf, clamp, run_scheme, periods);
    };
    std::vector<std::string> names;
    for (const Run& run : runs) names.push_back(tag_of(run));
    auto step = [&](std::size_t i) { return scenes::run_plate(spec_of(runs[i]), {}, "plate " + names[i]); };
    if (jobs.handled(names, [&](std::size_t i) { scenes::write_plate_run(d, "plate", step(i)); })) return;
    // wall_s: the run's time loop, where it was stepped (its run job, or this process).
    auto table = d.csv("runs.csv", {"n", "alpha", "particles", "dt", "steps", "wall_s", "T_sph", "amp_first", "amp_second",
                                    "decay_per_period", "T_over_theory"});
    std::vector<double> T_of_n, A_of_n;  // period and first amplitude at the study's alpha, by n
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const Run& run = runs[i];
      const std::string tag_text = tag_of(run);
      const auto r = jobs.result(tag_text, [](const sph::RunFolder& f) { return scenes::read_plate_run(f, "plate"); },
                                 [&] { return step(i); });
      if (!r.blow_up.empty()) throw std::runtime_error(tag_text + ": " + r.blow_up);
      const double T = scenes::period_from_crossings(scenes::zero_crossings(r.trace));
      const auto ext = scenes::half_cycle_extremes(r.trace);
      const double a1 = ext.size() > 0 ? std::abs(ext[0]) : NAN, a2 = ext.size() > 1 ? std::abs(ext[1]) : NAN;
      const double decay = 1.0 - (a2 / a1) * (a2 / a1);  // two half cycles make a period
      table.row(run.n, run.alpha, r.particles, r.dt, r.steps, r.wall_s, T, a1, a2, decay, T / T_theory);
      auto trace = d.csv("tip_" + tag_text + ".csv", {"t", "y_tip", "kinetic", "elastic", "power_artificial_stress", "power_viscosity", "power_xsph"});
      for (const auto& smp : r.trace) trace.row(smp.t, smp.y, smp.ke, smp.ee, smp.p_art, smp.p_visc, smp.p_xsph);
      d.value("T_" + tag_text, T, "period from the zero crossings");
      d.value("amplitude_" + tag_text, a1, "first extreme of the tip displacement");
      d.value("decay_per_period_" + tag_text, decay, "1 - (second extreme / first)^2");
      // Kinetic + elastic energy (issue 15 a: at n = 30 it grows, by the work of the artificial stress).
      if (!r.trace.empty()) {
        const double E0 = r.trace.front().ke + r.trace.front().ee;
        double E_max = E0;
        for (const auto& smp : r.trace) E_max = std::max(E_max, smp.ke + smp.ee);
        const double dE = (r.trace.back().ke + r.trace.back().ee) / E0 - 1;
        d.value("energy_change_" + tag_text, dE, "(kinetic + elastic) at the run's end (second crossing) over the start, minus 1");
        d.value("energy_peak_" + tag_text, E_max / E0 - 1, "largest (kinetic + elastic) over the start, minus 1");
        // The budget (GraySolver::PowerBudget): the works of the artificial stress, the viscosity and XSPH
        // (trapezoids over the samples) and what they leave of the energy change (the stress power's own
        // mismatch, the clamp, the sampling).
        double W_art = 0, W_visc = 0, W_xsph = 0;
        for (std::size_t i = 1; i < r.trace.size(); ++i) {
          const double dt = r.trace[i].t - r.trace[i - 1].t;
          W_art += 0.5 * dt * (r.trace[i].p_art + r.trace[i - 1].p_art);
          W_visc += 0.5 * dt * (r.trace[i].p_visc + r.trace[i - 1].p_visc);
          W_xsph += 0.5 * dt * (r.trace[i].p_xsph + r.trace[i - 1].p_xsph);
        }
        d.value("work_artificial_stress_" + tag_text, W_art / E0, "work of the artificial stress over the run / initial energy");
        d.value("work_viscosity_" + tag_text, W_visc / E0, "work of the viscosity over the run / initial energy (<= 0)");
        d.value("work_xsph_" + tag_text, W_xsph / E0, "work of XSPH's velocity (GraySolver::PowerBudget::xsph) over the run / initial energy");
        d.value("energy_residual_" + tag_text, dE - (W_art + W_visc + W_xsph) / E0,
                "energy change minus the three works, / initial energy: the part no counted term explains");
      }
      if (run.alpha == alpha) T_of_n.push_back(T), A_of_n.push_back(a1);
    }
    // Convergence ('the period and amplitude of the oscillations are converging'): successive differences shrink.
    const auto change_ratio = [](const std::vector<double>& x) {
      const std::size_t m = x.size();
      return std::abs(x[m - 1] - x[m - 2]) / std::abs(x[m - 2] - x[m - 3]);
    };
    if (T_of_n.size() >= 3) {
      d.value("period_change_ratio_finest", change_ratio(T_of_n), "|T(n3) - T(n2)| / |T(n2) - T(n1)|: < 1 when converging");
      d.value("amplitude_change_ratio_finest", change_ratio(A_of_n), "|A(n3) - A(n2)| / |A(n2) - A(n1)| of the first extreme: < 1 when converging");
    }
    d.value("T_finest_over_theory", T_of_n.back() / T_theory, "finest-resolution period / thin-plate theory (H)");
  });
}
