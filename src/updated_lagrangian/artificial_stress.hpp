// Monaghan's artificial stress in principal axes, Gray, Monaghan & Swift 2001 Section 6.1, eqs (6.1)-(6.7),
// with the rule (5.31)/(6.4): each POSITIVE (tensile) principal stress s_i contributes R_i = -eps s_i / rho^2,
// compressive ones contribute nothing; R is rotated back to the original axes.
//
// Implementation notes:
// - theta = atan2(2 s_xy, s_xx - s_yy) / 2 replaces tan(2 theta) = 2 s_xy / (s_xx - s_yy) (6.1): atan2 needs
//   no special case when s_xx = s_yy, so the Delta-sigma regularisation of (6.10) is unnecessary.
// - (6.3) as printed, s'_yy = s^2 s_xx + 2 s c s_xy + c^2 s_yy, does not preserve the trace; the rotation
//   gives -2 s c s_xy, which is what is used here (and what an eigen-decomposition gives).
#pragma once

#include <cmath>

#include "core/types.hpp"

namespace sph {

/// R_a for a particle with Cauchy stress `sigma` (tension positive) and density rho, factor eps (~0.3).
inline Tensor2 artificial_stress(const Tensor2& sigma, double rho, double eps) {
  const double sxx = sigma(0, 0), syy = sigma(1, 1), sxy = 0.5 * (sigma(0, 1) + sigma(1, 0));
  const double theta = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  const double c = std::cos(theta), s = std::sin(theta);
  const double s1 = c * c * sxx + 2.0 * s * c * sxy + s * s * syy;  // (6.2)
  const double s2 = s * s * sxx - 2.0 * s * c * sxy + c * c * syy;  // (6.3), sign corrected
  const double f = -eps / (rho * rho);
  const double r1 = s1 > 0 ? f * s1 : 0.0, r2 = s2 > 0 ? f * s2 : 0.0;  // (6.4)
  Tensor2 R;
  R(0, 0) = c * c * r1 + s * s * r2;  // (6.5)
  R(1, 1) = s * s * r1 + c * c * r2;  // (6.6)
  R(0, 1) = R(1, 0) = s * c * (r1 - r2);  // (6.7)
  return R;
}

}  // namespace sph
