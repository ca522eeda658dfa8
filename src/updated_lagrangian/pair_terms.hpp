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
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "core/kernels.hpp"
#include "core/materials.hpp"
#include "core/pair_list.hpp"
#include "core/parallel.hpp"
#include "updated_lagrangian/artificial_stress.hpp"
#include "updated_lagrangian/elastic_body.hpp"
#include "updated_lagrangian/pair_terms_wide.hpp"
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
/// sums them (the order of the sums then depends on the number of threads, at round-off). A thread's rows
/// are a..a' (the static partition of OpenMP) and its pairs reach only particles b > a, up to some b_max: it
/// zeroes and fills only [a, b_max], and the sum over threads skips those whose range misses a particle
/// (a zero it would add changes no bit), so the zeroing and the sum do not grow with the thread count.
struct GrayScratch {
  std::vector<Tensor2> sigma_over_rho2, R;  ///< R only with the artificial stress
  std::vector<double> volume;               ///< m / rho
  std::vector<ParticleRecord> records;      ///< the eight-wide pass 2's copy of what it reads per particle
  struct Partial {
    std::vector<Vec2> dv_avg;               ///< XSPH sum
    std::vector<double> rho_sum;            ///< summation density
    std::vector<PairSums> sums;             ///< pass 2: acceleration, continuity and velocity gradient sums
    std::size_t lo = 0, hi = 0;             ///< the particles this thread's pairs touch: [lo, hi)
  };
  std::vector<Partial> partial;             ///< one per thread
  void size_for(std::size_t n, int threads) {
    if (partial.size() < static_cast<std::size_t>(threads)) partial.resize(threads);
    for (auto& q : partial)
      if (q.sums.size() != n) {
        q.dv_avg.assign(n, Vec2::Zero());
        q.rho_sum.assign(n, 0.0);
        q.sums.assign(n, PairSums{});
      }
  }
};

inline double ipow(double x, int n) {
  double r = 1.0;
  for (int i = 0; i < n; ++i) r *= x;
  return r;
}

/// f^n of the artificial stress (3.12), f = W / W(dp): the paper's n = 4 by three multiplications (ipow's
/// order: the same bits) instead of ipow's loop, whose branch the compiler can take out of a pair loop.
inline double artificial_stress_fn(double f, int n) { return n == 4 ? ((f * f) * f) * f : ipow(f, n); }

/// The pair's term of the XSPH sum (3.6), (v_b - v_a) W_ab / rho_ab with rho_ab = (rho_a + rho_b) / 2: a gains
/// m_b times it, b loses m_a times it, and vhat = v + eps_xsph sum.
inline Vec2 xsph_pair_term(const Vec2& va, const Vec2& vb, double W, double rho_a, double rho_b) {
  return (vb - va) * (W / (0.5 * (rho_a + rho_b)));
}

/// Monaghan's viscosity Pi_ab >= 0 of an approaching pair (vr = v_ab . x_ab < 0; r2 = |x_ab|^2, eta2 = 0.01 h^2).
inline double monaghan_pi(double vr, double r2, double h, double eta2, double alpha, double beta, double c0,
                          double rho_a, double rho_b) {
  const double mu_ab = h * vr / (r2 + eta2);
  return (-alpha * c0 * mu_ab + beta * mu_ab * mu_ab) / (0.5 * (rho_a + rho_b));
}

/// The rates of the body's current state into `out`. With summation density it also sets body.rho.
/// h = h_over_dp dp, W_dp = W(dp, h) (the normalisation of f = W / W(dp)). `pairs` holds every pair once
/// (PairList::half): b > a in a's row. One parallel region: pass 1, the per-particle terms, pass 2 and the
/// sums of the threads' partials, separated by barriers.
template <class Terms, bool Wide = SPH_WIDE_PASS2 != 0>
void evaluate_gray_rates(ElasticBody& body, const GrayParameters& p, const CubicSpline& kernel, double h, double W_dp,
                         const PairList& pairs, GrayScratch& scratch, GrayRates& out) {
  static_assert(!Wide || SPH_WIDE_PASS2, "the eight-wide pass 2 needs AVX-512 (F and VL)");
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
  if (Wide && scratch.records.size() != n) scratch.records.assign(n, ParticleRecord{});
  auto& partial = scratch.partial;
  const std::vector<Vec2>& vhat = Terms::xsph ? out.vhat : v;
  const double W0 = kernel.W(0.0, h);
  const double eta2 = 0.01 * h * h, inv_Wdp = 1.0 / W_dp;
  const int nart = p.n_artificial;
  constexpr bool pass1 = Terms::xsph || Terms::summation;

#pragma omp parallel
  {
    const int T = omp_get_num_threads(), t = omp_get_thread_num();
    auto& q = partial[t];
    std::size_t a_begin, a_end;
    static_rows(n, t, T, a_begin, a_end);
    // The particles this thread's pairs touch: its rows and the b > a they reach (a loop over the pairs
    // here was 3% of a rings run).
    std::size_t hi = a_end;
    for (std::size_t a = a_begin; a < a_end; ++a) hi = std::max<std::size_t>(hi, pairs.reach[a]);
    q.lo = a_begin;
    q.hi = hi;
    // The sum over the threads whose range holds particle a, in thread order (its own row's thread among them).
    auto sum_threads = [&](std::size_t a, auto member) {
      int u = 0;
      while (a < partial[u].lo || a >= partial[u].hi) ++u;
      auto s = (partial[u].*member)[a];
      for (++u; u < T; ++u)
        if (a >= partial[u].lo && a < partial[u].hi) s += (partial[u].*member)[a];
      return s;
    };

    // The loops read the arrays through restrict pointers in registers: through the vectors, every store
    // into a partial sum could alias the vectors' own data pointers and the parameters, which the compiler
    // then reloads for every pair (perf annotate; removing it: 1.2x on the plate).
    const std::uint32_t* __restrict nb_ = nb.data();
    const Vec2* __restrict dx_ = dx.data();
    const double* __restrict W_ = Wab.data();
    const double* __restrict F_ = Fab.data();
    const std::uint32_t* __restrict row_ = pairs.start.data();
    const std::uint32_t* __restrict active_ = pairs.active.data();
    const Vec2* __restrict v_ = v.data();
    const double* __restrict m_ = m.data();

    // Pass 1 (only if a term needs it): XSPH velocity (3.6) and summation density, from the densities
    // of the previous evaluation.
    if constexpr (pass1) {
      if constexpr (Terms::xsph) std::fill(q.dv_avg.begin() + q.lo, q.dv_avg.begin() + q.hi, Vec2::Zero());
      if constexpr (Terms::summation) std::fill(q.rho_sum.begin() + q.lo, q.rho_sum.begin() + q.hi, 0.0);
      const double* __restrict rho_ = rho.data();
      Vec2* __restrict dv_avg = q.dv_avg.data();
      double* __restrict rho_sum = q.rho_sum.data();
      // Row a's own sums are carried in registers (see pass 2).
      for (std::size_t a = a_begin; a < a_end; ++a) {
        Vec2 dv_avg_a = dv_avg[a];
        double rho_sum_a = rho_sum[a];
        for (std::uint32_t k = row_[a], end = row_[a] + active_[a]; k < end; ++k) {
          const std::uint32_t b = nb_[k];
          if constexpr (Terms::xsph) {
            const Vec2 w = xsph_pair_term(v_[a], v_[b], W_[k], rho_[a], rho_[b]);
            dv_avg_a += m_[b] * w;
            dv_avg[b] -= m_[a] * w;
          }
          if constexpr (Terms::summation) {
            rho_sum_a += m_[b] * W_[k];
            rho_sum[b] += m_[a] * W_[k];
          }
        }
        if constexpr (Terms::xsph) dv_avg[a] = dv_avg_a;
        if constexpr (Terms::summation) rho_sum[a] = rho_sum_a;
      }
#pragma omp barrier
    }

    // Per particle: the XSPH velocity and summation density of pass 1, then sigma/rho^2, the artificial
    // stress R (6.1)-(6.7) and m/rho.
#pragma omp for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
      if constexpr (pass1) {
        if constexpr (Terms::xsph) out.vhat[a] = v[a] + p.eps_xsph * sum_threads(a, &GrayScratch::Partial::dv_avg);
        if constexpr (Terms::summation) rho[a] = sum_threads(a, &GrayScratch::Partial::rho_sum) + m[a] * W0;
      }
      const Tensor2 sigma = S[a] - linear_eos_pressure(rho[a], p.rho0, p.c0) * Tensor2::Identity();
      const Tensor2 A = sigma / (rho[a] * rho[a]);
      const double V = m[a] / rho[a];
      const Tensor2 Ra = Terms::artificial_stress ? artificial_stress(sigma, rho[a], p.eps_artificial) : Tensor2::Zero();
      if constexpr (Wide) {  // pass 2 reads the neighbours' records (pair_terms_wide.hpp)
        double* r = scratch.records[a].s;
        for (int c = 0; c < 4; ++c) {
          r[ParticleRecord::kA + c] = A.data()[c];
          r[ParticleRecord::kR + c] = Ra.data()[c];
        }
        const Vec2 u = Terms::xsph ? out.vhat[a] : v[a];
        r[ParticleRecord::kV] = v[a].x();
        r[ParticleRecord::kV + 1] = v[a].y();
        r[ParticleRecord::kVhat] = u.x();
        r[ParticleRecord::kVhat + 1] = u.y();
        r[ParticleRecord::kRho] = rho[a];
        r[ParticleRecord::kMass] = m[a];
        r[ParticleRecord::kVolume] = V;
        r[15] = 0.0;
      } else {
        sigma_over_rho2[a] = A;
        volume[a] = V;
        if constexpr (Terms::artificial_stress) R[a] = Ra;
      }
    }

    // Pass 2: acceleration (3.1)/(3.12), continuity (3.8), velocity gradient (3.10), each pair once: with
    // gW = grad_a W_ab = -grad_b W_ba and the symmetric M_ab, the pair adds m_b M gW to a and -m_a M gW to b,
    // m_b vab.gW and m_a vab.gW to the densities, and -V_b vab gW^T, -V_a vab gW^T to the gradients, into
    // the thread's PairSums records.
    std::fill(q.sums.begin() + q.lo, q.sums.begin() + q.hi, PairSums{});
    {
      PairSums* __restrict sums = q.sums.data();
      if constexpr (Wide) {
#if SPH_WIDE_PASS2
        const Pass2Inputs in{nb_, dx_->data(), W_, F_, scratch.records.data(), h, eta2, p.alpha, p.beta, p.c0, inv_Wdp, nart};
        for (std::size_t a = a_begin; a < a_end; ++a) wide::pass2_row<Terms>(a, row_[a], row_[a] + active_[a], in, sums);
#endif
      } else {
        const double* __restrict rho_ = rho.data();
        const Vec2* __restrict vhat_ = vhat.data();
        const Tensor2* __restrict A_ = sigma_over_rho2.data();
        const Tensor2* __restrict R_ = R.data();
        const double* __restrict volume_ = volume.data();
        const double alpha = p.alpha, beta = p.beta, c0 = p.c0;
        for (std::size_t a = a_begin; a < a_end; ++a) {
          const Tensor2 Aa = A_[a];
          // Row a's own sums in registers: its pairs reach only b > a, so nothing else writes a's entries
          // during the row, and loading them first and storing them after adds the same terms in the same
          // order (bit-identical). Through memory, every pair's store to b could alias a's entries, so the
          // compiler reloaded and stored a's sums for every pair.
          double sa[7];
          for (int c = 0; c < 7; ++c) sa[c] = sums[a].s[c];
          const double ma = m_[a], Va = volume_[a];
          for (std::uint32_t k = row_[a], end = row_[a] + active_[a]; k < end; ++k) {
            const std::uint32_t b = nb_[k];
            const Vec2 gW = dx_[k] * F_[k];  // grad_a W_ab (3.2)
            // M = A_a + A_b (+ (R_a + R_b) f^n) by components (column-major 0: (0,0), 1: (1,0), 2: (0,1), 3: (1,1)):
            // as an Eigen matrix, M went through the stack and was read back in wider pieces than written, a
            // store-forwarding stall; the operations (and their fused multiply-adds) are Eigen's.
            const double* Ab = A_[b].data();
            double M[4] = {Aa(0, 0) + Ab[0], Aa(1, 0) + Ab[1], Aa(0, 1) + Ab[2], Aa(1, 1) + Ab[3]};
            if constexpr (Terms::artificial_stress) {
              const double fn = artificial_stress_fn(W_[k] * inv_Wdp, nart);
              const double *Ra = R_[a].data(), *Rb = R_[b].data();
              for (int c = 0; c < 4; ++c) M[c] = std::fma(Ra[c] + Rb[c], fn, M[c]);
            }
            if constexpr (Terms::viscosity) {
              // Monaghan's Pi_ab >= 0 acts as a pressure, so it enters the stress sum with a minus sign. (A
              // branch-free form, Pi computed for every pair and selected, measured 8% slower on the plate: the
              // two divisions then run for every pair.)
              const double vr = (v_[a] - v_[b]).dot(dx_[k]);
              if (vr < 0.0) {
                const double Pi = monaghan_pi(vr, dx_[k].squaredNorm(), h, eta2, alpha, beta, c0, rho_[a], rho_[b]);
                M[0] -= Pi;
                M[3] -= Pi;
              }
            }
            const Vec2 vab = vhat_[a] - vhat_[b];
            // The pair's terms in PairSums' order: M gW, vab.gW, G = vab gW^T by components (as Eigen
            // temporaries they went through the stack, store-forwarding stalls that took a fifth of pass 2).
            const double t[7] = {std::fma(M[2], gW.y(), M[0] * gW.x()), std::fma(M[3], gW.y(), M[1] * gW.x()),
                                 Terms::summation ? 0.0 : vab.dot(gW),
                                 vab.x() * gW.x(), vab.y() * gW.x(), vab.x() * gW.y(), vab.y() * gW.y()};
            // a gains m_b t (acceleration, continuity) and -V_b t (gradient); b gains -m_a t, +m_a t, -V_a t.
            const double mb = m_[b], Vb = volume_[b];
            double* __restrict sb = sums[b].s;
            for (int c = 0; c < 3; ++c) sa[c] = std::fma(mb, t[c], sa[c]);
            for (int c = 3; c < 7; ++c) sa[c] = std::fma(-Vb, t[c], sa[c]);
            sb[0] = std::fma(-ma, t[0], sb[0]);
            sb[1] = std::fma(-ma, t[1], sb[1]);
            sb[2] = std::fma(ma, t[2], sb[2]);
            for (int c = 3; c < 7; ++c) sb[c] = std::fma(-Va, t[c], sb[c]);
          }
          for (int c = 0; c < 7; ++c) sums[a].s[c] = sa[c];
        }
      }
    }
#pragma omp barrier
#pragma omp for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
      const PairSums sum = sum_threads(a, &GrayScratch::Partial::sums);
      const Vec2 acc(sum.s[PairSums::kAccX], sum.s[PairSums::kAccY]);
      Tensor2 grad_v;  // grad_v(i, j) = d vhat_i / d x_j
      for (int c = 0; c < 4; ++c) grad_v.data()[c] = sum.s[PairSums::kGrad + c];
      const Motion kind = body.motion[a];
      out.dv[a] = kind == Motion::Free ? acc : kind == Motion::Driven ? body.drive[a] : Vec2::Zero();
      out.dx[a] = kind == Motion::Free ? vhat[a] : kind == Motion::Driven ? v[a] : Vec2::Zero();
      if constexpr (Terms::summation) out.drho[a] = 0.0;
      else out.drho[a] = sum.s[PairSums::kDrho];
      out.dS[a] = hooke_deviatoric_rate(p.mu, grad_v, S[a]);
      if constexpr (!Terms::xsph) out.vhat[a] = v[a];
    }
  }
}

}  // namespace sph
