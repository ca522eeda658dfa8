#include "gray2001/scenes/plate_run.hpp"

#include <cmath>

#include "core/fragments.hpp"
#include "frame/progress.hpp"
#include "gray2001/scenes/sampled_run.hpp"

namespace scenes {

PlateRunResult run_plate(const PlateRunSpec& s,
                         const std::function<void(const sph::GraySolver&, const sph::ElasticBody&)>& on_sample,
                         const std::string& progress_label) {
  Plate plate = make_plate(s.plate);
  sph::GrayParameters p = gray_parameters(s, s.plate.rho0, s.plate.dp, plate.box);
  p.c0 = s.plate.c0;
  sph::GraySolver solver(plate.body, p, s.options);
  const double vmax = s.plate.Vf * s.plate.c0;
  PlateRunResult r;
  r.dt = sph::gray_time_step(p, s.cfl, vmax);
  r.particles = plate.body.size();
  const double y0 = plate.body.x[plate.tip].y();
  std::vector<bool> free_particles(plate.body.size());
  for (std::size_t a = 0; a < plate.body.size(); ++a) free_particles[a] = plate.body.motion[a] == sph::Motion::Free;

  auto fragments = [&] {
    return sph::find_fragments(plate.body.x, plate.box, s.fracture_link * s.plate.dp, free_particles).count;
  };
  auto sample = [&](std::size_t pieces) {
    r.trace.push_back({solver.time(), plate.body.x[plate.tip].y() - y0, solver.kinetic_energy(), solver.elastic_energy(), pieces});
    if (on_sample) on_sample(solver, plate.body);
  };
  sph::Progress progress(progress_label, s.t_end);
  std::size_t pieces = fragments();
  sample(pieces);
  double next_sample = s.sample_dt, next_check = s.fracture_check_dt;
  int crossings = 0;
  try {
    while (solver.time() < s.t_end - 1e-12 && (s.max_steps < 0 || solver.steps() < s.max_steps)) {
      solver.step(std::min(r.dt, s.t_end - solver.time()));
      if (solver.time() >= next_check - 1e-12) {
        next_check += s.fracture_check_dt;
        pieces = fragments();
        if (pieces > 1 && r.fracture_time < 0) r.fracture_time = solver.time();
        if (r.fracture_time >= 0 && s.run_after_fracture >= 0 && solver.time() >= r.fracture_time + s.run_after_fracture) {
          sample(pieces);
          break;
        }
      }
      if (solver.time() >= next_sample - 1e-12) {
        next_sample += s.sample_dt;
        sample(pieces);
        const std::size_t k = r.trace.size();
        if (k > 2 && (r.trace[k - 1].y > 0) != (r.trace[k - 2].y > 0)) ++crossings;
        if (s.stop_after_crossings >= 0 && crossings >= s.stop_after_crossings) break;
      }
      progress.update(solver.time(), solver.steps());
    }
  } catch (const sph::BlowUp& e) {
    r.blow_up = e.what();
  }
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

sph::Snapshot snapshot_of(const sph::GraySolver& solver, const sph::ElasticBody& body) {
  sph::Snapshot sn{solver.time(), solver.steps(), body.x, body.v, body.rho, {}, {}, {}};
  for (std::size_t a = 0; a < body.size(); ++a) {
    const sph::Tensor2 sig = solver.stress(a);
    sn.sxx.push_back(sig(0, 0));
    sn.syy.push_back(sig(1, 1));
    sn.sxy.push_back(sig(0, 1));
  }
  return sn;
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
