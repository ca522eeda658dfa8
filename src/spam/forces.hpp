// SPAM motion and energy equations (Hoover, Hoover & Merritt 2004, Secs. II and IX):
//   dv_i/dt = m sum_j [(sigma/rho^2)_i + (sigma/rho^2)_j] . grad_i w_ij
//   de_i/dt = -(m/2) sum_j v_ij . [(sigma/rho^2)_i + (sigma/rho^2)_j] . grad_i w_ij
// (Sec. II writes the energy equation with P = -sigma and (v_j - v_i): the same thing), so that
// sum m (e + v^2/2) is conserved. With viscosity, sigma - q I replaces sigma in both. The pair term is
// written once as f_ij = m S_ij . grad_i w_ij with f_ji = -f_ij exactly (the same floating-point operations
// with d negated), which is what makes linear momentum conserved to round-off.
#pragma once

#include "spam/angular_momentum.hpp"
#include "spam/work.hpp"
#include "spam/state.hpp"

namespace sph {

template <class P>
void spam_forces(const SpamState& y, SpamWork& wk, SpamState& dy) {
  const long n = static_cast<long>(y.size());
  const double m = wk.params.mass;
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (long i = 0; i < n; ++i) {
    const double r2 = wk.rho[i] * wk.rho[i];
    double p = 0;
    if constexpr (P::viscosity) p = wk.q[i];
    wk.txx[i] = (y.sxx[i] - p) / r2; wk.tyy[i] = (y.syy[i] - p) / r2; wk.txy[i] = y.sxy[i] / r2;
  }
  auto pair_force = [&](long i, std::size_t k) {
    const std::size_t j = wk.pairs.b[k];
    const double sxx = wk.txx[i] + wk.txx[j], syy = wk.tyy[i] + wk.tyy[j], sxy = wk.txy[i] + wk.txy[j];
    const Vec2 g = wk.pairs.F[k] * wk.pairs.dx[k];
    return Vec2(m * (sxx * g.x() + sxy * g.y()), m * (sxy * g.x() + syy * g.y()));
  };
  if constexpr (P::torque_scaling) {
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
    for (long i = 0; i < n; ++i) {
      for (std::uint32_t k = wk.pairs.first(i); k < wk.pairs.last(i); ++k) {
        wk.f[k] = pair_force(i, k);
        wk.tau[k] = m * (wk.pairs.dx[k].x() * wk.f[k].y() - wk.pairs.dx[k].y() * wk.f[k].x());
      }
    }
    spam_scale_torques<P>(y.size(), wk);
  }
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (long i = 0; i < n; ++i) {
    Vec2 a = Vec2::Zero();
    double edot = 0;
    for (std::uint32_t k = wk.pairs.first(i); k < wk.pairs.last(i); ++k) {
      Vec2 f;
      if constexpr (P::torque_scaling) f = wk.f[k];
      else f = pair_force(i, k);
      a += f;
      edot -= 0.5 * (y.v[i] - y.v[wk.pairs.b[k]]).dot(f);
    }
    dy.v[i] = a;
    dy.e[i] = edot;
  }
  if constexpr (P::torque == SpamTorque::Gauss) spam_gauss<P>(y, wk, dy);
}

}  // namespace sph
