// The SPAM state integrated by RK4 (Hoover, Hoover & Merritt 2004, Sec. II): per particle the position,
// velocity, the stress components (sigma_xx, sigma_yy, sigma_xy), the density (an unknown only when it comes
// from the continuity equation; unused with summed densities) and the specific internal energy e. A structure
// of arrays whose fields are listed once (core/fields.hpp); every field is an RK4 unknown.
#pragma once

#include <tuple>
#include <vector>

#include "core/fields.hpp"
#include "core/types.hpp"

namespace sph {

struct SpamState {
  std::vector<Vec2> x, v;
  std::vector<double> sxx, syy, sxy, rho, e;

  /// n particles, every field zero.
  explicit SpamState(std::size_t n = 0) { resize_fields(*this, n); }
  std::size_t size() const { return x.size(); }
  auto fields() { return std::tie(x, v, sxx, syy, sxy, rho, e); }
  auto fields() const { return std::tie(x, v, sxx, syy, sxy, rho, e); }
};

}  // namespace sph
