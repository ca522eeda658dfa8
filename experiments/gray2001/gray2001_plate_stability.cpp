// Stability stress test of the Gray et al. 2001 scheme on the oscillating plate (target G-stab, beyond
// the paper): (1) the time-step factor swept to the blow-up point, with and without the artificial
// stress, and the margin of the scheme's default factor below it; (2) a long run of --long-periods periods;
// (3) a random perturbation of the initial lattice; (4) the one-period run again at half the default step:
// the period it measures must not move at the printed precision of Tables 1-2 (this justifies the default).
//
// (1) is repeated at the papers' dp = 0.1 (--paper-sweep-dp, 0 skips; issue 14 item 5: a margin measured
// only at 8 across H said nothing of the resolution the tables run at), over --paper-cfl-values.
// Every run is named (--list-runs true prints them): each sweep point and the four runs of (2)-(4) are jobs of
// their own in make figures (Makefile run_rules, --step-runs; issue 17), which the collecting run reads back from
// their folders (--runs-from). A job steps its point whatever the points below it gave; the collecting run stops
// each sweep at its first failure, as before.
// CHOSEN parameters: H = 2, L = 20, dp = 0.25 (8 across H: the sweep needs many runs), mu = 0.6 and
// V_f = 0.01 (the shortest period of Table 1), the other parameters as the table driver. A run "blows
// up" when the solver stops it (non-finite state, density below 5% of rho0, or |v| > 100 c0) or when the
// plate breaks (fracture at a link of 1.5 dp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "frame/driver.hpp"
#include "core/materials.hpp"
#include "frame/run_jobs.hpp"
#include "gray2001/scenes/plate_run.hpp"
#include "gray2001/scenes/run_files.hpp"

namespace {

struct Params {
  double dp = 0.25, Vf = 0.01, sweep_time = 300, long_periods = 20, perturbation = 0.01, paper_dp = 0.1;
  sph::GrayParameters scheme;  // the scheme's defaults (parameters.hpp) but mu (the constructor)
  std::vector<double> cfls{0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.5, 3.0};
  std::vector<double> paper_cfls{0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0};  // from the default up: the sweep at dp stops at 1.5
  Params() { scheme.mu = 0.6; }  // CHOSEN: the shortest periods of Table 1
};

void declare(sph::Driver& d, Params& p) {
  d.param("dp", p.dp, "particle spacing").positive();
  d.param("mu", p.scheme.mu, "shear modulus").non_negative();
  d.param("Vf", p.Vf, "tip speed / c0");
  d.param("cfl-values", p.cfls, "time-step factors of the sweep").positive();
  d.param("paper-sweep-dp", p.paper_dp, "spacing of the second sweep, the papers' (0: no second sweep)").non_negative().quick(0);  // the papers' resolution is a full run's
  d.param("paper-cfl-values", p.paper_cfls, "time-step factors of the second sweep").positive();
  d.param("sweep-time", p.sweep_time, "simulated time of each sweep run").positive().quick(60);
  d.param("long-periods", p.long_periods, "length of the long run in theoretical periods").positive().quick(1.5);  // three crossings: first and last period
  d.param("perturbation", p.perturbation, "random initial displacement / dp of the perturbed run").non_negative();
  d.param("cfl", p.scheme.cfl, "time-step factor of the long and perturbed runs").positive();
}

scenes::PlateRunSpec base_spec(const Params& p) {
  scenes::PlateRunSpec s;
  s.plate.H = 2.0;
  s.plate.dp = p.dp;
  s.plate.clamp_length = 2.0;
  s.plate.Vf = p.Vf;
  s.scheme = p.scheme;
  s.sample_dt = 1.0;
  s.fracture_check_dt = 10.0;
  s.run_after_fracture = 0.0;
  return s;
}

scenes::PlateRunResult read_run(const sph::RunFolder& f) { return scenes::read_plate_run(f, "plate"); }

// (1) Time-step sweeps at dp and at the papers' spacing (values suffixed _dp<spacing>); their points.
struct Point { int sweep; double spacing, eps, cfl; std::string name; };  // sweep 0: at dp, 1: at the papers' spacing

std::vector<Point> sweep_points(const Params& p) {
  std::vector<Point> points;
  auto add_sweep = [&](int sweep, double spacing, const std::vector<double>& factors) {
    for (const double eps : {0.0, 0.3})
      for (const double cfl : factors) {
        std::ostringstream name;
        name << "sweep_dp" << sph::format_number(spacing) << "_eps" << eps << "_cfl" << cfl;
        points.push_back({sweep, spacing, eps, cfl, name.str()});
      }
  };
  add_sweep(0, p.dp, p.cfls);
  if (p.paper_dp > 0) add_sweep(1, p.paper_dp, p.paper_cfls);
  return points;
}

scenes::PlateRunResult step_point(const Params& p, const Point& q) {
  auto s = base_spec(p);
  s.plate.dp = q.spacing;
  s.scheme.cfl = q.cfl;
  s.scheme.eps_artificial = q.eps;
  s.options.artificial_stress = q.eps > 0;
  s.t_end = p.sweep_time;
  return scenes::run_plate(s, {}, "cfl sweep dp " + sph::format_number(q.spacing));
}

// One sweep's rows of cfl_sweep.csv, stopped at its first failure, and its largest stable factor and margin.
void write_sweep(sph::Driver& d, const sph::RunJobs& jobs, const Params& p, const std::vector<Point>& points,
                 sph::CsvWriter& sweep, int which, const std::string& suffix) {
  for (const double eps : {0.0, 0.3}) {
    double largest_stable = 0;
    for (const Point& q : points) {
      if (q.sweep != which || q.eps != eps) continue;
      const auto r = jobs.result(q.name, read_run, [&] { return step_point(p, q); });
      const bool blew = !r.blow_up.empty(), broke = r.fracture_time >= 0;
      sweep.row(q.spacing, eps, q.cfl, r.dt, r.steps, r.trace.back().t, blew ? 1 : 0, broke ? 1 : 0, r.blow_up);
      if (!blew && !broke && q.cfl > largest_stable) largest_stable = q.cfl;
      if (blew || broke) break;  // larger factors only fail sooner
    }
    const std::string e = (eps > 0 ? "eps0.3" : "eps0") + suffix;
    d.value("largest_stable_cfl_" + e, largest_stable, "largest time-step factor of the sweep that neither blew up nor broke");
    d.value("stability_margin_" + e, largest_stable / p.scheme.cfl, "largest stable factor / the factor of the runs (--cfl)");
  }
}

// (2) The long run, (3) the perturbed lattice against an unperturbed reference of the same length, (4) the
// reference at half the step.
struct Whole { std::string name; double periods, shake, cfl_scale; };

std::vector<Whole> whole_runs(const Params& p) {
  return {{"reference", 1.0, 0.0, 1.0}, {"halved_dt", 1.0, 0.0, 0.5}, {"perturbed", 1.0, p.perturbation, 1.0},
          {"long", p.long_periods, 0.0, 1.0}};
}

scenes::PlateRunResult step_whole(const Params& p, const Whole& w, double T) {
  auto s = base_spec(p);
  s.scheme.cfl *= w.cfl_scale;
  s.t_end = w.periods * T * 2.0;  // margin: coarse plates run up to 1.5x the thin-plate period (G-fig4)
  s.stop_after_crossings = static_cast<int>(std::lround(2 * w.periods));
  s.plate.perturbation = w.shake;
  s.run_after_fracture = -1;
  return scenes::run_plate(s, {}, w.name);
}

// A whole run's first and last periods and its pieces at the end.
struct WholePeriods { double T_first, T_last; std::size_t fragments; };

// A whole run's row of runs.csv and its tip trace.
WholePeriods write_whole(sph::Driver& d, sph::CsvWriter& runs, const Whole& w, const scenes::PlateRunResult& r) {
  if (!r.blow_up.empty()) throw std::runtime_error(w.name + ": " + r.blow_up);
  const auto c = scenes::zero_crossings(r.trace);
  const double T_first = c.size() >= 2 ? c[1] : NAN;
  const double T_last = c.size() >= 3 ? c[c.size() - 1] - c[c.size() - 3] : NAN;
  const double e0 = r.trace.front().ke + r.trace.front().ee, e1 = r.trace.back().ke + r.trace.back().ee;
  runs.row(w.name, w.periods, r.steps, r.wall_s, T_first, T_last, r.trace.back().fragments, e0, e1);
  auto trace = d.csv("tip_" + w.name + ".csv", {"t", "y_tip", "kinetic", "elastic", "fragments"});
  for (const auto& smp : r.trace) trace.row(smp.t, smp.y, smp.ke, smp.ee, smp.fragments);
  return {T_first, T_last, r.trace.back().fragments};
}

}  // namespace

int main(int argc, char** argv) {
  sph::Driver d("gray2001_plate_stability", "G-stab", "Stability of the plate: time-step sweep, long run, perturbed lattice");
  Params p;
  declare(d, p);
  const sph::RunJobs jobs(d);  // --step-runs, --list-runs

  return d.run(argc, argv, [&] {
    const double T = scenes::plate_theory_period(p.scheme.mu, 2.0, 20.0);
    const std::vector<Point> points = sweep_points(p);
    const std::vector<Whole> wholes = whole_runs(p);
    std::vector<std::string> names;
    for (const Point& q : points) names.push_back(q.name);
    for (const Whole& w : wholes) names.push_back(w.name);
    if (jobs.handled(names, [&](std::size_t i) {
          scenes::write_plate_run(d, "plate", i < points.size() ? step_point(p, points[i]) : step_whole(p, wholes[i - points.size()], T));
        }))
      return;
    // Every run read from its job's folder (--runs-from), or stepped here.
    auto sweep = d.csv("cfl_sweep.csv", {"dp", "eps", "cfl", "dt", "steps", "t_reached", "blew_up", "fractured", "message"});
    write_sweep(d, jobs, p, points, sweep, 0, "");
    if (p.paper_dp > 0) write_sweep(d, jobs, p, points, sweep, 1, "_dp" + sph::format_number(p.paper_dp));
    auto runs = d.csv("runs.csv", {"run", "periods", "steps", "wall_s", "T_first", "T_last", "fragments", "energy_first", "energy_last"});
    auto one = [&](const std::string& name) {
      const Whole& w = *std::find_if(wholes.begin(), wholes.end(), [&](const Whole& x) { return x.name == name; });
      return write_whole(d, runs, w, jobs.result(name, read_run, [&] { return step_whole(p, w, T); }));
    };
    const WholePeriods ref = one("reference");
    const WholePeriods half = one("halved_dt");
    d.value("halved_dt_period_change", std::abs(half.T_first / ref.T_first - 1.0), "|T(cfl / 2) / T(cfl) - 1| of the one-period run");
    const WholePeriods pert = one("perturbed");
    d.value("perturbed_period_change", std::abs(pert.T_first / ref.T_first - 1.0), "|T(perturbed) / T(lattice) - 1|");
    d.value("perturbed_fragments", static_cast<double>(pert.fragments), "pieces after one period (1 = intact)");
    const WholePeriods lng = one("long");
    d.value("long_run_fragments", static_cast<double>(lng.fragments), "pieces after the long run (1 = intact)");
    d.value("long_run_period_drift", std::abs(lng.T_last / lng.T_first - 1.0), "|last period / first period - 1|");
  });
}
