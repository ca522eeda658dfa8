#include "gray2001/scenes/plate_run.hpp"

#include <cmath>

#include "core/diagnostics.hpp"
#include "core/fragments.hpp"
#include "core/materials.hpp"
#include "core/run_loop.hpp"
#include "frame/progress.hpp"

namespace scenes {

PlateRunSpec fig4_plate_run(int n, double Vf, double clamp_length, const sph::GrayParameters& scheme, double periods) {
  PlateRunSpec s;
  s.plate.L = 20.0;
  s.plate.H = 2.0;
  s.plate.dp = 2.0 / n;
  s.plate.clamp_length = clamp_length;
  s.plate.Vf = Vf;
  s.scheme = scheme;
  s.t_end = 2.0 * periods * plate_theory_period(scheme.mu, 2.0, 20.0);
  s.stop_after_crossings = 2;
  s.sample_dt = 0.5;
  s.fracture_check_dt = 100.0;
  s.power_budget = true;  // issue 15 (a): where the energy of the finest run comes from (Fig 4's energy rows)
  return s;
}

PlateRunSpec table_plate_run(double H, double Vf, double dp, double clamp_length, const sph::GrayParameters& scheme,
                             double periods, int crossings) {
  const double K = scheme.rho0 * scheme.c0 * scheme.c0;
  const double E = sph::young_from_bulk_shear(K, scheme.mu), nu = sph::poisson_ratio_from_bulk_shear(K, scheme.mu);
  PlateRunSpec s;
  s.plate.L = 20.0;
  s.plate.H = H;
  s.plate.dp = dp;
  s.plate.clamp_length = clamp_length;
  s.plate.Vf = Vf;
  s.scheme = scheme;
  s.t_end = periods * plate_theory_period(E, nu, H, 20.0, scheme.rho0);
  s.stop_after_crossings = crossings;
  s.sample_dt = 0.5;
  s.fracture_check_dt = 100.0;
  return s;
}

PlateRunResult run_plate(const PlateRunSpec& s,
                         const std::function<void(const sph::GraySolver&, const sph::ElasticBody&)>& on_sample,
                         const std::string& progress_label) {
  Plate plate = make_plate(s.plate, s.scheme);
  sph::ElasticBody& body = plate.body;
  sph::GraySolver solver(body, s.scheme, s.options);
  PlateRunResult r;
  r.dt = solver.time_step(s.plate.Vf * s.scheme.c0);
  r.particles = body.size();
  const double y0 = body.x[plate.tip].y();
  std::vector<bool> free_particles(body.size());
  for (std::size_t a = 0; a < body.size(); ++a) free_particles[a] = body.motion[a] == sph::Motion::Free;

  auto fragments = [&] { return sph::find_fragments(body.x, body.box, s.fracture_link * s.plate.dp, free_particles).count; };
  sph::Progress progress(progress_label, s.t_end);
  auto sample = [&](std::size_t pieces) {
    r.trace.push_back({solver.time(), body.x[plate.tip].y() - y0, sph::kinetic_energy(solver), solver.elastic_energy(), pieces});
    if (s.power_budget) {
      const auto p = solver.power_budget();
      r.trace.back().p_art = p.artificial_stress;
      r.trace.back().p_visc = p.viscosity;
      r.trace.back().p_xsph = p.xsph;
    }
    if (on_sample) on_sample(solver, body);
  };
  // Fracture checks every fracture_check_dt (and at t = 0), samples of the tip every sample_dt; a run stops
  // after its crossings or a while after the first fracture, if asked.
  sph::Cadence checks(s.fracture_check_dt), samples(s.sample_dt);
  std::size_t pieces = 1;
  int crossings = 0;
  auto observe = [&](const sph::GraySolver& sv) {
    if (sv.steps() == 0) {  // the start: the plate's pieces and the first sample
      checks.due(0.0);
      samples.due(0.0);
      pieces = fragments();
      sample(pieces);
      return false;
    }
    if (checks.due(sv.time())) {
      pieces = fragments();
      if (pieces > 1 && r.fracture_time < 0) r.fracture_time = sv.time();
      if (r.fracture_time >= 0 && s.run_after_fracture >= 0 && sv.time() >= r.fracture_time + s.run_after_fracture) {
        sample(pieces);
        return true;
      }
    }
    if (samples.due(sv.time())) {
      sample(pieces);
      const std::size_t k = r.trace.size();
      if (k > 2 && (r.trace[k - 1].y > 0) != (r.trace[k - 2].y > 0)) ++crossings;
      if (s.stop_after_crossings >= 0 && crossings >= s.stop_after_crossings) return true;
    }
    return false;
  };
  const auto outcome = sph::run(solver, {r.dt, s.max_steps, s.t_end}, observe,
                                [&](const sph::GraySolver& sv) { progress.update(sv.time(), sv.steps()); });
  r.blow_up = outcome.blow_up;
  r.steps = solver.steps();
  r.wall_s = progress.elapsed_s();
  return r;
}

std::vector<std::string> frame_columns() { return {"t", "x", "y", "sxx", "syy", "sxy", "fixed"}; }

void write_frame(sph::CsvWriter& out, const sph::GraySolver& solver, const sph::ElasticBody& body) {
  for (std::size_t a = 0; a < body.size(); ++a) {
    const sph::Tensor2 sig = solver.stress(a);
    out.row(solver.time(), body.x[a].x(), body.x[a].y(), sig(0, 0), sig(1, 1), sig(0, 1),
            body.motion[a] == sph::Motion::Free ? 0 : 1);
  }
}

std::vector<double> zero_crossings(const std::vector<TipSample>& trace) {
  std::vector<double> c;
  for (std::size_t i = 2; i < trace.size(); ++i) {  // skip the start, where y = 0 exactly
    const double y1 = trace[i - 1].y, y2 = trace[i].y;
    if ((y1 > 0) != (y2 > 0) && y1 != y2) c.push_back(trace[i - 1].t + (trace[i].t - trace[i - 1].t) * y1 / (y1 - y2));
  }
  return c;
}

double period_from_crossings(const std::vector<double>& crossings) {
  std::vector<double> c{0.0};
  c.insert(c.end(), crossings.begin(), crossings.end());
  if (c.size() == 2) return 2.0 * c[1];  // one half period only
  if (c.size() < 3) return std::nan("");
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i + 2 < c.size(); ++i, ++n) sum += c[i + 2] - c[i];
  return sum / n;
}

std::vector<double> half_cycle_extremes(const std::vector<TipSample>& trace) {
  std::vector<double> ext;
  double best = 0;
  for (std::size_t i = 1; i < trace.size(); ++i) {
    const double y = trace[i].y;
    if (i > 1 && (trace[i - 1].y > 0) != (y > 0)) {
      ext.push_back(best);
      best = 0;
    }
    if (std::abs(y) > std::abs(best)) best = y;
  }
  return ext;  // the last, unfinished half cycle is not included
}

}  // namespace scenes
