// Whole-body diagnostics of any particle set, with one convention for the whole library:
//   kinetic_energy(p)     sum m |v|^2 / 2, lab frame
//   linear_momentum(p)    sum m v
//   angular_momentum(p)   sum m (x v_y - y v_x): about the ORIGIN, lab-frame velocities
// and, by name, the centre-of-mass forms for bodies whose centre moves (Hoover's rotating hexagon):
//   centre_of_mass_frame(p)  the centre, its velocity, the angular momentum about the centre with the
//                            velocities relative to its velocity, and the moment of inertia about it.
// A particle set p offers size(), mass(i), position(i) and velocity(i): every solver does (and
// ParticleArrays below wraps plain arrays). Each solver's own energies (elastic, internal, potential) live
// with its formulation.
// shape_fit: the best rigid rotation of a reference configuration onto a body and the rms distance left.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "core/types.hpp"

namespace sph {

template <class P>
double kinetic_energy(const P& p) {
  double e = 0;
  for (std::size_t a = 0; a < p.size(); ++a) e += 0.5 * p.mass(a) * p.velocity(a).squaredNorm();
  return e;
}

template <class P>
Vec2 linear_momentum(const P& p) {
  Vec2 s = Vec2::Zero();
  for (std::size_t a = 0; a < p.size(); ++a) s += p.mass(a) * p.velocity(a);
  return s;
}

template <class P>
double angular_momentum(const P& p) {
  double L = 0;
  for (std::size_t a = 0; a < p.size(); ++a) {
    const Vec2 x = p.position(a), v = p.velocity(a);
    L += p.mass(a) * (x.x() * v.y() - x.y() * v.x());
  }
  return L;
}

struct CentreOfMassFrame {
  Vec2 centre = Vec2::Zero();    ///< sum m x / sum m
  Vec2 velocity = Vec2::Zero();  ///< sum m v / sum m
  double angular_momentum = 0;   ///< sum m (r x u), r = x - centre, u = v - velocity
  double inertia = 0;            ///< sum m |r|^2
  double kinetic = 0;            ///< sum m |v|^2 / 2 (lab frame, as kinetic_energy)
};

template <class P>
CentreOfMassFrame centre_of_mass_frame(const P& p) {
  CentreOfMassFrame f;
  double M = 0;
  for (std::size_t a = 0; a < p.size(); ++a) {
    const double m = p.mass(a);
    const Vec2 v = p.velocity(a);
    M += m;
    f.centre += m * p.position(a);
    f.velocity += m * v;
    f.kinetic += 0.5 * m * v.squaredNorm();
  }
  f.centre /= M;
  f.velocity /= M;
  for (std::size_t a = 0; a < p.size(); ++a) {
    const Vec2 r = p.position(a) - f.centre, u = p.velocity(a) - f.velocity;
    f.angular_momentum += p.mass(a) * (r.x() * u.y() - r.y() * u.x());
    f.inertia += p.mass(a) * r.squaredNorm();
  }
  return f;
}

/// Plain arrays as a particle set (equal masses m).
struct ParticleArrays {
  const std::vector<Vec2>& x;
  const std::vector<Vec2>& v;
  double m = 1.0;
  std::size_t size() const { return x.size(); }
  double mass(std::size_t) const { return m; }
  const Vec2& position(std::size_t a) const { return x[a]; }
  const Vec2& velocity(std::size_t a) const { return v[a]; }
};

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
