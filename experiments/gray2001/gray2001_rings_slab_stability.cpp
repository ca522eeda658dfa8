// Stability stress test of the Gray et al. 2001 scheme on the rings and the slab (target G-stab-rs, beyond the
// paper; the plate has G-stab): (1) the time-step factor swept to the blow-up point on both scenes, with
// the artificial stress (eps = 0.3) and without; (2) the ring collision at twice the paper's speed
// (0.118 each, relative 0.236), eps = 0.3; (3) the margin of the scheme's default factor below the limits, and
// the default justified: the whole collision (rings dp) and the slab to parting (slab dp), eps = 0.3, again at
// half the step, must give the quantities G-fig6 and G-fig8 check (restitution, fragments, parting time)
// unchanged within those checks' tolerances; the slab as an ensemble of 8 seeds at each factor (its parting
// time is one draw of an instability grown from the lattice's seed), compared by the median.
//
// Every run is named (--list-runs true prints them): each sweep point, each run of (3) and the fast collision are
// jobs of their own in make figures (Makefile run_rules, --step-runs; issue 17), which the collecting run reads back
// from their folders (--runs-from). A job steps its point whatever the points below it gave; the collecting run
// stops each sweep at its first failure, as before.
//
// CHOSEN parameters: rings dp = 0.2 over t = 80 (the first half of the impact, where the rings are most
// compressed); slab dp = 0.064 over t = 300 (strain 0.075, well into the plastic range); the fast collision
// at the paper's dp = 0.1. A sweep run FAILS when the solver stops it (non-finite state, density below 5% of
// rho0, |v| > 100 c0) or the body breaks (a ring in more than one fragment; the slab's ends parted) although
// the sweep's first run (the smallest factor) did not: without the artificial stress the slab parts by
// t ~ 190 at any stable step (the tensile instability, G-fig8), which is physics of the scheme, not of the
// step. The sweep stops at the first failure. Other parameters as the scene drivers.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "frame/driver.hpp"
#include "frame/run_jobs.hpp"
#include "gray2001/scenes/rings_run.hpp"
#include "gray2001/scenes/run_files.hpp"
#include "gray2001/scenes/slab.hpp"

namespace {

// The command line's parameters (declare() below: names, defaults, --quick values).
struct Params {
  double rings_dp = 0.2, slab_dp = 0.064, rings_time = 80, slab_time = 300, fast_dp = 0.1, fast_speed = 0.118;
  std::vector<double> cfls{0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.5, 3.0};
  double cfl = sph::GrayParameters{}.cfl;  // the scheme's default (parameters.hpp), used by the scene drivers
  int slab_seeds = 8;
  double slab_jitter = 1e-8;
};

void declare(sph::Driver& d, Params& p) {
  d.param("rings-dp", p.rings_dp, "particle spacing of the rings sweep").positive();
  d.param("slab-dp", p.slab_dp, "particle spacing of the slab sweep").positive();
  d.param("rings-time", p.rings_time, "simulated time of each rings sweep run").positive().quick(40);
  d.param("slab-time", p.slab_time, "simulated time of each slab sweep run").positive().quick(60);
  d.param("cfl-values", p.cfls, "time-step factors of the sweep").positive();
  d.param("fast-dp", p.fast_dp, "particle spacing of the fast collision").positive().quick(0.2);
  d.param("fast-speed", p.fast_speed, "speed of each ring in the fast collision (paper: 0.059)").positive();
  d.param("cfl", p.cfl, "the factor of the scene drivers: the margins and the halved-step runs refer to it").positive();
  d.param("slab-seeds", p.slab_seeds, "members of the slab's parting-time ensemble at each of the two factors").positive();
  d.param("slab-jitter", p.slab_jitter, "largest random displacement of the ensemble's particles, in dp (SlabSpec::jitter)").non_negative();
}

// Every scene's size before the first run: a spacing typed wrong stops here, not after the other scenes.
void check_sizes(const Params& p) {
  for (const double dp : {p.rings_dp, p.fast_dp}) { scenes::RingsSpec r; r.dp = dp; scenes::check_size(r); }
  { scenes::SlabSpec s; s.dp = p.slab_dp; scenes::check_size(s); }
  if (p.slab_seeds < 1) throw std::invalid_argument("--slab-seeds must be >= 1");
}

// The specs of every run, and their names.
scenes::RingsRunSpec sweep_rings(const Params& p, double eps, double f) {
  scenes::RingsRunSpec rs;
  rs.rings.dp = p.rings_dp;
  rs.rings.gap = std::max(0.2, 2.0 * p.rings_dp);
  rs.scheme.cfl = f;
  rs.options.artificial_stress = eps > 0;
  rs.scheme.eps_artificial = eps;
  rs.t_max = p.rings_time;
  rs.run_after_contact = -1;
  return rs;
}

scenes::SlabRunSpec sweep_slab(const Params& p, double eps, double f) {
  scenes::SlabRunSpec ss;
  ss.slab.dp = p.slab_dp;
  ss.scheme.cfl = f;
  ss.options.artificial_stress = eps > 0;
  ss.scheme.eps_artificial = eps;
  ss.t_max = p.slab_time;
  ss.run_after_fracture = 0;
  return ss;
}

scenes::RingsRunSpec whole_rings(const Params& p, double f) {
  scenes::RingsRunSpec rs;
  rs.rings.dp = p.rings_dp;
  rs.rings.gap = std::max(0.2, 2.0 * p.rings_dp);
  rs.scheme.cfl = f;
  return rs;
}

scenes::SlabRunSpec ensemble_slab(const Params& p, double f, int seed) {
  scenes::SlabRunSpec ss;
  ss.slab.dp = p.slab_dp;
  ss.slab.jitter = p.slab_jitter;
  ss.slab.seed = static_cast<unsigned>(seed);
  ss.scheme.cfl = f;
  return ss;
}

scenes::RingsRunSpec fast_rings(const Params& p) {
  scenes::RingsRunSpec fs;
  fs.rings.dp = p.fast_dp;
  fs.rings.gap = std::max(0.2, 2.0 * p.fast_dp);
  fs.rings.speed = p.fast_speed;
  return fs;
}

// (3): the drivers' factor and half of it.
std::array<double, 2> factors(const Params& p) { return {p.cfl, 0.5 * p.cfl}; }

std::string text(double x) { std::ostringstream o; o << x; return o.str(); }
std::string sweep_name(const char* scene, double eps, double f) { return std::string(scene) + "_eps" + text(eps) + "_cfl" + text(f); }
std::string slab_label(double f, int seed) { return "slab at cfl " + sph::format_number(f) + ", seed " + std::to_string(seed); }

// The named runs, and a run job's work for each name: step the run, write it.
struct Plan {
  std::vector<std::string> names;
  std::vector<std::function<void()>> steps;
  template <class Step, class Write>
  void add(const sph::Driver& d, const std::string& name, Step&& step, Write&& write) {
    names.push_back(name);
    steps.push_back([&d, name, step, write] { write(d, "run", step()); });
  }
};

Plan plan_runs(const sph::Driver& d, const Params& p) {
  Plan plan;
  for (const double eps : {0.0, 0.3})
    for (const double f : p.cfls) {
      plan.add(d, sweep_name("rings", eps, f), [&p, eps, f] { return scenes::run_rings(sweep_rings(p, eps, f), {}, "rings cfl sweep"); },
               scenes::write_rings_run);
      plan.add(d, sweep_name("slab", eps, f), [&p, eps, f] { return scenes::run_slab(sweep_slab(p, eps, f), {}, "slab cfl sweep"); },
               scenes::write_slab_run);
    }
  for (const double f : factors(p)) {
    plan.add(d, "rings_cfl" + text(f), [&p, f] { return scenes::run_rings(whole_rings(p, f), {}, "rings at cfl " + std::to_string(f)); },
             scenes::write_rings_run);
    if (d.quick()) continue;
    for (int seed = 0; seed < p.slab_seeds; ++seed)
      plan.add(d, "slab_cfl" + text(f) + "_seed" + std::to_string(seed),
               [&p, f, seed] { return scenes::run_slab(ensemble_slab(p, f, seed), {}, slab_label(f, seed)); }, scenes::write_slab_run);
  }
  plan.add(d, "fast", [&p] { return scenes::run_rings(fast_rings(p), {}, "rings fast"); }, scenes::write_rings_run);
  return plan;
}

// Every run read from its job's folder (--runs-from), or stepped here.
scenes::RingsRunResult rings(const sph::RunJobs& jobs, const std::string& name, const scenes::RingsRunSpec& spec, const std::string& label) {
  return jobs.result(name, [](const sph::RunFolder& f) { return scenes::read_rings_run(f, "run"); },
                     [&] { return scenes::run_rings(spec, {}, label); });
}

scenes::SlabRunResult slab(const sph::RunJobs& jobs, const std::string& name, const scenes::SlabRunSpec& spec, const std::string& label) {
  return jobs.result(name, [](const sph::RunFolder& f) { return scenes::read_slab_run(f, "run"); },
                     [&] { return scenes::run_slab(spec, {}, label); });
}

// (1): each sweep up to its first failure, and the largest stable factors.
void write_sweeps(sph::Driver& d, const sph::RunJobs& jobs, const Params& p) {
  auto sweep = d.csv("cfl_sweep.csv", {"scene", "eps", "cfl", "dt", "steps", "t_reached", "blew_up", "broke", "failed", "message"});
  for (const double eps : {0.0, 0.3}) {
    const std::string e = eps > 0 ? "eps0.3" : "eps0";
    double stable_rings = 0, stable_slab = 0;
    bool rings_baseline_broke = false, slab_baseline_broke = false;
    for (const double cfl : p.cfls) {
      const auto r = rings(jobs, sweep_name("rings", eps, cfl), sweep_rings(p, eps, cfl), "rings cfl sweep");
      const bool blew = !r.blow_up.empty(), broke = r.max_fragments > 1;
      if (cfl == p.cfls.front()) rings_baseline_broke = broke;
      const bool failed = blew || (broke && !rings_baseline_broke);
      sweep.row("rings", eps, cfl, r.dt, r.steps, r.trace.back().t, blew ? 1 : 0, broke ? 1 : 0, failed ? 1 : 0, r.blow_up);
      if (failed) break;
      stable_rings = cfl;
    }
    for (const double cfl : p.cfls) {
      const auto r = slab(jobs, sweep_name("slab", eps, cfl), sweep_slab(p, eps, cfl), "slab cfl sweep");
      const bool blew = !r.blow_up.empty(), broke = r.fracture_time >= 0;
      if (cfl == p.cfls.front()) slab_baseline_broke = broke;
      const bool failed = blew || (broke && !slab_baseline_broke);
      sweep.row("slab", eps, cfl, r.dt, r.steps, r.trace.back().t, blew ? 1 : 0, broke ? 1 : 0, failed ? 1 : 0, r.blow_up);
      if (failed) break;
      stable_slab = cfl;
    }
    d.value("rings_largest_stable_cfl_" + e, stable_rings, "largest factor of the sweep that neither blew up nor broke a ring the first run kept whole");
    d.value("slab_largest_stable_cfl_" + e, stable_slab, "largest factor of the sweep that neither blew up nor parted a slab the first run kept whole");
    d.value("rings_stability_margin_" + e, stable_rings / p.cfl, "largest stable factor / the drivers' factor (--cfl)");
    d.value("slab_stability_margin_" + e, stable_slab / p.cfl, "largest stable factor / the drivers' factor (--cfl)");
  }
}

// The slab's parting times at the two factors (one ensemble of seeds each): medians, shares, spreads.
void write_parting(sph::Driver& d, const std::vector<double> (&parting)[2]) {
  // -1: did not part by t_max; the median is then taken with those as the latest (they sort last as +inf).
  auto median = [](std::vector<double> t) {
    for (double& x : t) x = x < 0 ? INFINITY : x;
    std::sort(t.begin(), t.end());
    const std::size_t n = t.size();
    return n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
  };
  // The members that parted: their share, and their spread over the median.
  auto parted = [](const std::vector<double>& t) {
    std::vector<double> p;
    for (double x : t)
      if (x >= 0) p.push_back(x);
    return p;
  };
  const double m0 = median(parting[0]), m1 = median(parting[1]);
  d.value("slab_halved_dt_fracture_time_change", std::isfinite(m0) && std::isfinite(m1) ? std::abs(m1 / m0 - 1.0) : NAN,
          "|median parting time(cfl / 2) / median(cfl) - 1| over the seed ensembles, eps = 0.3 (NaN unless both medians parted)");
  const char* tag[2] = {"cfl", "half_cfl"};
  for (int k = 0; k < 2; ++k) {
    const auto p = parted(parting[k]);
    const std::string t = tag[k];
    d.value("slab_fracture_time_median_" + t, k ? m1 : m0, "median parting time over the seeds (unparted members last)");
    d.value("slab_parted_share_" + t, double(p.size()) / parting[k].size(), "share of the seeds whose ends parted by t_max");
    if (!p.empty()) {
      const auto [lo, hi] = std::minmax_element(p.begin(), p.end());
      d.value("slab_fracture_time_spread_" + t, (*hi - *lo) / (k ? m1 : m0), "(latest - earliest parting) / median, parted members");
    }
  }
}

// (3): the drivers' factor and half of it, eps = 0.3 (the slab's runs to parting only in full runs). The slab's
// parting time is the growth of an instability from the lattice's seed: one run is one draw (the same
// code, run with one thread and with two, parted at 676 and 522 at half the factor: the threads' sum order
// alone). So the slab is run as an ensemble of seeds at each factor (SlabSpec::jitter: random displacements
// of 1e-8 dp, far below any length of the problem) and the medians are compared.
void write_halved(sph::Driver& d, const sph::RunJobs& jobs, const Params& p) {
  auto halved = d.csv("halved_dt.csv", {"scene", "cfl", "seed", "dt", "steps", "restitution", "max_fragments", "fracture_time", "message"});
  scenes::RingsRunResult rings_at[2];
  std::vector<double> parting[2];
  const auto fs = factors(p);
  for (int k = 0; k < 2; ++k) {
    const double f = fs[k];
    rings_at[k] = rings(jobs, "rings_cfl" + text(f), whole_rings(p, f), "rings at cfl " + std::to_string(f));
    const auto& r = rings_at[k];
    if (!r.blow_up.empty()) throw std::runtime_error("rings at cfl " + std::to_string(f) + ": " + r.blow_up);
    halved.row("rings", f, -1, r.dt, r.steps, r.restitution, r.max_fragments, r.fracture_time, r.blow_up);
    if (d.quick()) continue;
    for (int seed = 0; seed < p.slab_seeds; ++seed) {
      const auto q = slab(jobs, "slab_cfl" + text(f) + "_seed" + std::to_string(seed), ensemble_slab(p, f, seed), slab_label(f, seed));
      if (!q.blow_up.empty()) throw std::runtime_error(slab_label(f, seed) + ": " + q.blow_up);
      halved.row("slab", f, seed, q.dt, q.steps, NAN, NAN, q.fracture_time, q.blow_up);
      parting[k].push_back(q.fracture_time);
    }
  }
  d.value("rings_halved_dt_restitution_change", std::abs(rings_at[1].restitution - rings_at[0].restitution),
          "|restitution(cfl / 2) - restitution(cfl)|, eps = 0.3");
  d.value("rings_halved_dt_fragments_change", std::abs(double(rings_at[1].max_fragments) - double(rings_at[0].max_fragments)),
          "|most fragments(cfl / 2) - most fragments(cfl)|, eps = 0.3");
  if (!d.quick()) write_parting(d, parting);
}

// (2): the fast collision.
void write_fast(sph::Driver& d, const sph::RunJobs& jobs, const Params& p) {
  const auto r = rings(jobs, "fast", fast_rings(p), "rings fast");
  auto fast = d.csv("fast_collision.csv", {"dp", "speed", "steps", "wall_s", "blew_up", "max_fragments", "min_main_share", "max_stray",
                                           "contact_duration", "restitution", "message"});
  const double duration = r.contact_end >= 0 ? r.contact_end - r.contact_start : NAN;
  fast.row(p.fast_dp, p.fast_speed, r.steps, r.wall_s, r.blow_up.empty() ? 0 : 1, r.max_fragments, r.min_main_share, r.max_stray,
           duration, r.restitution, r.blow_up);
  d.value("fast_blew_up", r.blow_up.empty() ? 0.0 : 1.0, "the 2x collision stopped the solver");
  d.value("fast_max_fragments", static_cast<double>(r.max_fragments), "most fragments of a ring at 2x speed");
  d.value("fast_min_main_share", r.min_main_share, "smallest share of a ring in its largest piece at 2x speed");
  d.value("fast_restitution", r.restitution, "relative speed after / before at 2x speed (-1: not separated)");
}

}  // namespace

int main(int argc, char** argv) {
  sph::Driver d("gray2001_rings_slab_stability", "G-stab-rs", "Stability of the rings and the slab: time-step sweep, fast collision");
  Params p;
  declare(d, p);
  const sph::RunJobs jobs(d);  // --step-runs, --list-runs

  return d.run(argc, argv, [&] {
    check_sizes(p);
    const Plan plan = plan_runs(d, p);
    if (jobs.handled(plan.names, [&](std::size_t i) { plan.steps[i](); })) return;
    write_sweeps(d, jobs, p);
    write_halved(d, jobs, p);
    write_fast(d, jobs, p);
  });
}
