// The right-hand side of the scheme of Gray, Monaghan & Swift 2001 for a scheme's list of terms (GrayTerms,
// pair_terms.hpp), over the cached pair geometry of a PairList (x_a - x_b, W, F with grad_a W = dx F), every
// pair once (b > a in a's row), added to both of its particles:
//   pass 1 (if XSPH or summation density): the XSPH sum (3.6), summation density
//   per particle: vhat and rho of pass 1, sigma / rho^2 (2.2), (2.7) and the terms' own fields (R (6.1)-(6.7),
//     v and rho of the viscosity) into the particle's neighbour record
//   pass 2: the pair terms, fused into one loop over blocks of N pairs, one per lane of lanes::Widest (AVX-512
//     8, AVX2 4, one pair at a time without a SIMD fused multiply-add): acceleration (3.1) with the artificial
//     stress (3.12) and the viscosity, continuity (3.8), velocity gradient (3.10)
//   per particle: the sums of the threads, the rates and the Hooke stress rate (2.3)-(2.5).
// A term that is off is not in the loops, and its fields and partial sums do not exist.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/kernels.hpp"
#include "core/lanes.hpp"
#include "core/materials.hpp"
#include "core/pair_list.hpp"
#include "core/parallel.hpp"
#include "updated_lagrangian/elastic_body.hpp"
#include "updated_lagrangian/pair_terms.hpp"
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

/// Per particle, the sums of pass 2 in one cache line: acceleration (x, y), continuity, velocity gradient
/// (column-major), and a zero.
struct alignas(64) PairSums {
  double s[8];
  enum : int { kAccX = 0, kAccY = 1, kDrho = 2, kGrad = 3 };
  PairSums& operator+=(const PairSums& o) {
    for (int c = 0; c < 8; ++c) s[c] += o.s[c];
    return *this;
  }
};

struct alignas(64) CacheLine {
  double s[8];
};

/// Per particle, what pass 2 reads of it as a neighbour, in whole cache lines: a block of N pairs loads the
/// N neighbours' records N numbers at a time, one aligned load each, and transposes them into lanes
/// (lanes::transpose; fifteen AVX-512 gathers, one per field, took twice as long on the AMD host of
/// 2026-12-04: 77 against 37 ns per eight neighbours). Always sigma / rho^2, the velocity of the gradient and
/// the continuity equation (vhat with XSPH, else v), m and -m / rho; then the fields of the terms that are on.
template <class Terms>
struct NeighbourRecord {
  static constexpr int kA = 0, kVhat = 4, kMass = 6, kMinusVolume = 7;
  static constexpr int kTensile = 8, kViscosity = kTensile + Terms::tensile::fields;
  static constexpr int size = (kViscosity + Terms::viscosity::fields + 7) / 8 * 8, lines = size / 8;
  /// Is field f read lane by lane (m and V are read per pair, whole)?
  static constexpr bool lane_field(int f) {
    return f < kMass || (f >= kTensile && f < kViscosity + Terms::viscosity::fields);
  }
  static constexpr bool lane_block(int first, int N) {
    for (int f = first; f < first + N; ++f)
      if (lane_field(f)) return true;
    return false;
  }
  /// The lane fields of the N neighbours rb[j] into f (lane j = neighbour j), N at a time.
  template <class V, std::size_t... B>
  SPH_LANES_INLINE static void load(const double* const* rb, V* f, std::index_sequence<B...>) {
    constexpr int N = lanes::width<V>;
    auto block = [&](auto b) {
      if constexpr (lane_block(b * N, N)) {
        for (int j = 0; j < N; ++j) f[b * N + j] = lanes::load_aligned<V>(rb[j] + b * N);
        lanes::transpose(f + b * N);
      }
    };
    (block(std::integral_constant<int, static_cast<int>(B)>{}), ...);
  }
  template <class V>
  SPH_LANES_INLINE static void load(const double* const* rb, V* f) {
    load(rb, f, std::make_index_sequence<size / lanes::width<V>>{});
  }
};

/// Per-thread partial sums: every pair is evaluated once, for both of its particles, so a thread adds into its
/// own arrays and one pass sums them (the order of the sums then depends on the number of threads, at
/// round-off). A thread's rows are a..a' (the static partition of OpenMP) and its pairs reach only particles
/// b > a, up to some b_max: it zeroes and fills only [a, b_max], and the sum over threads skips those whose
/// range misses a particle (a zero it would add changes no bit), so the zeroing and the sum do not grow with the
/// thread count.
struct GrayScratch {
  std::vector<CacheLine> records;  ///< NeighbourRecord<Terms>::lines per particle
  struct Partial {
    std::vector<Vec2> xsph;        ///< the XSPH sum (3.6), with Xsph only
    std::vector<double> rho;       ///< the summation density, with SummationDensity only
    std::vector<PairSums> sums;    ///< pass 2
    std::size_t lo = 0, hi = 0;    ///< the particles this thread's pairs touch: [lo, hi)
  };
  std::vector<Partial> partial;    ///< one per thread
  template <class Terms>
  void size_for(std::size_t n, int threads) {
    if (records.size() != n * NeighbourRecord<Terms>::lines) records.assign(n * NeighbourRecord<Terms>::lines, CacheLine{});
    if (partial.size() < static_cast<std::size_t>(threads)) partial.resize(threads);
    for (auto& q : partial) {
      if (q.sums.size() != n) q.sums.assign(n, PairSums{});
      if (Terms::xsph::pass1 && q.xsph.size() != n) q.xsph.assign(n, Vec2::Zero());
      if (Terms::density::pass1 && q.rho.size() != n) q.rho.assign(n, 0.0);
    }
  }
};

/// What pass 2 reads: the pair list, the neighbour records and the constants of the terms.
struct Pass2Inputs {
  const std::uint32_t* __restrict nb;
  const double* __restrict dx;  ///< x_a - x_b, interleaved
  const double* __restrict W;
  const double* __restrict F;
  const double* __restrict records;
  PairConstants k;
};

static_assert(lanes::width<lanes::Widest> <= PairList::kBlockSlack, "a block of pairs may read past the pair arrays");

/// Pass 2 of row a: pairs k0 .. k1 - 1 (b > a) in blocks of N, into the thread's sums. Each block's terms are
/// transposed into one octet per pair, [f_x, f_y, vhat_ab . gW, G00, G10, G01, G11, 0] (PairSums' layout), and
/// added to b's sums and, in pair order, to a's sums (kept in registers: its pairs reach only b > a, so nothing
/// else writes a's entries during the row): one fused multiply-add per octet, so a's sums get the terms in
/// the order of the pairs, and b's are distinct within a row: no width reorders a sum.
template <class Terms, class V>
inline void pass2_row(std::uint32_t a, std::uint32_t k0, std::uint32_t k1, const Pass2Inputs& in, PairSums* __restrict sums) {
  using L = NeighbourRecord<Terms>;
  using Octet = lanes::Octet<V>;
  constexpr int N = lanes::width<V>;
  const double* ra = in.records + std::size_t{a} * L::size;
  const double ma = ra[L::kMass], minus_Va = ra[L::kMinusVolume];
  // b gains -m_a (the acceleration (3.1)), +m_a (the continuity (3.8)), -V_a (the gradient (3.10)) times the
  // pair's terms; a gains m_b, m_b, -V_b.
  const Octet to_b = Octet::of({-ma, -ma, ma, minus_Va, minus_Va, minus_Va, minus_Va, 0.0});
  Octet sa = Octet::load(sums[a].s);
  for (std::uint32_t k = k0; k < k1; k += N) {
    const std::uint32_t live = std::min<std::uint32_t>(N, k1 - k);
    // Lanes past the row read past its last pair (the pair arrays have slack for a block) and a's record;
    // their terms are never added.
    const double* rb[N];
    for (int j = 0; j < N; ++j) rb[j] = in.records + std::size_t{static_cast<std::uint32_t>(j) < live ? in.nb[k + j] : a} * L::size;
    V fields[L::size];
    L::load(rb, fields);
    PairView<V> p;
    lanes::deinterleave(in.dx + 2 * std::size_t{k}, p.dx, p.dy);
    const V F = lanes::load<V>(in.F + k);
    p.W = lanes::load<V>(in.W + k);
    p.gWx = p.dx * F;  // grad_a W_ab (3.2)
    p.gWy = p.dy * F;
    p.ra = ra;
    p.rb = fields;
    V M[4];
    StressAcceleration::tensor<L::kA>(p, M);
    Terms::tensile::template pair<L::kTensile>(p, in.k, M);
    Terms::viscosity::template pair<L::kViscosity>(p, in.k, M);
    V t[8];
    StressAcceleration::pair(p, M, t[0], t[1]);
    const V vx = p.a(L::kVhat) - p.b(L::kVhat), vy = p.a(L::kVhat + 1) - p.b(L::kVhat + 1);
    t[2] = Terms::density::pair(p, vx, vy);
    VelocityGradient::pair(p, vx, vy, t + 3);
    t[7] = V(0.0);
    Octet x[N];
    lanes::to_octets(t, x);
    for (std::uint32_t j = 0; j < live; ++j) {
      const double mb = rb[j][L::kMass], minus_Vb = rb[j][L::kMinusVolume];
      sa = fma(Octet::of({mb, mb, mb, minus_Vb, minus_Vb, minus_Vb, minus_Vb, mb}), x[j], sa);
      double* sb = sums[in.nb[k + j]].s;
      fma(to_b, x[j], Octet::load(sb)).store(sb);
    }
  }
  sa.store(sums[a].s);
}

/// The rates of the body's current state into `out`. With summation density it also sets body.rho.
/// h = h_over_dp dp, W_dp = W(dp, h) (the normalisation of f = W / W(dp)). `pairs` holds every pair once
/// (PairList::half): b > a in a's row. One parallel region: pass 1, the per-particle terms, pass 2 and the
/// sums of the threads' partials, separated by barriers. V: the value type of pass 2 (core/lanes.hpp).
template <class Terms, class V = lanes::Widest>
void evaluate_gray_rates(ElasticBody& body, const GrayParameters& p, const CubicSpline& kernel, double h, double W_dp,
                         const PairList& pairs, GrayScratch& scratch, GrayRates& out) {
  using L = NeighbourRecord<Terms>;
  using Smoothing = typename Terms::xsph;
  using Density = typename Terms::density;
  constexpr bool xsph = Smoothing::pass1, summation = Density::pass1;
  const std::size_t n = body.size();
  const auto& v = body.v;
  const auto& m = body.m;
  auto& rho = body.rho;
  const auto& S = body.S;
  scratch.size_for<Terms>(n, omp_get_max_threads());
  auto& partial = scratch.partial;
  double* records = scratch.records.data()->s;
  const std::vector<Vec2>& vhat = xsph ? out.vhat : v;
  const double W0 = kernel.W(0.0, h);
  const Pass2Inputs in{pairs.b.data(), pairs.dx.data()->data(), pairs.W.data(), pairs.F.data(), records,
                       {h, 0.01 * h * h, p.alpha, p.beta, p.c0, 1.0 / W_dp, p.n_artificial}};

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
    const std::uint32_t* __restrict nb_ = pairs.b.data();
    const double* __restrict W_ = pairs.W.data();
    const std::uint32_t* __restrict row_ = pairs.start.data();
    const std::uint32_t* __restrict active_ = pairs.active.data();

    // Pass 1 (only if a term needs it), from the densities of the previous evaluation. Scalar: eight pairs
    // at a time measured 0.95x (a row's sum is a chain of one multiply-add per pair either way).
    if constexpr (xsph || summation) {
      if constexpr (xsph) std::fill(q.xsph.begin() + q.lo, q.xsph.begin() + q.hi, Vec2::Zero());
      if constexpr (summation) std::fill(q.rho.begin() + q.lo, q.rho.begin() + q.hi, 0.0);
      const Vec2* __restrict v_ = v.data();
      const double* __restrict m_ = m.data();
      const double* __restrict rho_ = rho.data();
      Vec2* __restrict xsph_sum = q.xsph.data();
      double* __restrict rho_sum = q.rho.data();
      for (std::size_t a = a_begin; a < a_end; ++a) {
        Vec2 xsph_a = xsph ? xsph_sum[a] : Vec2::Zero();  // row a's own sums in registers (see pass2_row)
        double rho_a = summation ? rho_sum[a] : 0.0;
        for (std::uint32_t k = row_[a], end = row_[a] + active_[a]; k < end; ++k) {
          const std::uint32_t b = nb_[k];
          Smoothing::pass1_pair(v_[a], v_[b], W_[k], rho_[a], rho_[b], m_[a], m_[b], xsph_a, xsph_sum, b);
          Density::pass1_pair(W_[k], m_[a], m_[b], rho_a, rho_sum, b);
        }
        if constexpr (xsph) xsph_sum[a] = xsph_a;
        if constexpr (summation) rho_sum[a] = rho_a;
      }
#pragma omp barrier
    }

    // Per particle: vhat (3.6) and the summation density of pass 1, then the neighbour record.
#pragma omp for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
      if constexpr (xsph) out.vhat[a] = Xsph::velocity(v[a], p.eps_xsph, sum_threads(a, &GrayScratch::Partial::xsph));
      if constexpr (summation) rho[a] = sum_threads(a, &GrayScratch::Partial::rho) + m[a] * W0;
      const Tensor2 sigma = S[a] - linear_eos_pressure(rho[a], p.rho0, p.c0) * Tensor2::Identity();
      const Tensor2 A = sigma / (rho[a] * rho[a]);
      double* r = records + a * L::size;
      for (int c = 0; c < 4; ++c) r[L::kA + c] = A.data()[c];
      r[L::kVhat] = vhat[a].x();
      r[L::kVhat + 1] = vhat[a].y();
      r[L::kMass] = m[a];
      r[L::kMinusVolume] = -(m[a] / rho[a]);
      Terms::tensile::particle(r + L::kTensile, sigma, rho[a], p.eps_artificial);
      Terms::viscosity::particle(r + L::kViscosity, v[a], rho[a]);
    }

    // Pass 2 (pass2_row), into the thread's sums.
    std::fill(q.sums.begin() + q.lo, q.sums.begin() + q.hi, PairSums{});
    PairSums* __restrict sums = q.sums.data();
    for (std::size_t a = a_begin; a < a_end; ++a)
      pass2_row<Terms, V>(static_cast<std::uint32_t>(a), row_[a], row_[a] + active_[a], in, sums);
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
      out.drho[a] = summation ? 0.0 : sum.s[PairSums::kDrho];
      out.dS[a] = hooke_deviatoric_rate(p.mu, grad_v, S[a]);
      if constexpr (!xsph) out.vhat[a] = v[a];
    }
  }
}

}  // namespace sph
