// SPAM constitutive terms (Hoover, Hoover & Merritt 2004, Secs. II and IX):
//   velocity gradient   (grad v)_i = -sum_j (m v_ij / rho_ij) grad_i w_ij,  v_ij = v_i - v_j,
//                       rho_ij = (rho_i + rho_j)/2                                            (Sec. IX)
//   elastic stress rate sigma_dot = lambda (div v) I + eta (grad v + grad v^T)                (Sec. II)
//   rotation terms      sxx_dot -= 2 omega sxy, syy_dot += 2 omega sxy, sxy_dot += omega (sxx - syy),
//                       omega = (dv_y/dx - dv_x/dy)/2                                          (Sec. II)
//   viscous pressure    q_i = rho_i (c dx)^2 (div v)^2 when div v < 0 (von Neumann-Richtmyer; Sec. IX (ii))
// Sec. IX prints (grad v)_i = sum_j (v_ij/rho_ij) grad_i w_ij without m and without the minus sign; with
// grad_i w_ij = d F, F = w'/r < 0, only the minus sign makes a uniform expansion v = eps x give +eps
// (m = 1 in the paper). The rotation terms are the corotational (Jaumann) rate Omega sigma - sigma Omega.
#pragma once

#include "spam/work.hpp"
#include "spam/state.hpp"

namespace sph {

/// Stress rates into dy and the viscous pressure into wk.q. Needs wk.rho.
template <class P>
void spam_stress_rate(const SpamState& y, SpamWork& wk, SpamState& dy) {
  const long n = static_cast<long>(y.size());
  const double m = wk.params.mass, lambda = wk.params.lambda, eta = wk.params.eta;
  const double cdx = wk.params.viscosity_coefficient * wk.params.viscosity_length;
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (long i = 0; i < n; ++i) {
    double gxx = 0, gxy = 0, gyx = 0, gyy = 0;  // g_ab = dv_a/dx_b
    for (std::uint32_t k = wk.pairs.first(i); k < wk.pairs.last(i); ++k) {
      const std::size_t j = wk.pairs.b[k];
      const double s = -m * wk.pairs.F[k] / (0.5 * (wk.rho[i] + wk.rho[j]));
      const Vec2 vij = y.v[i] - y.v[j];
      gxx += s * vij.x() * wk.pairs.dx[k].x(); gxy += s * vij.x() * wk.pairs.dx[k].y();
      gyx += s * vij.y() * wk.pairs.dx[k].x(); gyy += s * vij.y() * wk.pairs.dx[k].y();
    }
    const double div = gxx + gyy, omega = 0.5 * (gyx - gxy);
    dy.sxx[i] = lambda * div + 2 * eta * gxx - 2 * omega * y.sxy[i];
    dy.syy[i] = lambda * div + 2 * eta * gyy + 2 * omega * y.sxy[i];
    dy.sxy[i] = eta * (gxy + gyx) + omega * (y.sxx[i] - y.syy[i]);
    if constexpr (P::viscosity) wk.q[i] = div < 0 ? wk.rho[i] * cdx * cdx * div * div : 0.0;
  }
}

}  // namespace sph
