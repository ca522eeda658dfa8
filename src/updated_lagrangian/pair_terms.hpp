// The right-hand side of the scheme of Gray, Monaghan & Swift 2001 for a compile-time choice of terms
// (GrayTerms): the pair loop of Sections 2, 3 and 6,
//   pass 1 (if XSPH or summation density): XSPH velocity (3.6), summation density
//   per particle: sigma / rho^2 with sigma = S - P(rho) I (2.2), (2.7), and the artificial stress R (6.1)-(6.7)
//   pass 2: acceleration (3.1) with R_ab f^n (3.12) and Monaghan's viscosity, continuity (3.8), velocity
//           gradient (3.10) of the XSPH velocity and the Hooke stress rate (2.3)-(2.5)
// over the cached pair geometry of a PairList (x_a - x_b, W, F with grad_a W = dx F). A term that is off
// is not compiled into the loops. Included by gray_solver.cpp only.
#pragma once

#include <cstdint>
#include <type_traits>
#include <vector>

#include "core/kernels.hpp"
#include "core/materials.hpp"
#include "core/pair_list.hpp"
#include "updated_lagrangian/artificial_stress.hpp"
#include "updated_lagrangian/elastic_body.hpp"
#include "updated_lagrangian/parameters.hpp"

namespace sph {

/// The rates of one evaluation: dx moves the particles (the XSPH velocity of a Free particle, the velocity
/// of a Driven one, zero for a Fixed one), dv accelerates them, vhat is the XSPH velocity of every particle.
struct GrayRates {
  std::vector<Vec2> dx, dv, vhat;
  std::vector<double> drho;
  std::vector<Tensor2> dS;
  auto fields() { return std::tie(dx, dv, vhat, drho, dS); }
  auto fields() const { return std::tie(dx, dv, vhat, drho, dS); }
  auto first_order() const { return std::tie(drho, dS); }
};

/// Compile-time selection of the terms of the pair loop.
template <bool ArtificialStress, bool Xsph, bool Viscosity, bool Summation>
struct GrayTerms {
  static constexpr bool artificial_stress = ArtificialStress;
  static constexpr bool xsph = Xsph;
  static constexpr bool viscosity = Viscosity;
  static constexpr bool summation = Summation;
};

/// The one place where the run-time options become a compile-time instance of the pair loop: calls
/// f(GrayTerms<...>{}) for the terms `o` switches on.
template <class F>
auto select_terms(const GrayOptions& o, F&& f) {
  auto with_sum = [&](auto as, auto xs, auto av) {
    return o.summation_density ? f(GrayTerms<decltype(as)::value, decltype(xs)::value, decltype(av)::value, true>{})
                               : f(GrayTerms<decltype(as)::value, decltype(xs)::value, decltype(av)::value, false>{});
  };
  auto with_av = [&](auto as, auto xs) {
    return o.viscosity ? with_sum(as, xs, std::true_type{}) : with_sum(as, xs, std::false_type{});
  };
  auto with_xs = [&](auto as) { return o.xsph ? with_av(as, std::true_type{}) : with_av(as, std::false_type{}); };
  return o.artificial_stress ? with_xs(std::true_type{}) : with_xs(std::false_type{});
}

/// Per-particle intermediates owned by the terms that need them.
struct GrayScratch {
  std::vector<Tensor2> sigma_over_rho2, R;  ///< R only with the artificial stress
  std::vector<double> volume;               ///< m / rho
  std::vector<double> rho_sum;              ///< only with summation density
};

inline double ipow(double x, int n) {
  double r = 1.0;
  for (int i = 0; i < n; ++i) r *= x;
  return r;
}

/// The rates of the body's current state into `out`. With summation density it also sets body.rho.
/// h = h_over_dp dp, W_dp = W(dp, h) (the normalisation of f = W / W(dp)).
template <class Terms>
void evaluate_gray_rates(ElasticBody& body, const GrayParameters& p, const CubicSpline& kernel, double h, double W_dp,
                         const PairList& pairs, GrayScratch& scratch, GrayRates& out) {
  const std::size_t n = body.size();
  const auto& v = body.v;
  const auto& m = body.m;
  auto& rho = body.rho;
  const auto& S = body.S;
  const auto& nb = pairs.b;
  const auto& dx = pairs.dx;
  const auto& Wab = pairs.W;
  const auto& Fab = pairs.F;
  auto& sigma_over_rho2 = scratch.sigma_over_rho2;
  auto& R = scratch.R;

  // Pass 1 (only if a term needs it): XSPH velocity (3.6) and summation density, from the densities
  // of the previous evaluation.
  if constexpr (Terms::xsph || Terms::summation) {
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
      Vec2 dv_avg = Vec2::Zero();
      double rs = 0.0;
      for (std::uint32_t k = pairs.first(a); k < pairs.last(a); ++k) {
        const std::uint32_t b = nb[k];
        if constexpr (Terms::xsph) dv_avg += m[b] / (0.5 * (rho[a] + rho[b])) * (v[b] - v[a]) * Wab[k];
        if constexpr (Terms::summation) rs += m[b] * Wab[k];
      }
      out.vhat[a] = Terms::xsph ? Vec2(v[a] + p.eps_xsph * dv_avg) : v[a];
      if constexpr (Terms::summation) scratch.rho_sum[a] = rs + m[a] * kernel.W(0.0, h);
    }
    if constexpr (Terms::summation) rho = scratch.rho_sum;
  }
  const std::vector<Vec2>& vhat = Terms::xsph ? out.vhat : v;

  // Per-particle stress terms: sigma/rho^2, the artificial stress R (6.1)-(6.7), and m/rho (the volume of the
  // velocity gradient's sum, divided once per particle instead of once per pair: the same quotient).
  auto& volume = scratch.volume;
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    const Tensor2 sigma = S[a] - linear_eos_pressure(rho[a], p.rho0, p.c0) * Tensor2::Identity();
    sigma_over_rho2[a] = sigma / (rho[a] * rho[a]);
    volume[a] = m[a] / rho[a];
    if constexpr (Terms::artificial_stress) R[a] = artificial_stress(sigma, rho[a], p.eps_artificial);
  }

  // Pass 2: acceleration (3.1)/(3.12), continuity (3.8), velocity gradient (3.10), stress rate (2.3).
  const double eta2 = 0.01 * h * h, inv_Wdp = 1.0 / W_dp;
  const int nart = p.n_artificial;
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    Vec2 acc = Vec2::Zero();
    double drho = 0.0;
    Tensor2 grad_v = Tensor2::Zero();  // grad_v(i, j) = d vhat_i / d x_j
    const Tensor2 Aa = sigma_over_rho2[a];
    for (std::uint32_t k = pairs.first(a); k < pairs.last(a); ++k) {
      const std::uint32_t b = nb[k];
      const Vec2 gW = dx[k] * Fab[k];  // grad_a W_ab (3.2)
      Tensor2 M = Aa + sigma_over_rho2[b];
      if constexpr (Terms::artificial_stress) M += (R[a] + R[b]) * ipow(Wab[k] * inv_Wdp, nart);
      if constexpr (Terms::viscosity) {
        const double vr = (v[a] - v[b]).dot(dx[k]);
        if (vr < 0.0) {
          // Monaghan's Pi_ab >= 0 acts as a pressure, so it enters the stress sum with a minus sign.
          const double mu_ab = h * vr / (dx[k].squaredNorm() + eta2);
          const double Pi = (-p.alpha * p.c0 * mu_ab + p.beta * mu_ab * mu_ab) / (0.5 * (rho[a] + rho[b]));
          M.diagonal().array() -= Pi;
        }
      }
      acc += m[b] * (M * gW);
      const Vec2 vab = vhat[a] - vhat[b];
      if constexpr (!Terms::summation) drho += m[b] * vab.dot(gW);
      grad_v.noalias() -= volume[b] * vab * gW.transpose();
    }
    const Motion kind = body.motion[a];
    out.dv[a] = kind == Motion::Free ? acc : kind == Motion::Driven ? body.drive[a] : Vec2::Zero();
    out.dx[a] = kind == Motion::Free ? vhat[a] : kind == Motion::Driven ? v[a] : Vec2::Zero();
    out.drho[a] = Terms::summation ? 0.0 : drho;
    out.dS[a] = hooke_deviatoric_rate(p.mu, grad_v, S[a]);
    if constexpr (!Terms::xsph) out.vhat[a] = v[a];
  }
}

}  // namespace sph
