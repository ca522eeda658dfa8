// Neighbour pairs in compressed-row form with their geometry cached per pair (a Verlet list): the pair
// storage of every formulation that searches neighbours in the current configuration (Gray's scheme, SPAM).
//
// Candidates are collected from the cell list within the search radius (the kernel support) plus a skin,
// and only re-collected when some particle has moved more than half the skin since the last collection
// (two particles then cannot have come within the support unseen); with skin 0 they are re-collected
// whenever anything moved. Every update refreshes the geometry of the candidates: x_a - x_b, W and F
// (grad_a W_ab = (x_a - x_b) F_ab), computed by the formulation's `geometry(r, W, F)`, which must give
// W = F = 0 beyond the support, and keeps the pairs inside the support, in candidate order: a pair with
// W = F = 0 adds exactly nothing to any sum, so the passes skip it without changing a bit. Every pass of an
// evaluation reads the cache, so the kernel is evaluated once per pair per update. A full list holds each
// pair twice (a->b and b->a): passes gather into their own particle only, which parallelises over
// particles without atomics (SPAM); a half list (`half`) holds each pair once, for passes that add a pair
// to both particles (Gray's scheme: half the pair work). No allocation once the arrays have reached their
// size. On AVX-512 the refresh of an open box takes eight candidates at a time when the geometry has an
// eight-wide form (the cubic spline's and Lucy's kernels, kernels.hpp), with the same bits as the scalar loop.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "core/neighbours.hpp"
#include "core/parallel.hpp"

namespace sph {

struct PairList {
  // Candidates (collected with the skin): those of particle a are cand[start[a] .. start[a+1]).
  std::vector<std::uint32_t> start, cand;
  // The pairs inside the support at the last update, in candidate order: those of particle a are
  // k = first(a) .. last(a) - 1 (at the front of a's candidate slots), with
  std::vector<std::uint32_t> b;      ///< neighbour index
  std::vector<Vec2> dx;              ///< x_a - x_b (minimum image)
  std::vector<double> W;             ///< W(r_ab, h)
  std::vector<double> F;             ///< F_ab with grad_a W_ab = dx F_ab (Gray et al. 2001 eq 3.2)
  std::vector<std::uint32_t> active; ///< number of pairs inside the support, per particle
  /// Per particle, 1 + the largest neighbour index among its pairs (0 without pairs): with a half list, the
  /// particles a block of rows reaches are [first row, max reach), found from the rows instead of the pairs.
  std::vector<std::uint32_t> reach;
  long collections = 0;              ///< how often the candidates were re-collected (diagnostics)
  /// Every pair once, in the row of its lower index (b > a), for formulations that add a pair's terms to
  /// both of its particles; otherwise every pair twice (a->b and b->a), for those that gather.
  bool half = false;
  /// Slots past the last candidate in b, dx, W and F: a loop over blocks of up to this many pairs
  /// (updated_lagrangian/pair_loop.hpp) reads a whole block from any pair on without leaving the arrays (it
  /// does not use what it reads past a row's end).
  static constexpr std::size_t kBlockSlack = 8;

  std::uint32_t first(std::size_t a) const { return start[a]; }
  std::uint32_t last(std::size_t a) const { return start[a] + active[a]; }
  /// Candidate slots (the arrays' size).
  std::size_t slots() const { return cand.size(); }

  /// Brings the list up to date for positions x. `cells` must have been constructed with a radius of at
  /// least support_radius + skin; it is rebuilt here when the candidates are re-collected.
  template <class Geometry>
  void update(CellList2D& cells, const std::vector<Vec2>& x, double support_radius, double skin, Geometry&& geometry) {
    if (must_collect(x, skin)) {
      cells.build(x);
      collect(cells, x, support_radius + skin);
    }
    refresh(cells, x, support_radius, geometry);
  }

 private:
  bool must_collect(const std::vector<Vec2>& x, double skin) const {
    if (x_collected_.size() != x.size()) return true;
    const double limit2 = 0.25 * skin * skin;
    const long n = static_cast<long>(x.size());
    bool moved = false;
#pragma omp parallel for reduction(|| : moved) schedule(static) if (n >= kParallelMin)
    for (long a = 0; a < n; ++a) moved = moved || (x[a] - x_collected_[a]).squaredNorm() > limit2;
    return moved;
  }

  // One traversal of the cell stencil: each thread appends the candidates of its rows (a contiguous block,
  // OpenMP's static partition) to its own buffer and counts them per row; after the prefix sum each thread
  // copies its block into place. The same candidates in the same order as counting first and filling in a
  // second traversal, which cost twice the search (22% of a rings run, where the list is re-collected every
  // ~4 steps).
  void collect(const CellList2D& cells, const std::vector<Vec2>& x, double radius) {
    const long n = static_cast<long>(x.size());
    start.resize(n + 1);
    start[0] = 0;
    const int threads = n >= kParallelMin ? omp_get_max_threads() : 1;
    if (buffers_.size() < static_cast<std::size_t>(threads)) buffers_.resize(threads);
#pragma omp parallel num_threads(threads)
    {
      const int t = omp_get_thread_num();
      std::size_t begin, end;
      static_rows(n, t, omp_get_num_threads(), begin, end);
      // The thread works on a vector of its own stack, not in place: the headers of the threads' vectors share
      // a cache line in buffers_, and every resize of one stored into the line the other thread was writing
      // (false sharing: a 1.6x longer collection on 2 threads). The swap keeps the capacity, so no allocation.
      std::vector<std::uint32_t> buffer;
      buffer.swap(buffers_[t]);
      buffer.clear();
      for (long a = static_cast<long>(begin); a < static_cast<long>(end); ++a) {
        const std::size_t before = buffer.size();
        cells.append_neighbours(x, a, radius, buffer, half);
        start[a + 1] = static_cast<std::uint32_t>(buffer.size() - before);
      }
#pragma omp barrier
#pragma omp single
      {
        for (long a = 0; a < n; ++a) start[a + 1] += start[a];
        const std::size_t total = start[n];
        cand.resize(total);
        b.resize(total + kBlockSlack);
        dx.resize(total + kBlockSlack);
        W.resize(total + kBlockSlack);
        F.resize(total + kBlockSlack);
        active.resize(n);
        reach.resize(n);
      }
      std::copy(buffer.begin(), buffer.end(), cand.begin() + start[begin]);
      buffers_[t].swap(buffer);
    }
    x_collected_ = x;
    ++collections;
  }

  template <class Geometry>
  void refresh(const CellList2D& cells, const std::vector<Vec2>& x, double support_radius, Geometry& geometry) {
    const long n = static_cast<long>(x.size());
    const double support2 = support_radius * support_radius;
    const auto displacement = cells.minimum_image();
    const std::decay_t<Geometry> g = geometry;  // by value: in registers, like the pointers below (see MinimumImage)
#if defined(__AVX512F__) && defined(__AVX512VL__)
    if constexpr (batch8_of<std::decay_t<Geometry>>::value) {
      if (!displacement.periodic_x && !displacement.periodic_y) {
        refresh8(x, n, support2, g);
        return;
      }
    }
#endif
    const std::uint32_t* __restrict start_ = start.data();
    const std::uint32_t* __restrict cand_ = cand.data();
    const Vec2* __restrict x_ = x.data();
    std::uint32_t* __restrict b_ = b.data();
    Vec2* __restrict dx_ = dx.data();
    double* __restrict W_ = W.data();
    double* __restrict F_ = F.data();
    std::uint32_t* __restrict active_ = active.data();
    std::uint32_t* __restrict reach_ = reach.data();
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
    for (long a = 0; a < n; ++a) {
      std::uint32_t j = start_[a], far = 0;
      const Vec2 xa = x_[a];
      for (std::uint32_t k = start_[a], end = start_[a + 1]; k < end; ++k) {
        const std::uint32_t c = cand_[k];
        const Vec2 d = displacement(xa, x_[c]);
        const double r2 = d.squaredNorm();
        if (r2 >= support2) continue;  // in the skin only: no square root, no kernel
        double w, f;
        g(std::sqrt(r2), w, f);
        if (w == 0.0 && f == 0.0) continue;  // beyond the support: every term of the pair is zero
        b_[j] = c;
        dx_[j] = d;
        W_[j] = w;
        F_[j] = f;
        far = std::max(far, c + 1);
        ++j;
      }
      active_[a] = j - start_[a];
      reach_[a] = far;
    }
  }

  template <class G, class = void>
  struct batch8_of : std::false_type {};
#if defined(__AVX512F__) && defined(__AVX512VL__)
  template <class G>
  struct batch8_of<G, std::void_t<decltype(G::batch8)>> : std::bool_constant<G::batch8> {};

  // The refresh eight candidates at a time (no periodic wrap): the candidates' positions loaded, the
  // distances and the geometry's eight-wide form computed, and the pairs inside the support stored in
  // candidate order (compressed). Every number is the one the scalar loop above computes, bit for bit: x_a -
  // x_b by components, |d|^2 as x^2 + y^2 without a fused multiply-add (Eigen's squaredNorm of a Vec2), the
  // exact square root, and a geometry whose eight-wide form matches its scalar one (tests/test_pair_list.cpp).
  // On the plate (n = 20, one thread) the refresh's share of a step fell from 17% to 12% (about 1.6x faster), the
  // step 1.12x; the SPAM hexagon (Lucy's kernel, a full list refreshed at every RK4 stage) 1.5x.
  template <class G>
  void refresh8(const std::vector<Vec2>& x, long n, double support2, const G& g) {
    const std::uint32_t* __restrict start_ = start.data();
    const std::uint32_t* __restrict cand_ = cand.data();
    const double* __restrict xd = x.data()->data();
    std::uint32_t* __restrict b_ = b.data();
    double* __restrict dx_ = dx.data()->data();
    double* __restrict W_ = W.data();
    double* __restrict F_ = F.data();
    std::uint32_t* __restrict active_ = active.data();
    std::uint32_t* __restrict reach_ = reach.data();
    const __m512i lo = _mm512_setr_epi64(0, 8, 1, 9, 2, 10, 3, 11), hi = _mm512_setr_epi64(4, 12, 5, 13, 6, 14, 7, 15);
    const __m512i even = _mm512_setr_epi64(0, 2, 4, 6, 8, 10, 12, 14), odd = _mm512_setr_epi64(1, 3, 5, 7, 9, 11, 13, 15);
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
    for (long a = 0; a < n; ++a) {
      std::uint32_t j = start_[a];
      const __m512d xa = _mm512_set1_pd(xd[2 * a]), ya = _mm512_set1_pd(xd[2 * a + 1]);
      __m256i far = _mm256_setzero_si256();  // 1 + the largest kept neighbour, per lane
      for (std::uint32_t k = start_[a], end = start_[a + 1]; k < end; k += 8) {
        const __mmask8 live = end - k >= 8 ? 0xff : static_cast<__mmask8>((1u << (end - k)) - 1u);
        const __m256i c = _mm256_maskz_loadu_epi32(live, cand_ + k);
        // The candidates' positions, one 16-byte load each, deinterleaved into x and y lanes (two gathers took
        // longer on the AMD host); lanes past the row read particle 0 and are never kept.
        alignas(32) std::uint32_t ci[8];
        _mm256_store_si256(reinterpret_cast<__m256i*>(ci), c);
        auto four = [&](int j) {  // [x y] of candidates j .. j + 3
          __m512d q = _mm512_castpd128_pd512(_mm_loadu_pd(xd + 2 * std::size_t{ci[j]}));
          q = _mm512_insertf64x2(q, _mm_loadu_pd(xd + 2 * std::size_t{ci[j + 1]}), 1);
          q = _mm512_insertf64x2(q, _mm_loadu_pd(xd + 2 * std::size_t{ci[j + 2]}), 2);
          return _mm512_insertf64x2(q, _mm_loadu_pd(xd + 2 * std::size_t{ci[j + 3]}), 3);
        };
        const __m512d p_lo = four(0), p_hi = four(4);
        const __m512d dxv = _mm512_sub_pd(xa, _mm512_permutex2var_pd(p_lo, even, p_hi));
        const __m512d dyv = _mm512_sub_pd(ya, _mm512_permutex2var_pd(p_lo, odd, p_hi));
        // The rounding-mode forms are not plain vector operators, so GCC cannot fuse them into a multiply-add.
        constexpr int kAsIs = _MM_FROUND_CUR_DIRECTION;
        const __m512d r2 = _mm512_add_round_pd(_mm512_mul_round_pd(dxv, dxv, kAsIs), _mm512_mul_round_pd(dyv, dyv, kAsIs), kAsIs);
        __mmask8 keep = live & _mm512_cmp_pd_mask(r2, _mm512_set1_pd(support2), _CMP_LT_OQ);
        if (!keep) continue;
        __m512d w, f;
        g(_mm512_sqrt_pd(r2), w, f);
        const __m512d zero = _mm512_setzero_pd();
        keep &= ~(_mm512_cmp_pd_mask(w, zero, _CMP_EQ_OQ) & _mm512_cmp_pd_mask(f, zero, _CMP_EQ_OQ));
        const int kept = __builtin_popcount(keep);
        _mm256_mask_compressstoreu_epi32(b_ + j, keep, c);
        far = _mm256_mask_max_epu32(far, keep, far, _mm256_add_epi32(c, _mm256_set1_epi32(1)));
        _mm512_mask_compressstoreu_pd(W_ + j, keep, w);
        _mm512_mask_compressstoreu_pd(F_ + j, keep, f);
        const __m512d cx = _mm512_maskz_compress_pd(keep, dxv), cy = _mm512_maskz_compress_pd(keep, dyv);
        const unsigned both = (1u << (2 * kept)) - 1u;  // x, y of the kept pairs, interleaved
        _mm512_mask_storeu_pd(dx_ + 2 * j, static_cast<__mmask8>(both), _mm512_permutex2var_pd(cx, lo, cy));
        _mm512_mask_storeu_pd(dx_ + 2 * j + 8, static_cast<__mmask8>(both >> 8), _mm512_permutex2var_pd(cx, hi, cy));
        j += kept;
      }
      active_[a] = j - start_[a];
      alignas(32) std::uint32_t lanes[8];
      _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), far);
      reach_[a] = *std::max_element(lanes, lanes + 8);
    }
  }
#endif

  std::vector<Vec2> x_collected_;
  std::vector<std::vector<std::uint32_t>> buffers_;  ///< per thread: the candidates of its rows (collect)
};

}  // namespace sph
