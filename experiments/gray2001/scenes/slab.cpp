#include "gray2001/scenes/slab.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "core/diagnostics.hpp"
#include "core/lattices.hpp"
#include "core/run_loop.hpp"
#include "frame/progress.hpp"

namespace scenes {

sph::GrayParameters slab_scheme() {
  sph::GrayParameters p;
  p.mu = 0.3;
  return p;
}

sph::GrayOptions slab_options() {
  sph::GrayOptions o;
  o.plasticity = true;
  return o;
}

void check_size(const SlabSpec& s) {
  sph::check_particle_count((s.L / s.dp) * (s.H / s.dp), s.dp, "slab");
}

Slab make_slab(const SlabSpec& s, double rho0) {
  if (!(s.dp > 0) || !(s.L > 0) || !(s.H > 0) || !(s.band > 0) || s.end_accel < 0 || !(s.margin > 0))
    throw std::invalid_argument("slab: need dp, L, H, band, margin > 0 and end acceleration >= 0");
  check_size(s);
  const long nx = std::lround(s.L / s.dp), ny = std::lround(s.H / s.dp);
  Slab slab;
  slab.nx = nx;
  slab.ny = ny;
  slab.length = nx * s.dp;
  slab.height = ny * s.dp;
  if (ny < 3 || 2.0 * s.band >= slab.length - 2.0 * s.dp)
    throw std::invalid_argument("slab: need at least 3 particles across and free particles between the bands");
  if (!(s.jitter >= 0) || s.jitter >= 0.1) throw std::invalid_argument("slab: need 0 <= jitter < 0.1 (in dp)");
  const double m = rho0 * s.dp * s.dp;
  std::mt19937_64 random(s.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (long j = 0; j < ny; ++j)
    for (long i = 0; i < nx; ++i) {
      sph::Vec2 x((i + 0.5) * s.dp, (j + 0.5) * s.dp);
      const bool left = x.x() < s.band, right = x.x() > slab.length - s.band;  // of the lattice site
      if (s.jitter > 0) x += s.jitter * s.dp * sph::Vec2(unit(random), unit(random));
      if (left || right) {
        (left ? slab.left_band : slab.right_band).push_back(slab.body.size());
        slab.body.add(x, sph::Vec2::Zero(), m, rho0, sph::Motion::Driven, sph::Vec2(left ? -s.end_accel : s.end_accel, 0.0));
      } else {
        slab.body.add(x, sph::Vec2::Zero(), m, rho0);
      }
    }
  if (slab.left_band.empty() || slab.right_band.empty()) throw std::invalid_argument("slab: band narrower than dp / 2");
  slab.body.dp = s.dp;
  slab.body.box = {-s.margin, -s.margin, slab.length + s.margin, slab.height + s.margin, false, false};
  return slab;
}

SlabRunResult run_slab(const SlabRunSpec& s, const SlabObserver& on_sample, const std::string& progress_label) {
  if (!(s.t_max > 0) || !(s.sample_dt > 0) || !(s.fracture_link > 0) || !(s.neck_bin >= 1) || !(s.clump_ratio > 0) ||
      !(s.opening_gap > 1))
    throw std::invalid_argument("slab run: need t_max, sample_dt, fracture_link, clump_ratio > 0, neck_bin >= 1, opening_gap > 1");
  const double reach = 0.5 * s.slab.end_accel * s.t_max * s.t_max;
  if (reach > 0.9 * s.slab.margin)
    throw std::invalid_argument("slab run: the ends would travel " + std::to_string(reach) + " by t_max: raise the margin");
  Slab slab = make_slab(s.slab, s.scheme.rho0);
  sph::ElasticBody& body = slab.body;
  sph::GraySolver solver(body, s.scheme, s.options);
  SlabRunResult r;
  r.dt = solver.time_step(s.slab.end_accel * s.t_max);
  r.particles = body.size();
  SlabMeter meter(slab_geometry(slab), s);
  std::vector<SlabMeasurement> samples;
  double fracture_time = -1;

  auto sample = [&] {
    samples.push_back(meter.measure(solver.time(), body.x, sph::kinetic_energy(solver), solver.elastic_energy()));
    r.trace.push_back(samples.back().sample);
    if (r.trace.back().parted && fracture_time < 0) fracture_time = solver.time();
    if (on_sample) on_sample(solver, body, r.trace.back());
  };
  sph::Progress progress(progress_label, s.t_max);
  sph::Cadence cadence(s.sample_dt);
  auto observe = [&](const sph::GraySolver& sv) {
    if (!cadence.due(sv.time())) return false;
    sample();
    return sv.steps() > 0 && slab_stops_at(fracture_time, sv.time(), s);
  };
  r.blow_up = sph::run(solver, {r.dt, -1, s.t_max}, observe,
                       [&](const sph::GraySolver& sv) { progress.update(sv.time(), sv.steps()); }).blow_up;
  r.steps = solver.steps();
  r.wall_s = progress.elapsed_s();
  const SlabSummary sum = summarise_slab(samples, s, body.dp);
  set_summary(r, sum);
  return r;
}

}  // namespace scenes
