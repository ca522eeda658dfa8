// Whole-body diagnostics of a particle system with equal masses m, shared by SPAM and the molecular
// dynamics reference (Hoover, Hoover & Merritt 2004, Sec. I): centre of mass, linear and angular momentum
// L = sum m (x v_y - y v_x) about the centre of mass, kinetic energy, moment of inertia, and the shape
// error of a body against a reference configuration after removing the best rigid rotation.
#pragma once

#include <cmath>
#include <vector>

#include "core/lattices.hpp"

namespace sph {

struct BodyMoments {
  Vec2 centre = Vec2::Zero();     // centre of mass
  Vec2 momentum = Vec2::Zero();   // sum m v
  double angular_momentum = 0;    // about the centre of mass, velocities relative to its velocity
  double kinetic = 0;             // sum m v^2 / 2 (lab frame)
  double inertia = 0;             // sum m |r - centre|^2
};

inline BodyMoments body_moments(const std::vector<Vec2>& x, const std::vector<Vec2>& v, double m) {
  BodyMoments b;
  const double n = static_cast<double>(x.size());
  Vec2 vc = Vec2::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) { b.centre += x[i]; vc += v[i]; b.kinetic += 0.5 * m * v[i].squaredNorm(); }
  b.centre /= n;
  b.momentum = m * vc;
  vc /= n;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec2 r = x[i] - b.centre, u = v[i] - vc;
    b.angular_momentum += m * (r.x() * u.y() - r.y() * u.x());
    b.inertia += m * r.squaredNorm();
  }
  return b;
}

/// Best rigid rotation angle theta of `ref` (about its centroid) onto `x` (about its centroid), and the rms
/// distance left: the shape error, blind to how far the body has turned. 2D Procrustes:
/// theta = atan2(sum r0 x r, sum r0 . r).
struct ShapeFit { double angle = 0, rms = 0; };
inline ShapeFit shape_fit(const std::vector<Vec2>& ref, const std::vector<Vec2>& x) {
  Vec2 c0 = Vec2::Zero(), c = Vec2::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) { c0 += ref[i]; c += x[i]; }
  c0 /= static_cast<double>(x.size());
  c /= static_cast<double>(x.size());
  double sdot = 0, scross = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec2 a = ref[i] - c0, b = x[i] - c;
    sdot += a.dot(b);
    scross += a.x() * b.y() - a.y() * b.x();
  }
  ShapeFit f;
  f.angle = std::atan2(scross, sdot);
  const double cs = std::cos(f.angle), sn = std::sin(f.angle);
  double s2 = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec2 a = ref[i] - c0, b = x[i] - c;
    const Vec2 ra(cs * a.x() - sn * a.y(), sn * a.x() + cs * a.y());
    s2 += (b - ra).squaredNorm();
  }
  f.rms = std::sqrt(s2 / static_cast<double>(x.size()));
  return f;
}

}  // namespace sph
