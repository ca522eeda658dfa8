#include "gray2001/scenes/rings_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/kernels.hpp"
#include "core/run_loop.hpp"
#include "frame/progress.hpp"

namespace scenes {

RingsProbeSpec rings_probe_spec(const RingsRunSpec& s, const Rings& rings) {
  RingsProbeSpec p;
  p.first_right = rings.first_right;
  p.box = rings.body.box;
  p.dp = rings.body.dp;
  p.support = sph::CubicSpline::support() * (s.scheme.h_over_dp * rings.body.dp);  // the solver's (gray_solver.cpp)
  p.fracture_link = s.fracture_link;
  p.min_fragment = s.min_fragment;
  return p;
}

RingsRunResult run_rings(const RingsRunSpec& s,
                         const std::function<void(const sph::GraySolver&, const sph::ElasticBody&)>& on_sample,
                         const std::string& progress_label) {
  if (!(s.t_max > 0) || !(s.sample_dt > 0) || !(s.fracture_link > 0) || s.min_fragment < 1)
    throw std::invalid_argument("rings run: need t_max, sample_dt, fracture_link > 0 and min_fragment >= 1");
  Rings rings = make_rings(s.rings, s.scheme.rho0);
  sph::ElasticBody& body = rings.body;
  sph::GraySolver solver(body, s.scheme, s.options);
  RingsRunResult r;
  r.dt = solver.time_step(s.rings.speed);
  r.particles = body.size();
  const RingsProbe probe(rings_probe_spec(s, rings), body.m);
  RingsCollision collision;
  auto sample = [&] {
    r.trace.push_back(probe(solver.time(), body.x, body.v, solver.elastic_energy()));
    collision.add(r.trace.back());
    if (on_sample) on_sample(solver, body);
  };
  sph::Progress progress(progress_label, s.t_max);
  sph::Cadence samples(s.sample_dt);
  auto observe = [&](const sph::GraySolver& sv) {
    if (!samples.due(sv.time())) return false;
    sample();
    return sv.steps() > 0 && collision.separated_for(sv.time(), s.run_after_contact);
  };
  r.blow_up = sph::run(solver, {r.dt, -1, s.t_max}, observe,
                       [&](const sph::GraySolver& sv) { progress.update(sv.time(), sv.steps()); }).blow_up;
  collision.finish(r.trace.back(), s.rings.speed, !r.blow_up.empty());
  r.contact_start = collision.contact_start;
  r.contact_end = collision.contact_end;
  r.rebound_speed = collision.rebound_speed;
  r.restitution = collision.restitution;
  r.fracture_time = collision.fracture_time;
  r.max_fragments = collision.max_fragments;
  r.max_stray = collision.max_stray;
  r.min_main_share = collision.min_main_share;
  r.steps = solver.steps();
  r.wall_s = progress.elapsed_s();
  return r;
}

}  // namespace scenes
