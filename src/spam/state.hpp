// The SPAM state integrated by RK4 (Hoover, Hoover & Merritt 2004, Sec. II): per particle the position,
// velocity, the stress components (sigma_xx, sigma_yy, sigma_xy), the density (an unknown only when it comes
// from the continuity equation; unused with summed densities) and the specific internal energy e.
#pragma once

#include <vector>

#include "core/lattices.hpp"
#include "core/rk4.hpp"

namespace sph {

struct SpamState {
  std::vector<Vec2> x, v;
  std::vector<double> sxx, syy, sxy, rho, e;

  explicit SpamState(std::size_t n = 0) { resize(n); }
  std::size_t size() const { return x.size(); }
  void resize(std::size_t n) {
    x.resize(n, Vec2::Zero()); v.resize(n, Vec2::Zero());
    sxx.resize(n, 0.0); syy.resize(n, 0.0); sxy.resize(n, 0.0); rho.resize(n, 0.0); e.resize(n, 0.0);
  }
  void resize_like(const SpamState& o) { resize(o.size()); }
  void set_axpy(const SpamState& a, double s, const SpamState& k) {
    vec_set_axpy(x, a.x, s, k.x); vec_set_axpy(v, a.v, s, k.v);
    vec_set_axpy(sxx, a.sxx, s, k.sxx); vec_set_axpy(syy, a.syy, s, k.syy); vec_set_axpy(sxy, a.sxy, s, k.sxy);
    vec_set_axpy(rho, a.rho, s, k.rho); vec_set_axpy(e, a.e, s, k.e);
  }
  void axpy(double s, const SpamState& k) {
    vec_axpy(x, s, k.x); vec_axpy(v, s, k.v);
    vec_axpy(sxx, s, k.sxx); vec_axpy(syy, s, k.syy); vec_axpy(sxy, s, k.sxy);
    vec_axpy(rho, s, k.rho); vec_axpy(e, s, k.e);
  }
};

}  // namespace sph
