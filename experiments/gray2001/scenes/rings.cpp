#include "gray2001/scenes/rings.hpp"

#include <cmath>
#include <stdexcept>

#include "core/lattices.hpp"

namespace scenes {

void check_size(const RingsSpec& s) {
  sph::check_particle_count(2.0 * std::pow(2.0 * s.r_outer / s.dp, 2), s.dp, "rings");  // the squares scanned
}

Rings make_rings(const RingsSpec& s, double rho0) {
  if (!(s.dp > 0) || !(s.r_outer > s.r_inner) || s.r_inner < 0 || s.gap < 0)
    throw std::invalid_argument("rings: need dp > 0, 0 <= r_inner < r_outer, gap >= 0");
  Rings r;
  const double m = rho0 * s.dp * s.dp;
  check_size(s);
  const int n = static_cast<int>(std::ceil(2.0 * s.r_outer / s.dp - 1e-9));
  const double ri2 = s.r_inner * s.r_inner, ro2 = s.r_outer * s.r_outer;
  const double offset = s.r_outer + 0.5 * s.gap;
  for (int side : {-1, 1}) {
    if (side > 0) r.first_right = r.body.size();
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double x = -s.r_outer + i * s.dp, y = -s.r_outer + j * s.dp;
        const double d2 = x * x + y * y;
        if (d2 < ri2 || d2 >= ro2) continue;
        r.body.add({x + side * offset, y}, {-side * s.speed, 0.0}, m, rho0);
      }
  }
  const double half = offset + s.r_outer;
  r.body.dp = s.dp;
  r.body.box = {-2.0 * half, -2.0 * half, 2.0 * half, 2.0 * half, false, false};
  return r;
}

}  // namespace scenes
