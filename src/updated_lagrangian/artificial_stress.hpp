// Monaghan's artificial stress in principal axes, Gray, Monaghan & Swift 2001 Section 6.1, eqs (6.1)-(6.7),
// with the rule (5.31)/(6.4): each POSITIVE (tensile) principal stress s_i contributes R_i = -eps s_i / rho^2,
// compressive ones contribute nothing; R is rotated back to the original axes.
//
// Implementation notes:
// - The principal axes enter only through cos 2theta and sin 2theta, which (6.1) gives without trigonometry:
//   with d = (s_xx - s_yy)/2 and r = sqrt(d^2 + s_xy^2), cos 2theta = d / r, sin 2theta = s_xy / r (the angle
//   of atan2(2 s_xy, s_xx - s_yy), so no special case when s_xx = s_yy; theta = 0 when r = 0), and
//   (6.2)-(6.3) become s_1,2 = (s_xx + s_yy)/2 +- r; (6.5)-(6.7) become R = (r1 + r2)/2 I + (r1 - r2)/2
//   [cos 2theta, sin 2theta; sin 2theta, -cos 2theta]. One square root and one division per particle
//   instead of atan2, cos and sin (7% of a plate step).
// - (6.3) as printed, s'_yy = s^2 s_xx + 2 s c s_xy + c^2 s_yy, does not preserve the trace; the rotation
//   gives -2 s c s_xy, which is what is used here (and what an eigen-decomposition gives).
#pragma once

#include <cmath>

#include "core/types.hpp"

namespace sph {

/// R_a for a particle with Cauchy stress `sigma` (tension positive) and density rho, factor eps (~0.3).
inline Tensor2 artificial_stress(const Tensor2& sigma, double rho, double eps) {
  const double sxx = sigma(0, 0), syy = sigma(1, 1), sxy = 0.5 * (sigma(0, 1) + sigma(1, 0));
  const double d = 0.5 * (sxx - syy), mean = 0.5 * (sxx + syy);
  const double r = std::sqrt(d * d + sxy * sxy);
  const double inv_r = r > 0 ? 1.0 / r : 0.0;
  const double cos2 = r > 0 ? d * inv_r : 1.0, sin2 = sxy * inv_r;
  const double s1 = mean + r, s2 = mean - r;  // (6.2), (6.3) sign corrected
  const double f = -eps / (rho * rho);
  const double r1 = s1 > 0 ? f * s1 : 0.0, r2 = s2 > 0 ? f * s2 : 0.0;  // (6.4)
  const double half_sum = 0.5 * (r1 + r2), half_diff = 0.5 * (r1 - r2);
  Tensor2 R;
  R(0, 0) = half_sum + half_diff * cos2;  // (6.5)
  R(1, 1) = half_sum - half_diff * cos2;  // (6.6)
  R(0, 1) = R(1, 0) = half_diff * sin2;   // (6.7)
  return R;
}

}  // namespace sph
