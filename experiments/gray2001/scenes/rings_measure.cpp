#include "gray2001/scenes/rings_measure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/fragments.hpp"
#include "core/kernels.hpp"

namespace scenes {

RingsProbe::RingsProbe(const RingsProbeSpec& spec, std::vector<double> masses) : s_(spec), m_(std::move(masses)) {
  const std::size_t n = m_.size(), nl = s_.first_right;
  if (nl == 0 || nl >= n) throw std::invalid_argument("rings measurement: each ring needs particles (first_right in (0, n))");
  if (!(s_.dp > 0) || !(s_.support > 0) || !(s_.fracture_link > 0) || s_.min_fragment < 1)
    throw std::invalid_argument("rings measurement: need dp, support, fracture_link > 0 and min_fragment >= 1");
  in_left_.assign(n, false);
  in_right_.assign(n, false);
  for (std::size_t a = 0; a < n; ++a) (a < nl ? in_left_ : in_right_)[a] = true;
  for (std::size_t a = 0; a < n; ++a) (a < nl ? mass_l_ : mass_r_) += m_[a];
}

RingsSample RingsProbe::operator()(double t, const std::vector<sph::Vec2>& x, const std::vector<sph::Vec2>& v,
                                   double elastic_energy) const {
  const std::size_t n = m_.size(), nl = s_.first_right;
  if (x.size() != n || v.size() != n) throw std::invalid_argument("rings measurement: state of another size than the rings");
  // Pieces of one ring: its fragments, its stray particles, and the label of its largest piece.
  struct Pieces { sph::Fragments f; std::size_t main = 0, fragments = 0, stray = 0; };
  auto pieces_of = [&](const std::vector<bool>& ring) {
    Pieces p{sph::find_fragments(x, s_.box, s_.fracture_link * s_.dp, ring)};
    for (std::size_t k = 0; k < p.f.sizes.size(); ++k) {
      if (p.f.sizes[k] > p.f.sizes[p.main]) p.main = k;
      if (p.f.sizes[k] >= s_.min_fragment) ++p.fragments;
      else p.stray += p.f.sizes[k];
    }
    return p;
  };
  const Pieces L = pieces_of(in_left_), R = pieces_of(in_right_);
  sph::Vec2 pl = sph::Vec2::Zero(), pr = sph::Vec2::Zero(), xl = sph::Vec2::Zero(), xr = sph::Vec2::Zero();
  for (std::size_t a = 0; a < n; ++a) {
    (a < nl ? pl : pr) += m_[a] * v[a];
    (a < nl ? xl : xr) += m_[a] * x[a];
  }
  const sph::Vec2 vl = pl / mass_l_, vr = pr / mass_r_;
  // Contact: a pair of the two main pieces inside the support with W > 0, tested as the solver's pair list does
  // (core/pair_list.hpp's refresh: r^2 < support^2, then the kernel), so that the set is the pair list's. The cell
  // list is built a little wider than the support so that no candidate the pair list would keep is missed.
  const double support2 = s_.support * s_.support, h = 0.5 * s_.support;
  const auto kernel = sph::CubicSpline(2).at(h);
  sph::CellList2D cells(s_.box, s_.support * 1.01);
  cells.build(x);
  double dmin = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < nl; ++a) {
    if (L.f.label[a] != L.main) continue;
    cells.for_each_neighbour(x, a, s_.support * 1.01, [&](std::size_t b, const sph::Vec2& d, double) {
      if (b < nl || R.f.label[b] != R.main) return;
      const double r2 = d.squaredNorm();
      if (r2 >= support2) return;
      double w, f;
      kernel(std::sqrt(r2), w, f);
      if (w > 0) dmin = std::min(dmin, d.norm());
    });
  }
  const int contact = std::isfinite(dmin) ? 1 : 0;
  double ke = 0;  // as sph::kinetic_energy (core/diagnostics.hpp), in a loop of its own like it
  for (std::size_t a = 0; a < n; ++a) ke += 0.5 * m_[a] * v[a].squaredNorm();
  const double share =
      std::min(static_cast<double>(L.f.sizes[L.main]) / nl, static_cast<double>(R.f.sizes[R.main]) / (n - nl));
  return {t, ke, 0.5 * (mass_l_ * vl.squaredNorm() + mass_r_ * vr.squaredNorm()), elastic_energy, vl.x(), vr.x(),
          xl.x() / mass_l_, xr.x() / mass_r_, dmin, contact, L.fragments, R.fragments, L.stray + R.stray, share};
}

void RingsCollision::add(const RingsSample& s) {
  max_fragments = std::max({max_fragments, s.fragments_left, s.fragments_right});
  max_stray = std::max(max_stray, s.stray);
  min_main_share = std::min(min_main_share, s.main_share);
  if (std::max(s.fragments_left, s.fragments_right) > 1 && fracture_time < 0) fracture_time = s.t;
  if (s.contact && contact_start < 0) contact_start = s.t;
  if (!s.contact && contact_start >= 0 && contact_end < 0) contact_end = s.t;
}

bool RingsCollision::separated_for(double t, double run_after_contact) const {
  return contact_end >= 0 && run_after_contact >= 0 && t >= contact_end + run_after_contact;
}

void RingsCollision::finish(const RingsSample& last, double speed, bool blew_up) {
  if (contact_end >= 0 && !blew_up) {
    rebound_speed = 0.5 * (last.v_right - last.v_left);
    restitution = rebound_speed / speed;
  }
}

}  // namespace scenes
