// The value type of a pair loop written once for one pair at a time and for a block of pairs side by side: a
// double, or a SIMD batch of doubles (xsimd, Debian libxsimd-dev, header-only), one pair per lane. The terms are
// templates over it (updated_lagrangian/pair_terms.hpp); this file holds what differs between the two: the
// width, broadcasts, masks, the fused and the unfused product, and the transposes between a block of
// per-particle records and lanes.
//
// Bits: each lane computes its pair with the operations of the one-pair form, and IEEE addition,
// multiplication, division and fused multiply-add are one rounding per lane, so a result does not depend on
// the width. What could differ is the compiler's choice: GCC contracts a product followed by an addition into
// a fused multiply-add (-ffp-contract=fast, its default for C++), for doubles and vector operators alike, case
// by case. The terms therefore say which they mean: fma(a, b, c) is fused, rounded(a * b) + c is not.
#pragma once

#include <xsimd/xsimd.hpp>

#include <cmath>
#include <cstddef>
#include <utility>

namespace sph::lanes {

// The helpers below are a few instructions each, called in the innermost loop: inlined always (GCC kept
// to_octets out of line, a call with its arrays through memory: 10% of an evaluation).
#define SPH_LANES_INLINE [[gnu::always_inline]] inline

/// The widest batch of doubles of the target with a fused multiply-add in hardware, or double: every fma of
/// the terms must be one rounding, and xsimd's fma on a target without one is a * b + c (two roundings).
/// AVX-512 8 lanes, AVX2 with FMA 4, Arm 2; an x86-64 build without FMA (SPH_NATIVE=OFF) one pair at a time.
#if XSIMD_WITH_AVX512F
using Widest = xsimd::batch<double, xsimd::avx512f>;
#elif XSIMD_WITH_FMA3_AVX2
using Widest = xsimd::batch<double, xsimd::fma3<xsimd::avx2>>;
#elif XSIMD_WITH_NEON64
using Widest = xsimd::batch<double, xsimd::neon64>;
#else
using Widest = double;
#endif

template <class V> struct Width { static constexpr int value = static_cast<int>(V::size); };
template <> struct Width<double> { static constexpr int value = 1; };
/// Pairs per value: 1 for a double.
template <class V> constexpr int width = Width<V>::value;

/// x, rounded: hidden from the compiler (an empty asm statement, no instruction), which then cannot contract
/// the product that made it into a following addition.
inline double rounded(double x) {
#if defined(__aarch64__)
  asm("" : "+w"(x));
#else
  asm("" : "+v"(x));
#endif
  return x;
}
template <class A>
inline xsimd::batch<double, A> rounded(xsimd::batch<double, A> x) {
#if defined(__aarch64__)
  asm("" : "+w"(x.data));
#else
  asm("" : "+v"(x.data));
#endif
  return x;
}

inline double fma(double a, double b, double c) { return std::fma(a, b, c); }
template <class A>
inline xsimd::batch<double, A> fma(const xsimd::batch<double, A>& a, const xsimd::batch<double, A>& b,
                                   const xsimd::batch<double, A>& c) {
#if defined(__FMA__)
  // xsimd's SSE batches have no fused form once AVX is on (fma3<sse4_2> is then not offered); the tests run
  // two lanes on such hosts.
  if constexpr (xsimd::batch<double, A>::size == 2) return _mm_fmadd_pd(a, b, c);
#endif
  return xsimd::fma(a, b, c);
}

/// A comparison's mask: a bool for a double, one bit per lane for a batch.
inline bool any(bool m) { return m; }
template <class A>
inline bool any(const xsimd::batch_bool<double, A>& m) { return xsimd::any(m); }
inline double select(bool m, double x, double y) { return m ? x : y; }
template <class A>
inline xsimd::batch<double, A> select(const xsimd::batch_bool<double, A>& m, const xsimd::batch<double, A>& x,
                                      const xsimd::batch<double, A>& y) {
  return xsimd::select(m, x, y);
}

template <class V> V load(const double* p) { return V::load_unaligned(p); }
template <> inline double load<double>(const double* p) { return *p; }
template <class V> V load_aligned(const double* p) { return V::load_aligned(p); }
template <> inline double load_aligned<double>(const double* p) { return *p; }
inline void store_aligned(double* p, double x) { *p = x; }
template <class A>
inline void store_aligned(double* p, const xsimd::batch<double, A>& x) { x.store_aligned(p); }

/// The value whose lane i is f(i) (f(0) for a double), from scalars: no store and reload through memory.
template <class V, class F, std::size_t... I>
SPH_LANES_INLINE V from_lanes(F&& f, std::index_sequence<I...>) {
  if constexpr (sizeof...(I) == 1) return f(0);
  else return V{f(I)...};
}
template <class V, class F>
SPH_LANES_INLINE V from_lanes(F&& f) { return from_lanes<V>(f, std::make_index_sequence<width<V>>{}); }

/// In place: lane j of v[i] and lane i of v[j] exchanged (an N x N transpose of N values; nothing for a double).
inline void transpose(double*) {}
template <class A>
SPH_LANES_INLINE void transpose(xsimd::batch<double, A>* v) {
  constexpr int N = width<xsimd::batch<double, A>>;
  if constexpr (N == 2) {  // SSE, NEON: xsimd 8's zips interleave within 128-bit halves, which is all of them here
    const auto lo = xsimd::zip_lo(v[0], v[1]), hi = xsimd::zip_hi(v[0], v[1]);
    v[0] = lo;
    v[1] = hi;
#if XSIMD_WITH_AVX
  } else if constexpr (N == 4) {
    const __m256d t0 = _mm256_unpacklo_pd(v[0], v[1]), t1 = _mm256_unpackhi_pd(v[0], v[1]);  // [v0_0 v1_0 v0_2 v1_2]
    const __m256d t2 = _mm256_unpacklo_pd(v[2], v[3]), t3 = _mm256_unpackhi_pd(v[2], v[3]);
    v[0] = _mm256_permute2f128_pd(t0, t2, 0x20);
    v[1] = _mm256_permute2f128_pd(t1, t3, 0x20);
    v[2] = _mm256_permute2f128_pd(t0, t2, 0x31);
    v[3] = _mm256_permute2f128_pd(t1, t3, 0x31);
#endif
#if XSIMD_WITH_AVX512F
  } else if constexpr (N == 8) {
    __m512d t[8], u[8];
    for (int i = 0; i < 4; ++i) {
      t[2 * i] = _mm512_unpacklo_pd(v[2 * i], v[2 * i + 1]);      // [v0_0 v1_0 v0_2 v1_2 v0_4 v1_4 v0_6 v1_6]
      t[2 * i + 1] = _mm512_unpackhi_pd(v[2 * i], v[2 * i + 1]);  // the odd lanes
    }
    const __m512i even = _mm512_setr_epi64(0, 1, 8, 9, 4, 5, 12, 13), odd = _mm512_setr_epi64(2, 3, 10, 11, 6, 7, 14, 15);
    for (int i = 0; i < 2; ++i) {
      u[4 * i + 0] = _mm512_permutex2var_pd(t[4 * i], even, t[4 * i + 2]);      // lanes 0, 4 of rows 4i..4i+3
      u[4 * i + 1] = _mm512_permutex2var_pd(t[4 * i], odd, t[4 * i + 2]);       // lanes 2, 6
      u[4 * i + 2] = _mm512_permutex2var_pd(t[4 * i + 1], even, t[4 * i + 3]);  // lanes 1, 5
      u[4 * i + 3] = _mm512_permutex2var_pd(t[4 * i + 1], odd, t[4 * i + 3]);   // lanes 3, 7
    }
    v[0] = _mm512_shuffle_f64x2(u[0], u[4], 0x44); v[4] = _mm512_shuffle_f64x2(u[0], u[4], 0xEE);
    v[2] = _mm512_shuffle_f64x2(u[1], u[5], 0x44); v[6] = _mm512_shuffle_f64x2(u[1], u[5], 0xEE);
    v[1] = _mm512_shuffle_f64x2(u[2], u[6], 0x44); v[5] = _mm512_shuffle_f64x2(u[2], u[6], 0xEE);
    v[3] = _mm512_shuffle_f64x2(u[3], u[7], 0x44); v[7] = _mm512_shuffle_f64x2(u[3], u[7], 0xEE);
#endif
  } else {
    static_assert(N == 0, "lanes::transpose: no transpose for this width");
  }
}

/// x_k = p[2k] and y_k = p[2k + 1], k = 0 .. N - 1 (the pair list's interleaved x_a - x_b), into lanes.
inline void deinterleave(const double* p, double& x, double& y) {
  x = p[0];
  y = p[1];
}
template <class A>
SPH_LANES_INLINE void deinterleave(const double* p, xsimd::batch<double, A>& x, xsimd::batch<double, A>& y) {
  using V = xsimd::batch<double, A>;
  constexpr int N = width<V>;
  if constexpr (N == 2) {
    const V lo = V::load_unaligned(p), hi = V::load_unaligned(p + 2);  // [x0 y0], [x1 y1]
    x = xsimd::zip_lo(lo, hi);
    y = xsimd::zip_hi(lo, hi);
#if XSIMD_WITH_AVX
  } else if constexpr (N == 4) {
    // [x0 y0 | x2 y2] and [x1 y1 | x3 y3] from 16-byte halves; unpacking them within halves gives x and y
    const __m256d q02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p)), _mm_loadu_pd(p + 4), 1);
    const __m256d q13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p + 2)), _mm_loadu_pd(p + 6), 1);
    x = _mm256_unpacklo_pd(q02, q13);
    y = _mm256_unpackhi_pd(q02, q13);
#endif
#if XSIMD_WITH_AVX512F
  } else if constexpr (N == 8) {
    const __m512d lo = _mm512_loadu_pd(p), hi = _mm512_loadu_pd(p + 8);
    x = _mm512_permutex2var_pd(lo, _mm512_setr_epi64(0, 2, 4, 6, 8, 10, 12, 14), hi);
    y = _mm512_permutex2var_pd(lo, _mm512_setr_epi64(1, 3, 5, 7, 9, 11, 13, 15), hi);
#endif
  } else {
    static_assert(N == 0, "lanes::deinterleave: not for this width");
  }
}

/// Eight doubles as 8 / N values: a particle's pass-2 sums, or a pair's terms, in one cache line.
template <class V>
struct Octet {
  static constexpr int N = width<V>, parts = 8 / N;
  V part[parts];
  SPH_LANES_INLINE static Octet load(const double* p) {
    Octet o;
    for (int i = 0; i < parts; ++i) o.part[i] = load_aligned<V>(p + N * i);
    return o;
  }
  /// e[0 .. 7] (from scalars, for constants of a row).
  SPH_LANES_INLINE static Octet of(const double (&e)[8]) {
    Octet o;
    for (int i = 0; i < parts; ++i) o.part[i] = from_lanes<V>([&](std::size_t j) { return e[N * i + j]; });
    return o;
  }
  SPH_LANES_INLINE void store(double* p) const {
    for (int i = 0; i < parts; ++i) store_aligned(p + N * i, part[i]);
  }
};
/// f x + s by elements, each one fused multiply-add.
template <class V>
SPH_LANES_INLINE Octet<V> fma(const Octet<V>& f, const Octet<V>& x, const Octet<V>& s) {
  Octet<V> r;
  for (int i = 0; i < Octet<V>::parts; ++i) r.part[i] = fma(f.part[i], x.part[i], s.part[i]);
  return r;
}

/// Eight quantities of N pairs, t[q] lane j, into one octet per pair: x[j] element q (transposes of N x N blocks).
template <class V>
SPH_LANES_INLINE void to_octets(const V (&t)[8], Octet<V>* x) {
  constexpr int N = width<V>;
  for (int p = 0; p < Octet<V>::parts; ++p) {
    V block[N];
    for (int i = 0; i < N; ++i) block[i] = t[N * p + i];
    transpose(block);
    for (int j = 0; j < N; ++j) x[j].part[p] = block[j];
  }
}

}  // namespace sph::lanes
