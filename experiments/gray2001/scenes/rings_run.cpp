#include "gray2001/scenes/rings_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/diagnostics.hpp"
#include "core/fragments.hpp"
#include "core/run_loop.hpp"
#include "frame/progress.hpp"

namespace scenes {

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
  const std::size_t n = body.size(), nl = rings.first_right;
  std::vector<bool> in_left(n, false), in_right(n, false);
  for (std::size_t a = 0; a < n; ++a) (a < nl ? in_left : in_right)[a] = true;
  double mass_l = 0, mass_r = 0;
  for (std::size_t a = 0; a < n; ++a) (a < nl ? mass_l : mass_r) += body.m[a];

  // Pieces of one ring: its fragments, its stray particles, and the label of its largest piece.
  struct Pieces { sph::Fragments f; std::size_t main = 0, fragments = 0, stray = 0; };
  auto pieces_of = [&](const std::vector<bool>& ring) {
    Pieces p{sph::find_fragments(body.x, body.box, s.fracture_link * s.rings.dp, ring)};
    for (std::size_t k = 0; k < p.f.sizes.size(); ++k) {
      if (p.f.sizes[k] > p.f.sizes[p.main]) p.main = k;
      if (p.f.sizes[k] >= s.min_fragment) ++p.fragments;
      else p.stray += p.f.sizes[k];
    }
    return p;
  };
  auto sample = [&] {
    const Pieces L = pieces_of(in_left), R = pieces_of(in_right);
    sph::Vec2 pl = sph::Vec2::Zero(), pr = sph::Vec2::Zero(), xl = sph::Vec2::Zero(), xr = sph::Vec2::Zero();
    for (std::size_t a = 0; a < n; ++a) {
      (a < nl ? pl : pr) += body.m[a] * body.v[a];
      (a < nl ? xl : xr) += body.m[a] * body.x[a];
    }
    const sph::Vec2 vl = pl / mass_l, vr = pr / mass_r;
    // Contact from the pair list: a pair of the two main pieces with a non-zero kernel interacts.
    const auto& pairs = solver.pairs();
    double dmin = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < nl; ++a) {
      if (L.f.label[a] != L.main) continue;
      for (std::uint32_t k = pairs.first(a); k < pairs.last(a); ++k) {
        const std::uint32_t b = pairs.b[k];
        if (b >= nl && R.f.label[b] == R.main && pairs.W[k] > 0) dmin = std::min(dmin, pairs.dx[k].norm());
      }
    }
    const int contact = std::isfinite(dmin) ? 1 : 0;
    const double share = std::min(static_cast<double>(L.f.sizes[L.main]) / nl, static_cast<double>(R.f.sizes[R.main]) / (n - nl));
    r.trace.push_back({solver.time(), sph::kinetic_energy(solver), 0.5 * (mass_l * vl.squaredNorm() + mass_r * vr.squaredNorm()),
                       solver.elastic_energy(), vl.x(), vr.x(), xl.x() / mass_l, xr.x() / mass_r, dmin, contact, L.fragments,
                       R.fragments, L.stray + R.stray, share});
    r.max_fragments = std::max({r.max_fragments, L.fragments, R.fragments});
    r.max_stray = std::max(r.max_stray, L.stray + R.stray);
    r.min_main_share = std::min(r.min_main_share, share);
    if (std::max(L.fragments, R.fragments) > 1 && r.fracture_time < 0) r.fracture_time = solver.time();
    if (contact && r.contact_start < 0) r.contact_start = solver.time();
    if (!contact && r.contact_start >= 0 && r.contact_end < 0) r.contact_end = solver.time();
    if (on_sample) on_sample(solver, body);
  };
  sph::Progress progress(progress_label, s.t_max);
  auto separated_long_enough = [&] {
    return r.contact_end >= 0 && s.run_after_contact >= 0 && solver.time() >= r.contact_end + s.run_after_contact;
  };
  sph::Cadence samples(s.sample_dt);
  auto observe = [&](const sph::GraySolver& sv) {
    if (!samples.due(sv.time())) return false;
    sample();
    return sv.steps() > 0 && separated_long_enough();
  };
  r.blow_up = sph::run(solver, {r.dt, -1, s.t_max}, observe,
                       [&](const sph::GraySolver& sv) { progress.update(sv.time(), sv.steps()); }).blow_up;
  if (r.contact_end >= 0 && r.blow_up.empty()) {
    const auto& last = r.trace.back();
    r.rebound_speed = 0.5 * (last.v_right - last.v_left);
    r.restitution = r.rebound_speed / s.rings.speed;
  }
  r.steps = solver.steps();
  r.wall_s = progress.elapsed_s();
  return r;
}

}  // namespace scenes
