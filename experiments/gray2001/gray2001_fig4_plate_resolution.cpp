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

namespace {

struct Params {
  std::vector<int> ns{10, 20, 30};
  std::vector<double> alphas{0.5, 2.0};
  double clamp = 2.0, Vf = 0.01, periods = 1.0;
  sph::GrayParameters scheme;  // the scheme's defaults (parameters.hpp); Fig 4's mu = 0.22 is the default
};

void declare(sph::Driver& d, Params& p) {
  d.param("n", p.ns, "particles across H = 2").positive().quick({4, 6, 8});
  d.param("alpha", p.scheme.alpha, "artificial viscosity alpha (= beta) of the resolution runs").non_negative();
  d.param("alphas-coarse", p.alphas, "further alpha (= beta) values run at the coarsest n").non_negative().quick({2.0});
  d.param("clamp-length", p.clamp, "plate length held between the fixed layers").non_negative();
  d.param("cfl", p.scheme.cfl, "time-step factor").positive();
  d.param("mu", p.scheme.mu, "shear modulus (Fig 4: 0.22)").non_negative();
  d.param("Vf", p.Vf, "tip speed / c0 (Fig 4: 0.01)");
  d.param("eps", p.scheme.eps_artificial, "artificial stress factor (Sec 6: 0.3; 0 = none: the energy study of issue 15)").non_negative();
  d.param("eps-xsph", p.scheme.eps_xsph, "XSPH factor (Sec 3: 0.5; 0 = particles move with their own velocity)").non_negative();
  d.param("periods", p.periods, "half the longest run, in theoretical periods (runs stop at the second crossing)").positive();
}

struct Run { int n; double alpha; };

// Each run named (the unit of a job: Makefile run_rules): stepped here, or read from its run job's folder.
std::string tag_of(const Run& run) {
  std::ostringstream tag;
  tag << "n" << run.n << "_alpha" << run.alpha;
  return tag.str();
}

scenes::PlateRunSpec spec_of(const Params& p, const Run& run) {
  sph::GrayParameters run_scheme = p.scheme;
  run_scheme.alpha = run_scheme.beta = run.alpha;
  return scenes::fig4_plate_run(run.n, p.Vf, p.clamp, run_scheme, p.periods);
}

// Kinetic + elastic energy (issue 15 a: at n = 30 it grows, by the work of the artificial stress).
void write_energy_values(sph::Driver& d, const std::string& tag_text, const std::vector<scenes::TipSample>& trace) {
  const double E0 = trace.front().ke + trace.front().ee;
  double E_max = E0;
  for (const auto& smp : trace) E_max = std::max(E_max, smp.ke + smp.ee);
  const double dE = (trace.back().ke + trace.back().ee) / E0 - 1;
  d.value("energy_change_" + tag_text, dE, "(kinetic + elastic) at the run's end (second crossing) over the start, minus 1");
  d.value("energy_peak_" + tag_text, E_max / E0 - 1, "largest (kinetic + elastic) over the start, minus 1");
  // The budget (GraySolver::PowerBudget): the works of the artificial stress, the viscosity and XSPH
  // (trapezoids over the samples) and what they leave of the energy change (the stress power's own
  // mismatch, the clamp, the sampling).
  double W_art = 0, W_visc = 0, W_xsph = 0;
  for (std::size_t i = 1; i < trace.size(); ++i) {
    const double dt = trace[i].t - trace[i - 1].t;
    W_art += 0.5 * dt * (trace[i].p_art + trace[i - 1].p_art);
    W_visc += 0.5 * dt * (trace[i].p_visc + trace[i - 1].p_visc);
    W_xsph += 0.5 * dt * (trace[i].p_xsph + trace[i - 1].p_xsph);
  }
  d.value("work_artificial_stress_" + tag_text, W_art / E0, "work of the artificial stress over the run / initial energy");
  d.value("work_viscosity_" + tag_text, W_visc / E0, "work of the viscosity over the run / initial energy (<= 0)");
  d.value("work_xsph_" + tag_text, W_xsph / E0, "work of XSPH's velocity (GraySolver::PowerBudget::xsph) over the run / initial energy");
  d.value("energy_residual_" + tag_text, dE - (W_art + W_visc + W_xsph) / E0,
          "energy change minus the three works, / initial energy: the part no counted term explains");
}

// A run's row of runs.csv, its tip trace and values; returns its period and first amplitude.
std::pair<double, double> write_run(sph::Driver& d, sph::CsvWriter& table, const Run& run, const scenes::PlateRunResult& r,
                                    double T_theory) {
  const std::string tag_text = tag_of(run);
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
  if (!r.trace.empty()) write_energy_values(d, tag_text, r.trace);
  return {T, a1};
}

}  // namespace

int main(int argc, char** argv) {
  sph::Driver d("gray2001_fig4_plate_resolution", "G-fig4", "Gray et al. 2001 Fig 4: plate tip y(t) against resolution");
  Params p;
  declare(d, p);
  const sph::RunJobs jobs(d);  // --step-runs, --list-runs

  return d.run(argc, argv, [&] {
    if (p.ns.size() < 2) throw std::invalid_argument("need at least two resolutions");
    const double mu = p.scheme.mu, alpha = p.scheme.alpha;
    const double T_theory = scenes::plate_theory_period(mu, 2.0, 20.0);
    std::vector<Run> runs;
    for (int n : p.ns) runs.push_back({n, alpha});
    for (double a : p.alphas) runs.push_back({p.ns.front(), a});
    std::vector<std::string> names;
    for (const Run& run : runs) names.push_back(tag_of(run));
    auto step = [&](std::size_t i) { return scenes::run_plate(spec_of(p, runs[i]), {}, "plate " + names[i]); };
    if (jobs.handled(names, [&](std::size_t i) { scenes::write_plate_run(d, "plate", step(i)); })) return;
    // wall_s: the run's time loop, where it was stepped (its run job, or this process).
    auto table = d.csv("runs.csv", {"n", "alpha", "particles", "dt", "steps", "wall_s", "T_sph", "amp_first", "amp_second",
                                    "decay_per_period", "T_over_theory"});
    std::vector<double> T_of_n, A_of_n;  // period and first amplitude at the study's alpha, by n
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const auto r = jobs.result(tag_of(runs[i]), [](const sph::RunFolder& f) { return scenes::read_plate_run(f, "plate"); },
                                 [&] { return step(i); });
      const auto [T, a1] = write_run(d, table, runs[i], r, T_theory);
      if (runs[i].alpha == alpha) T_of_n.push_back(T), A_of_n.push_back(a1);
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
