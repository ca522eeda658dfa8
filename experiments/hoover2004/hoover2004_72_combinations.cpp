// Beyond Hoover, Hoover & Merritt 2004: the 2 x 2 x 2 x 3 x 3 = 72 algorithm combinations of Sec. IX on the
// rotating 217-particle hexagon for one nominal revolution: (i) closest-approach reflection or not,
// (ii) von Neumann-Richtmyer viscosity or not, (iii) summed or continuity densities, (iv) dr/dt = v, <v> or
// <v>_M, (v) angular momentum held by Gauss's principle, Ldot_i scaling or Ldot_ij scaling. Ranked by the
// retention of L (|1 - L/L0| after the revolution; a run that blew up ranks last) and then by the shape
// error (rms distance from the best-rotated initial hexagon). Writes ranking.csv and the usual series.
// CHOSEN: dt = 0.1 (the sweep costs 72 revolutions: about 5 minutes on 2 idle cores, 8 on the shared
// machine; the runs are spread over the OpenMP threads), <v>_M with arithmetic
// rho_ij, plain continuity equation, closest distance 0.7, viscosity q = rho (2 dx)^2 (div v)^2 in compression.
// Each combination is a run of its own, named by its label with '_' for '/' (--list-runs true prints them): a job
// of its own in make figures (Makefile run_rules, --step-runs; issue 17), which writes its run into its folder
// (scenes/hexagon_files.hpp) for the collecting run to read back (--runs-from).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "frame/driver.hpp"
#include "frame/run_jobs.hpp"
#include "hoover2004/scenes/hexagon.hpp"
#include "hoover2004/scenes/hexagon_files.hpp"

using namespace sph;

namespace {

// The 2 x 2 x 2 x 3 x 3 combinations of Sec. IX, each named by its label.
std::vector<scenes::HexagonVariant> combinations() {
  std::vector<scenes::HexagonVariant> v;
  for (bool approach : {false, true})
    for (bool visc : {false, true})
      for (auto dens : {SpamDensity::Summation, SpamDensity::Continuity})
        for (auto adv : {SpamAdvection::Velocity, SpamAdvection::Shepard, SpamAdvection::MonaghanArithmetic})
          for (auto torque : {SpamTorque::Gauss, SpamTorque::ParticleScaling, SpamTorque::PairScaling}) {
            SpamOptions o;
            o.closest_approach = approach; o.viscosity = visc; o.density = dens; o.advection = adv; o.torque = torque;
            v.push_back({o.label(), o});
          }
  return v;
}

struct Row { std::string variant; double L_ratio, shape, failed_at; long reflections; SpamOptions o; };

// The runs (runs[i] of v[i]) after one nominal revolution, ranked by the retention of L, then by the shape error.
std::vector<Row> ranked(const scenes::HexagonSetup& s, const std::vector<scenes::HexagonVariant>& v,
                        const std::vector<scenes::HexagonRun>& runs) {
  const double pi = std::acos(-1.0);
  std::vector<Row> rows;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const auto& r = runs[i];
    const std::size_t k = r.sample_at_angle(2 * pi, s.omega());
    const bool done = !r.failed && k < r.t.size();
    rows.push_back({r.variant, done ? r.L[k] / r.L0 : std::nan(""), done ? r.shape_rms[k] : std::nan(""),
                    r.failed ? r.failed_at : -1.0, r.reflections, v[i].options});
  }
  auto key = [](const Row& r) { return std::isfinite(r.L_ratio) ? std::abs(1 - r.L_ratio) : 1e300; };
  std::stable_sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) {
    if (key(a) != key(b)) return key(a) < key(b);
    const double sa = std::isfinite(a.shape) ? a.shape : 1e300, sb = std::isfinite(b.shape) ? b.shape : 1e300;
    return sa < sb;
  });
  // L held to 1e-6 counts as held (RK4 keeps the quadratic L only to its order): ties go by the shape error.
  std::stable_sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) {
    const double ka = std::max(key(a), 1e-6), kb = std::max(key(b), 1e-6);
    if (ka != kb) return ka < kb;
    const double sa = std::isfinite(a.shape) ? a.shape : 1e300, sb = std::isfinite(b.shape) ? b.shape : 1e300;
    return sa < sb;
  });
  return rows;
}

void write_ranking(Driver& d, const std::vector<Row>& rows) {
  auto out = d.csv("ranking.csv", {"rank", "variant", "L_over_L0_360deg", "shape_rms_360deg", "failed_at", "reflections"});
  int rank = 1, survived = 0, held = 0;
  for (const auto& r : rows) {
    out.row(static_cast<double>(rank++), r.variant, r.L_ratio, r.shape, r.failed_at, static_cast<double>(r.reflections));
    if (r.failed_at < 0) ++survived;
    if (std::isfinite(r.L_ratio) && std::abs(1 - r.L_ratio) < 1e-6) ++held;
  }
  d.value("combinations", static_cast<double>(rows.size()), "2 x 2 x 2 x 3 x 3");
  d.value("combinations_surviving", survived, "runs that did not blow up in a revolution");
  d.value("combinations_holding_L", held, "runs with |1 - L/L0| < 1e-6 after a revolution");
}

// Sec. X: "the combination of Monaghan's velocity averaging with a conservative local constraint on the
// angular momentum provides good solutions", and "velocity averaging (or viscosity, or a minimum distance
// of closest approach) can provide accurate simulations": the <v>_M + pair-torque runs against the runs
// with none of the three (dr/dt = v, no viscosity, no closest approach).
// A run that ended before the revolution without blowing up (--revolutions < 1) measures neither: NaN.
void record_sec_x(Driver& d, const std::vector<Row>& rows) {
  auto holds = [](const Row& r) { return r.failed_at < 0 && std::isfinite(r.L_ratio) && std::abs(1 - r.L_ratio) < 1e-6; };
  auto unsampled = [](const Row& r) { return r.failed_at < 0 && !std::isfinite(r.L_ratio); };
  double monaghan_pair = 0, monaghan_pair_held = 0;
  double best_monaghan_pair = INFINITY, best_unprotected = INFINITY;
  for (const auto& r : rows) {
    const bool mp = r.o.advection == SpamAdvection::MonaghanArithmetic && r.o.torque == SpamTorque::PairScaling;
    const bool unprotected = r.o.advection == SpamAdvection::Velocity && !r.o.viscosity && !r.o.closest_approach;
    const double shape = unsampled(r) ? NAN : r.failed_at < 0 ? r.shape : INFINITY;  // a blow-up: unbounded
    if (mp) {
      ++monaghan_pair;
      monaghan_pair_held += unsampled(r) ? NAN : holds(r) ? 1 : 0;
      best_monaghan_pair = std::isnan(shape) ? NAN : std::min(best_monaghan_pair, shape);
    }
    if (unprotected) best_unprotected = std::isnan(shape) ? NAN : std::min(best_unprotected, shape);
  }
  d.value("monaghan_pair_torque_runs", monaghan_pair, "runs with <v>_M and the pair torque scaling (2 x 2 x 2)");
  d.value("monaghan_pair_torque_holding_L", monaghan_pair_held, "of them: no blow-up and |1 - L/L0| < 1e-6 after the revolution");
  // 0 when every unprotected run blew up (its shape error is then unbounded).
  d.value("shape_best_monaghan_pair_over_best_unprotected",
          std::isinf(best_unprotected) && std::isfinite(best_monaghan_pair) ? 0.0 : best_monaghan_pair / best_unprotected,
          "smallest shape error of the <v>_M + pair-torque runs over that of the runs without averaging, viscosity "
          "or closest approach (0: every one of those blew up)");
}

}  // namespace

int main(int argc, char** argv) {
  Driver d("hoover2004_72_combinations", "H-72", "all 72 SPAM combinations of Sec. IX ranked");
  scenes::HexagonSetup s;
  s.dt = 0.1;
  auto hex = scenes::hexagon_params(d, s);
  hex.shells.quick(3);
  hex.dt.quick(0.2);
  hex.revolutions.quick(0.25);
  const sph::RunJobs jobs(d);  // --step-runs, --list-runs
  return d.run(argc, argv, [&] {
    const double pi = std::acos(-1.0);
    s.snapshot_angles = {2 * pi};
    const std::vector<scenes::HexagonVariant> v = combinations();
    std::vector<std::string> names;
    for (const auto& x : v) names.push_back(scenes::value_name(x.name));
    if (jobs.handled(names, [&](std::size_t i) { scenes::write_hexagon_run(d, "hexagon", scenes::run_hexagon(s, v[i])); }))
      return;
    std::vector<scenes::HexagonRun> runs;  // read from the run jobs' folders (--runs-from), else stepped here
    for (const auto& name : names)
      if (const auto folder = jobs.folder(name)) runs.push_back(scenes::read_hexagon_run(*folder, "hexagon"));
    if (runs.empty()) runs = scenes::run_hexagons(s, v);
    scenes::record_hexagons(d, s, v, runs);
    const std::vector<Row> rows = ranked(s, v, runs);
    write_ranking(d, rows);
    record_sec_x(d, rows);
  });
}
