// SPAM density and kinematics (Hoover, Hoover & Merritt 2004):
//   summed density            rho_i = m sum_j w_ij, self term included                          (Sec. II (i))
//   continuity                drho_i/dt = m sum_j (v_i - v_j) . grad_i w_ij                      (Sec. II (ii))
//   chain-rule continuity     drho_i/dt = m sum_j <v_i - v_j> . grad_i w_ij, <v> = dr/dt            (Sec. VI)
//   Shepard average           dr_i/dt = <v> = sum_j v_j w_ij / sum_j w_ij                          (Sec. IV)
//   Monaghan's average        dr_i/dt = v_i + sum_j m (v_j - v_i) w_ij / rho_ij,
//                             rho_ij = (rho_i + rho_j)/2 or sqrt(rho_i rho_j)                      (Sec. IV)
// The Shepard average is normalised by sum_j w_ij itself (CHOSEN): the paper's m/rho_i equals it only for
// summed densities, and with continuity densities m/rho_i would not reproduce a uniform velocity.
// The paper prints Monaghan's form without m; m = 1 there, and m makes it dimensionless.
#pragma once

#include <cmath>

#include "spam/work.hpp"
#include "spam/state.hpp"

namespace sph {

/// rho (summed or from the state) and, where needed, sum_j w_ij.
template <class P>
void spam_density(const SpamState& y, SpamWork& wk) {
  const long n = static_cast<long>(y.size());
  const double m = wk.params.mass;
  constexpr bool need_sum = P::density == SpamDensity::Summation || P::advection == SpamAdvection::Shepard;
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (long i = 0; i < n; ++i) {
    if constexpr (need_sum) {
      double s = wk.w0;
      for (std::uint32_t k = wk.pairs.first(i); k < wk.pairs.last(i); ++k) s += wk.pairs.W[k];
      wk.sumw[i] = s;
      if constexpr (P::density == SpamDensity::Summation) wk.rho[i] = m * s;
    }
    if constexpr (P::density == SpamDensity::Continuity) wk.rho[i] = y.rho[i];
  }
}

template <SpamAdvection A>
inline double pair_density(double ri, double rj) {
  if constexpr (A == SpamAdvection::MonaghanGeometric) return std::sqrt(ri * rj);
  else return 0.5 * (ri + rj);
}

/// The advection velocity dr/dt into wk.u (only for the averaged forms; plain SPAM uses v itself).
template <class P>
void spam_advection(const SpamState& y, SpamWork& wk) {
  if constexpr (P::averaged) {
    const long n = static_cast<long>(y.size());
    const double m = wk.params.mass;
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
    for (long i = 0; i < n; ++i) {
      if constexpr (P::advection == SpamAdvection::Shepard) {
        Vec2 s = wk.w0 * y.v[i];
        for (std::uint32_t k = wk.pairs.first(i); k < wk.pairs.last(i); ++k) s += wk.pairs.W[k] * y.v[wk.pairs.b[k]];
        wk.u[i] = s / wk.sumw[i];
      } else {
        Vec2 s = Vec2::Zero();
        for (std::uint32_t k = wk.pairs.first(i); k < wk.pairs.last(i); ++k) {
          const std::size_t j = wk.pairs.b[k];
          s += (wk.pairs.W[k] / pair_density<P::advection>(wk.rho[i], wk.rho[j])) * (y.v[j] - y.v[i]);
        }
        wk.u[i] = y.v[i] + m * s;
      }
    }
  }
}

/// dr/dt and, for continuity densities, drho/dt (with v, or with <v> for the chain-rule form).
template <class P>
void spam_kinematics_rates(const SpamState& y, SpamWork& wk, SpamState& dy) {
  const long n = static_cast<long>(y.size());
  const double m = wk.params.mass;
  const std::vector<Vec2>& c = P::chain_rule ? wk.u : y.v;
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (long i = 0; i < n; ++i) {
    if constexpr (P::averaged) dy.x[i] = wk.u[i];
    else dy.x[i] = y.v[i];
    if constexpr (P::density == SpamDensity::Continuity) {
      double s = 0;
      for (std::uint32_t k = wk.pairs.first(i); k < wk.pairs.last(i); ++k) s += (c[i] - c[wk.pairs.b[k]]).dot(wk.pairs.dx[k]) * wk.pairs.F[k];
      dy.rho[i] = m * s;
    } else {
      dy.rho[i] = 0.0;
    }
  }
}

}  // namespace sph
