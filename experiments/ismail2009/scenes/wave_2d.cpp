#include "ismail2009/scenes/wave_2d.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/materials.hpp"
#include "core/run_loop.hpp"
#include "ismail2009/scenes/domain_2d.hpp"
#include "total_lagrangian/solver_2d.hpp"

namespace scenes {

using sph::Vec2;

namespace {
const auto zero = [](const Vec2&, double) { return 0.0; };
}

sph::TlConfig2D wave_body(const Wave2DSpec& spec) {
  if (spec.kind != "strain" && spec.kind != "stress") throw std::invalid_argument("wave_body: kind strain or stress, not " + spec.kind);
  const SmoothedPulse p(spec.p0, spec.pulse, spec.smooth);
  auto dom = rectangle_domain(spec.L, spec.height(), 0, 1, 2, 2);
  // Left: tensile traction T11 = +p (t = P n with n = -e1: t1 = -p); right: held; sides: u2 = 0 (strain)
  // or free (stress), always free to slide.
  const auto condition = sph::boundary_condition;
  std::vector<sph::BoundaryCondition2D> conds{
      condition(false, [p](const Vec2&, double t) { return -p(t); }, false, zero),
      condition(true, zero, true, zero),
      spec.kind == "strain" ? condition(false, zero, true, zero) : condition(false, zero, false, zero)};
  auto cfg = make_body(dom, conds, spec.ps, spec.h_over_ps);
  cfg.rho = spec.rho;
  cfg.lame = sph::lame_from_young_poisson(spec.E, spec.nu);
  return cfg;
}

double wave_dt(const Wave2DSpec& spec, double support_radius) {
  return 0.3 * support_radius / sph::longitudinal_wave_speed(sph::lame_from_young_poisson(spec.E, spec.nu), spec.rho);
}

double wave_t_end(const Wave2DSpec& spec) {
  return 0.13 / sph::longitudinal_wave_speed(sph::lame_from_young_poisson(spec.E, spec.nu), spec.rho) + spec.pulse + 2e-6;
}

WaveRecord run_wave_2d(const Wave2DSpec& spec) {
  sph::TlSolver2D body(wave_body(spec));
  const double dt = wave_dt(spec, body.h()), t_end = wave_t_end(spec);
  const auto gx = spec.gauge_x();
  const int rows = spec.rows;
  WaveRecord rec;
  rec.particles = body.n_real();
  rec.gauge_i.assign(gx.size(), {});
  for (std::size_t g = 0; g < gx.size(); ++g)
    for (int r = 0; r < rows; ++r) rec.gauge_i[g].push_back(body.nearest({gx[g], r * spec.ps}));
  rec.T.assign(gx.size(), std::vector<std::vector<double>>(rows));
  double t = 0;  // the time before the step just taken: the stress refers to it
  auto record = [&](const sph::TlSolver2D& b) {
    if (b.steps() > 0) {
      rec.t.push_back(t);
      for (std::size_t g = 0; g < gx.size(); ++g)
        for (int r = 0; r < rows; ++r) rec.T[g][r].push_back(b.cauchy(rec.gauge_i[g][r])(0, 0));
    }
    t = b.time();
    return false;
  };
  sph::RunPlan plan{dt};
  plan.t_end = t_end;
  plan.whole_steps = true;
  const auto outcome = sph::run(body, plan, record);
  if (outcome.blew_up()) throw std::runtime_error(spec.kind + " wave run became non-finite: " + outcome.blow_up);
  rec.steps = outcome.steps;
  rec.wall_s = outcome.wall_s;
  return rec;
}

WaveMeasures measure_wave(const Wave2DSpec& spec, const std::vector<double>& ts,
                          const std::vector<std::vector<std::vector<double>>>& T) {
  const auto gx = spec.gauge_x();
  const int rows = spec.rows, mid = rows / 2;
  if (T.size() != gx.size()) throw std::invalid_argument("measure_wave: one record per gauge");
  for (const auto& g : T) {
    if (static_cast<int>(g.size()) != rows) throw std::invalid_argument("measure_wave: one record per row");
    for (const auto& v : g)
      if (v.size() != ts.size()) throw std::invalid_argument("measure_wave: one value per time");
  }
  const double p0 = spec.p0, pulse = spec.pulse;
  auto centroid = [&](int g) {
    const double t50 = crossing_time(ts, T[g][mid], 0.5 * p0);
    return centroid_time(ts, T[g][mid], t50 - 0.5 * pulse, t50 + 1.5 * pulse);
  };
  WaveMeasures m;
  m.speed = (gx[1] - gx[0]) / (centroid(1) - centroid(0));
  const double t50 = crossing_time(ts, T[0][mid], 0.5 * p0), mid_t = t50 + 0.5 * pulse;
  double spread = 0, amp = 0;
  for (int r = 0; r < rows; ++r) {
    const double a = window_mean(ts, T[0][r], mid_t - 0.1 * pulse, mid_t + 0.1 * pulse);
    if (r == mid) amp = a;
    spread = std::max(spread, std::abs(a - window_mean(ts, T[0][mid], mid_t - 0.1 * pulse, mid_t + 0.1 * pulse)));
  }
  m.plateau_over_p0 = amp / p0;
  m.spread_over_p0 = spread / p0;
  return m;
}

}  // namespace scenes
