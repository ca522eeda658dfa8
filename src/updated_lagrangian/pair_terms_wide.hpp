// Pass 2 of Gray's pair loop (pair_terms.hpp) eight pairs at a time on AVX-512, with the bits of the scalar
// loop. Each lane takes one pair of a row: the neighbours' fields come from their ParticleRecords (two cache
// lines each, written by the per-particle pass), loaded whole and transposed into lanes (fifteen gathers, one
// per field, took twice as long on the AMD host: 77 against 37 ns per eight neighbours in a micro-benchmark), every per-pair number is
// computed with the scalar loop's operations (a product that the scalar code adds unfused is computed by the
// rounding-mode intrinsics, which GCC cannot fuse; a fused multiply-add where the scalar code has one), and
// the eight pairs' terms are transposed into one record per pair, [f_x, f_y, v_ab.gW, G00, G10, G01, G11, 0]
// (PairSums' layout). Each pair's record is then added to b's sums, and to a's sums in pair order, as one
// eight-wide fused multiply-add: a's sums get the terms in the scalar loop's order, and b's are distinct in a
// row, so nothing is reordered. tests/test_gray_solver.cpp holds this path to the scalar one, bit for bit.
#pragma once

#include <cstdint>

namespace sph {

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

/// Per particle, what pass 2 reads of a neighbour, in two cache lines: sigma / rho^2 and the artificial stress R
/// (column-major 2x2 each; R zero without the artificial stress), v, the XSPH velocity vhat, rho, m, m / rho.
struct alignas(64) ParticleRecord {
  double s[16];
  enum : int { kA = 0, kR = 4, kV = 8, kVhat = 10, kRho = 12, kMass = 13, kVolume = 14 };
};
}  // namespace sph

#if defined(__AVX512F__) && defined(__AVX512VL__)
#define SPH_WIDE_PASS2 1
#include <immintrin.h>

namespace sph {

/// What pass 2 reads: the pair list, the particles' fields and the constants of the terms.
struct Pass2Inputs {
  const std::uint32_t* __restrict nb;
  const double* __restrict dx;      ///< x_a - x_b, interleaved
  const double* __restrict W;
  const double* __restrict F;
  const ParticleRecord* __restrict rec;
  double h, eta2, alpha, beta, c0, inv_Wdp;
  int nart;
};

namespace wide {

constexpr int kAsIs = _MM_FROUND_CUR_DIRECTION;
// Unfusable forms: the scalar loop rounds these products before adding them.
inline __m512d mul(__m512d a, __m512d b) { return _mm512_mul_round_pd(a, b, kAsIs); }
inline __m512d add(__m512d a, __m512d b) { return _mm512_add_round_pd(a, b, kAsIs); }
inline __m512d sub(__m512d a, __m512d b) { return _mm512_sub_round_pd(a, b, kAsIs); }
inline __m512d bcast(double x) { return _mm512_set1_pd(x); }

/// r[0..7] (row i = quantity i, lane j = pair j) into x[j] = column j.
inline void transpose8(const __m512d r[8], __m512d x[8]) {
  __m512d t[8], u[8];
  for (int i = 0; i < 4; ++i) {
    t[2 * i] = _mm512_unpacklo_pd(r[2 * i], r[2 * i + 1]);      // [r0_0 r1_0 r0_2 r1_2 r0_4 r1_4 r0_6 r1_6]
    t[2 * i + 1] = _mm512_unpackhi_pd(r[2 * i], r[2 * i + 1]);  // the odd lanes
  }
  const __m512i even = _mm512_setr_epi64(0, 1, 8, 9, 4, 5, 12, 13), odd = _mm512_setr_epi64(2, 3, 10, 11, 6, 7, 14, 15);
  for (int i = 0; i < 2; ++i) {
    u[4 * i + 0] = _mm512_permutex2var_pd(t[4 * i], even, t[4 * i + 2]);     // lanes 0, 4 of rows 4i..4i+3
    u[4 * i + 1] = _mm512_permutex2var_pd(t[4 * i], odd, t[4 * i + 2]);      // lanes 2, 6
    u[4 * i + 2] = _mm512_permutex2var_pd(t[4 * i + 1], even, t[4 * i + 3]); // lanes 1, 5
    u[4 * i + 3] = _mm512_permutex2var_pd(t[4 * i + 1], odd, t[4 * i + 3]);  // lanes 3, 7
  }
  x[0] = _mm512_shuffle_f64x2(u[0], u[4], 0x44); x[4] = _mm512_shuffle_f64x2(u[0], u[4], 0xEE);
  x[2] = _mm512_shuffle_f64x2(u[1], u[5], 0x44); x[6] = _mm512_shuffle_f64x2(u[1], u[5], 0xEE);
  x[1] = _mm512_shuffle_f64x2(u[2], u[6], 0x44); x[5] = _mm512_shuffle_f64x2(u[2], u[6], 0xEE);
  x[3] = _mm512_shuffle_f64x2(u[3], u[7], 0x44); x[7] = _mm512_shuffle_f64x2(u[3], u[7], 0xEE);
}

/// f^n as the scalar ipow computes it (r = 1, then r *= f n times: the same product order).
inline __m512d power(__m512d f, int n) {
  if (n == 0) return bcast(1.0);
  __m512d r = f;
  for (int i = 1; i < n; ++i) r = mul(r, f);
  return r;
}

/// Pass 2 of row a: pairs k0 .. k1 - 1 (b > a), into the thread's sums; a's own sums in `sa` (a register).
template <class Terms>
inline void pass2_row(std::size_t a, std::uint32_t k0, std::uint32_t k1, const Pass2Inputs& in, PairSums* __restrict sums) {
  using P = ParticleRecord;
  const double* ra = in.rec[a].s;
  const __m512d Aa0 = bcast(ra[P::kA]), Aa1 = bcast(ra[P::kA + 1]), Aa2 = bcast(ra[P::kA + 2]), Aa3 = bcast(ra[P::kA + 3]);
  const double ma = ra[P::kMass], Va = ra[P::kVolume];
  // b's record gains -m_a f (acceleration), +m_a v_ab.gW (continuity), -V_a G (gradient); a's gains the terms
  // with m_b and V_b (pair_terms.hpp, pass 2).
  const __m512d to_b = _mm512_setr_pd(-ma, -ma, ma, -Va, -Va, -Va, -Va, 0.0);
  const __m512i even = _mm512_setr_epi64(0, 2, 4, 6, 8, 10, 12, 14), odd = _mm512_setr_epi64(1, 3, 5, 7, 9, 11, 13, 15);
  const __m512d sign = bcast(-0.0);
  __m512d sa = _mm512_load_pd(sums[a].s);
  alignas(32) std::uint32_t bs[8];
  for (std::uint32_t k = k0; k < k1; k += 8) {
    const unsigned count = k1 - k >= 8 ? 8u : k1 - k;
    const __mmask8 live = static_cast<__mmask8>((1u << count) - 1u);
    // Lanes past the row read particle 0 (valid memory); their terms are never added.
    const __m256i bi = _mm256_maskz_loadu_epi32(live, in.nb + k);
    _mm256_store_si256(reinterpret_cast<__m256i*>(bs), bi);
    // The neighbours' records, lane j = pair j: f[i] is field i of the first line, g[i] of the second.
    __m512d rows[8], f[8], g[8];
    for (int j = 0; j < 8; ++j) rows[j] = _mm512_load_pd(in.rec[bs[j]].s);
    transpose8(rows, f);
    for (int j = 0; j < 8; ++j) rows[j] = _mm512_load_pd(in.rec[bs[j]].s + 8);
    transpose8(rows, g);
    const unsigned both = (1u << (2 * count)) - 1u;
    const __m512d d_lo = _mm512_maskz_loadu_pd(static_cast<__mmask8>(both), in.dx + 2 * k);
    const __m512d d_hi = _mm512_maskz_loadu_pd(static_cast<__mmask8>(both >> 8), in.dx + 2 * k + 8);
    const __m512d dxx = _mm512_permutex2var_pd(d_lo, even, d_hi), dxy = _mm512_permutex2var_pd(d_lo, odd, d_hi);
    const __m512d Fk = _mm512_maskz_loadu_pd(live, in.F + k);
    const __m512d gWx = mul(dxx, Fk), gWy = mul(dxy, Fk);  // grad_a W_ab (3.2)
    __m512d M0 = add(Aa0, f[P::kA]);
    __m512d M1 = add(Aa1, f[P::kA + 1]);
    __m512d M2 = add(Aa2, f[P::kA + 2]);
    __m512d M3 = add(Aa3, f[P::kA + 3]);
    if constexpr (Terms::artificial_stress) {
      const __m512d fn = power(mul(_mm512_maskz_loadu_pd(live, in.W + k), bcast(in.inv_Wdp)), in.nart);
      M0 = _mm512_fmadd_pd(add(bcast(ra[P::kR]), f[P::kR]), fn, M0);
      M1 = _mm512_fmadd_pd(add(bcast(ra[P::kR + 1]), f[P::kR + 1]), fn, M1);
      M2 = _mm512_fmadd_pd(add(bcast(ra[P::kR + 2]), f[P::kR + 2]), fn, M2);
      M3 = _mm512_fmadd_pd(add(bcast(ra[P::kR + 3]), f[P::kR + 3]), fn, M3);
    }
    if constexpr (Terms::viscosity) {
      const __m512d dvx = sub(bcast(ra[P::kV]), g[P::kV - 8]);
      const __m512d dvy = sub(bcast(ra[P::kV + 1]), g[P::kV + 1 - 8]);
      const __m512d vr = add(mul(dvx, dxx), mul(dvy, dxy));
      const __mmask8 approaching = live & _mm512_cmp_pd_mask(vr, _mm512_setzero_pd(), _CMP_LT_OQ);
      if (approaching) {  // monaghan_pi, operation by operation
        const __m512d r2 = add(mul(dxx, dxx), mul(dxy, dxy));
        const __m512d mu = _mm512_div_pd(mul(bcast(in.h), vr), add(r2, bcast(in.eta2)));
        const __m512d rho_ab = mul(bcast(0.5), add(bcast(ra[P::kRho]), g[P::kRho - 8]));
        const __m512d num = _mm512_fmadd_pd(bcast(-in.alpha * in.c0), mu, mul(mul(bcast(in.beta), mu), mu));
        const __m512d Pi = _mm512_div_pd(num, rho_ab);
        M0 = _mm512_mask_sub_round_pd(M0, approaching, M0, Pi, kAsIs);
        M3 = _mm512_mask_sub_round_pd(M3, approaching, M3, Pi, kAsIs);
      }
    }
    __m512d r[8], x[8];
    r[0] = _mm512_fmadd_pd(M2, gWy, mul(M0, gWx));  // M gW
    r[1] = _mm512_fmadd_pd(M3, gWy, mul(M1, gWx));
    const __m512d vabx = sub(bcast(ra[P::kVhat]), g[P::kVhat - 8]);
    const __m512d vaby = sub(bcast(ra[P::kVhat + 1]), g[P::kVhat + 1 - 8]);
    r[2] = Terms::summation ? _mm512_setzero_pd() : add(mul(vabx, gWx), mul(vaby, gWy));
    r[3] = mul(vabx, gWx);
    r[4] = mul(vaby, gWx);
    r[5] = mul(vabx, gWy);
    r[6] = mul(vaby, gWy);
    r[7] = _mm512_setzero_pd();
    transpose8(r, x);
    const __m512d mb = g[P::kMass - 8];
    const __m512d minus_Vb = _mm512_xor_pd(g[P::kVolume - 8], sign);
    for (unsigned j = 0; j < count; ++j) {
      // a's factors of pair j: [m_b m_b m_b -V_b -V_b -V_b -V_b m_b] (the last multiplies the zero)
      const __m512i pick = _mm512_setr_epi64(j, j, j, 8 + j, 8 + j, 8 + j, 8 + j, j);
      sa = _mm512_fmadd_pd(_mm512_permutex2var_pd(mb, pick, minus_Vb), x[j], sa);
      double* sb = sums[bs[j]].s;
      _mm512_store_pd(sb, _mm512_fmadd_pd(to_b, x[j], _mm512_load_pd(sb)));
    }
  }
  _mm512_store_pd(sums[a].s, sa);
}

}  // namespace wide
}  // namespace sph

#else
#define SPH_WIDE_PASS2 0
#endif
