// The right-hand side of the scheme of Gray, Monaghan & Swift 2001 for a compile-time choice of terms
// (GrayTerms): the pair loop of Sections 2, 3 and 6,
//   pass 1 (if XSPH or summation density): XSPH velocity (3.6), summation density
//   per particle: sigma / rho^2 with sigma = S - P(rho) I (2.2), (2.7), and the artificial stress R (6.1)-(6.7)
//   pass 2: acceleration (3.1) with R_ab f^n (3.12) and Monaghan's viscosity, continuity (3.8), velocity
//           gradient (3.10) of the XSPH velocity and the Hooke stress rate (2.3)-(2.5)
// over the cached pair geometry of a PairList (x_a - x_b, W, F with grad_a W = dx F). A term that is off
// is not compiled into the loops. Included by gray_solver.cpp only.
#pragma once

#include <omp.h>

#include <algorithm>
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

/// Per-particle intermediates owned by the terms that need them, and the partial sums of each thread: every
/// pair is evaluated once, for both of its particles, so a thread adds into its own arrays and one pass
/// sums them (the order of the sums then depends on the number of threads, at round-off).
struct GrayScratch {
  std::vector<Tensor2> sigma_over_rho2, R;  ///< R only with the artificial stress
  std::vector<double> volume;               ///< m / rho
  struct Partial {
    std::vector<Vec2> dv_avg, acc;          ///< XSPH sum, acceleration sum
    std::vector<double> rho_sum, drho;      ///< summation density, continuity sum
    std::vector<Tensor2> grad_v;            ///< velocity gradient sum
  };
  std::vector<Partial> partial;             ///< one per thread
  void size_for(std::size_t n, int threads) {
    if (partial.size() < static_cast<std::size_t>(threads)) partial.resize(threads);
    for (auto& q : partial)
      if (q.acc.size() != n) {
        q.dv_avg.assign(n, Vec2::Zero()); q.acc.assign(n, Vec2::Zero());
        q.rho_sum.assign(n, 0.0); q.drho.assign(n, 0.0); q.grad_v.assign(n, Tensor2::Zero());
      }
  }
};

inline double ipow(double x, int n) {
  double r = 1.0;
  for (int i = 0; i < n; ++i) r *= x;
  return r;
}

/// The rates of the body's current state into `out`. With summation density it also sets body.rho.
/// h = h_over_dp dp, W_dp = W(dp, h) (the normalisation of f = W / W(dp)). `pairs` holds every pair once
/// (PairList::half): b > a in a's row.
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
  auto& volume = scratch.volume;
  scratch.size_for(n, omp_get_max_threads());
  auto& partial = scratch.partial;

  // Pass 1 (only if a term needs it): XSPH velocity (3.6) and summation density, from the densities
  // of the previous evaluation.
  int threads = 1;  // the team that filled the partial sums
  if constexpr (Terms::xsph || Terms::summation) {
#pragma omp parallel
    {
#pragma omp single
      threads = omp_get_num_threads();
      auto& q = partial[omp_get_thread_num()];
      if constexpr (Terms::xsph) std::fill(q.dv_avg.begin(), q.dv_avg.end(), Vec2::Zero());
      if constexpr (Terms::summation) std::fill(q.rho_sum.begin(), q.rho_sum.end(), 0.0);
#pragma omp for schedule(static)
      for (std::size_t a = 0; a < n; ++a)
        for (std::uint32_t k = pairs.first(a); k < pairs.last(a); ++k) {
          const std::uint32_t b = nb[k];
          if constexpr (Terms::xsph) {
            const Vec2 w = (v[b] - v[a]) * (Wab[k] / (0.5 * (rho[a] + rho[b])));
            q.dv_avg[a] += m[b] * w;
            q.dv_avg[b] -= m[a] * w;
          }
          if constexpr (Terms::summation) {
            q.rho_sum[a] += m[b] * Wab[k];
            q.rho_sum[b] += m[a] * Wab[k];
          }
        }
    }
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
      Vec2 dv_avg = partial[0].dv_avg[a];
      double rs = partial[0].rho_sum[a];
      for (int t = 1; t < threads; ++t) {
        if constexpr (Terms::xsph) dv_avg += partial[t].dv_avg[a];
        if constexpr (Terms::summation) rs += partial[t].rho_sum[a];
      }
      out.vhat[a] = Terms::xsph ? Vec2(v[a] + p.eps_xsph * dv_avg) : v[a];
      if constexpr (Terms::summation) rho[a] = rs + m[a] * kernel.W(0.0, h);
    }
  }
  const std::vector<Vec2>& vhat = Terms::xsph ? out.vhat : v;

  // Per-particle stress terms: sigma/rho^2, the artificial stress R (6.1)-(6.7), and m/rho.
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    const Tensor2 sigma = S[a] - linear_eos_pressure(rho[a], p.rho0, p.c0) * Tensor2::Identity();
    sigma_over_rho2[a] = sigma / (rho[a] * rho[a]);
    volume[a] = m[a] / rho[a];
    if constexpr (Terms::artificial_stress) R[a] = artificial_stress(sigma, rho[a], p.eps_artificial);
  }

  // Pass 2: acceleration (3.1)/(3.12), continuity (3.8), velocity gradient (3.10), each pair once: with
  // gW = grad_a W_ab = -grad_b W_ba and the symmetric M_ab, the pair adds m_b M gW to a and -m_a M gW to b,
  // m_b vab.gW and m_a vab.gW to the densities, and -V_b vab gW^T, -V_a vab gW^T to the gradients.
  const double eta2 = 0.01 * h * h, inv_Wdp = 1.0 / W_dp;
  const int nart = p.n_artificial;
#pragma omp parallel
  {
#pragma omp single
    threads = omp_get_num_threads();
    auto& q = partial[omp_get_thread_num()];
    std::fill(q.acc.begin(), q.acc.end(), Vec2::Zero());
    if constexpr (!Terms::summation) std::fill(q.drho.begin(), q.drho.end(), 0.0);
    std::fill(q.grad_v.begin(), q.grad_v.end(), Tensor2::Zero());
#pragma omp for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
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
        const Vec2 f = M * gW;
        q.acc[a] += m[b] * f;
        q.acc[b] -= m[a] * f;
        const Vec2 vab = vhat[a] - vhat[b];
        if constexpr (!Terms::summation) {
          const double d = vab.dot(gW);
          q.drho[a] += m[b] * d;
          q.drho[b] += m[a] * d;
        }
        const Tensor2 G = vab * gW.transpose();
        q.grad_v[a].noalias() -= volume[b] * G;
        q.grad_v[b].noalias() -= volume[a] * G;
      }
    }
  }
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    Vec2 acc = partial[0].acc[a];
    double drho = partial[0].drho[a];
    Tensor2 grad_v = partial[0].grad_v[a];  // grad_v(i, j) = d vhat_i / d x_j
    for (int t = 1; t < threads; ++t) {
      acc += partial[t].acc[a];
      if constexpr (!Terms::summation) drho += partial[t].drho[a];
      grad_v += partial[t].grad_v[a];
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
