// Angular-momentum treatments of SPAM (Hoover, Hoover & Merritt 2004):
//   pair torque scaling (Sec. VIII)     Ldot_ij = m d_ij x f_ij, the torque of the pair force; positive ones are
//                                        scaled by 1/R, negative ones by R, R^2 = sum of positives / -sum of
//                                        negatives, so sum_ij Ldot_ij = 0 exactly.
//   particle torque scaling (Sec. VIII) Ldot_i = 1/2 sum_j Ldot_ij scaled the same way.
//   Gauss's principle (Sec. VII)        m dv/dt = F_SPAM + m (-alpha (v - v_c) + beta z x r),
//                                        beta = -Ldot_SPAM / D, alpha = beta L / (2K), D = m R^2 - L^2/(2K).
// How a scaled torque becomes a force (the paper does not say; CHOSEN): only the component of the pair force
// perpendicular to d_ij carries torque, so it is multiplied by the pair's factor s_ij (s_i for particle
// scaling becomes s_ij = (s_i + s_j)/2, which makes sum_ij s_ij Ldot_ij = sum_i s_i Ldot_i = 0). s_ij is
// symmetric, so the pair forces stay antisymmetric: linear momentum is still conserved exactly, and the
// energy equation uses the scaled forces, so total energy is conserved too.
// Gauss signs: derived from Edot = 0 and Ldot = 0 with the printed constraint force F_x = -alpha v_x - beta y,
// F_y = -alpha v_y + beta x; the printed alpha = -beta L/2K, beta = Ldot/D are the same up to the sign of
// beta. D >= 0 by Cauchy-Schwarz (L^2 <= 2 K m R^2), zero for rigid rotation: the multipliers are switched
// off while D < gauss_floor * m R^2 (counted in gauss_floor_hits).
#pragma once

#include <cmath>

#include "spam/work.hpp"
#include "spam/state.hpp"

namespace sph {

inline double torque_ratio(double positive, double negative) {
  return positive > 0 && negative > 0 ? std::sqrt(positive / negative) : 1.0;
}
inline double torque_factor(double torque, double R) { return torque > 0 ? 1.0 / R : (torque < 0 ? R : 1.0); }

/// Rescales the tangential part of the stored pair forces wk.f so that the torques sum to zero.
template <class P>
void spam_scale_torques(std::size_t n_particles, SpamWork& wk) {
  const long n = static_cast<long>(n_particles);
  double pos = 0, neg = 0;
  if constexpr (P::torque == SpamTorque::PairScaling) {
#pragma omp parallel for schedule(static) if (n >= kParallelMin) reduction(+ : pos, neg)
    for (long i = 0; i < n; ++i) {
      for (std::uint32_t k = wk.pairs.first(i); k < wk.pairs.last(i); ++k) (wk.tau[k] > 0 ? pos : neg) += std::abs(wk.tau[k]);
    }
  } else {
#pragma omp parallel for schedule(static) if (n >= kParallelMin) reduction(+ : pos, neg)
    for (long i = 0; i < n; ++i) {
      double s = 0;
      for (std::uint32_t k = wk.pairs.first(i); k < wk.pairs.last(i); ++k) s += wk.tau[k];
      wk.ldot[i] = 0.5 * s;
      (wk.ldot[i] > 0 ? pos : neg) += std::abs(wk.ldot[i]);
    }
  }
  const double R = torque_ratio(pos, neg);
  wk.torque_ratio = R; wk.torque_positive = pos; wk.torque_negative = neg;
  if constexpr (P::torque == SpamTorque::ParticleScaling)
    for (long i = 0; i < n; ++i) wk.scale[i] = torque_factor(wk.ldot[i], R);
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
  for (long i = 0; i < n; ++i) {
    for (std::uint32_t k = wk.pairs.first(i); k < wk.pairs.last(i); ++k) {
      double s;
      if constexpr (P::torque == SpamTorque::PairScaling) s = torque_factor(wk.tau[k], R);
      else s = 0.5 * (wk.scale[i] + wk.scale[wk.pairs.b[k]]);
      const Vec2& d = wk.pairs.dx[k];
      const Vec2 radial = (wk.f[k].dot(d) / d.squaredNorm()) * d;
      wk.f[k] = radial + s * (wk.f[k] - radial);
    }
  }
}

/// Adds Gauss's constraint accelerations to dy.v (which holds the SPAM accelerations).
template <class P>
void spam_gauss(const SpamState& y, SpamWork& wk, SpamState& dy) {
  const std::size_t n = y.size();
  const double m = wk.params.mass;
  Vec2 c = Vec2::Zero(), vc = Vec2::Zero();
  for (std::size_t i = 0; i < n; ++i) { c += y.x[i]; vc += y.v[i]; }
  c /= static_cast<double>(n); vc /= static_cast<double>(n);
  double L = 0, K = 0, R2 = 0, Ldot = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 r = y.x[i] - c, u = y.v[i] - vc;
    L += m * (r.x() * u.y() - r.y() * u.x());
    K += 0.5 * m * u.squaredNorm();
    R2 += r.squaredNorm();
    Ldot += m * (r.x() * dy.v[i].y() - r.y() * dy.v[i].x());
  }
  const double D = m * R2 - (K > 0 ? L * L / (2 * K) : 0.0);
  double alpha = 0, beta = 0;
  if (K > 0 && D > wk.params.gauss_floor * m * R2) {
    beta = -Ldot / D;
    alpha = beta * L / (2 * K);
  } else {
    ++wk.gauss_floor_hits;
  }
  wk.gauss_alpha = alpha; wk.gauss_beta = beta; wk.gauss_denominator = D; wk.gauss_inertia = m * R2;
  wk.spam_torque = Ldot;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 r = y.x[i] - c;
    dy.v[i] += -alpha * (y.v[i] - vc) + beta * Vec2(-r.y(), r.x());
  }
}

}  // namespace sph
