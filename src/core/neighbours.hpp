// Cell-linked list in 2D with optional periodic boundaries.
//
// Particles are binned into square cells of side >= the search radius (counting sort, O(N), no
// allocation once the arrays have reached their size), and a query visits the 3 x 3 block of cells
// around a particle. With periodic boundaries displacements use the minimum image, which requires the
// search radius to be at most half the period (checked).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/lattices.hpp"

#if defined(__AVX512F__) && defined(__AVX512VL__)
#include <immintrin.h>
#endif

namespace sph {

struct Box2 {
  double xmin = 0, ymin = 0, xmax = 1, ymax = 1;
  bool periodic_x = false, periodic_y = false;
  double Lx() const { return xmax - xmin; }
  double Ly() const { return ymax - ymin; }
};

/// The smallest non-periodic box holding all points (throws on an empty set).
Box2 bounding_box(const std::vector<Vec2>& points);

class CellList2D {
 public:
  /// `radius` is the largest search radius that queries will use. For a non-periodic direction the box
  /// only sizes the grid: particles outside it are binned into the edge cells, so a query stays exact.
  CellList2D(const Box2& box, double radius);

  /// Bins the particles. Call again whenever positions change.
  void build(const std::vector<Vec2>& x);

  /// x_a - x_b, by the minimum image in periodic directions.
  Vec2 displacement(const Vec2& a, const Vec2& b) const { return minimum_image()(a, b); }
  /// The same as a small value to keep in registers: a loop that stores through pointers the compiler
  /// cannot tell apart from this list's box would otherwise reload the box for every pair.
  struct MinimumImage {
    bool periodic_x, periodic_y;
    double Lx, Ly;
    Vec2 operator()(const Vec2& a, const Vec2& b) const {
      Vec2 d = a - b;
      if (periodic_x) d.x() -= Lx * std::nearbyint(d.x() / Lx);
      if (periodic_y) d.y() -= Ly * std::nearbyint(d.y() / Ly);
      return d;
    }
  };
  MinimumImage minimum_image() const { return {box_.periodic_x, box_.periodic_y, box_.Lx(), box_.Ly()}; }

  /// Calls f(j, d, r) for every particle j != i with r = |d| < radius, d = x_i - x_j (minimum image).
  /// `radius` must not exceed the radius the list was built for (the stencil would miss pairs): throws.
  /// A relative excess of 1e-12 (the same radius computed another way) is allowed: the cells have a
  /// 1e-9 margin (see the constructor).
  template <class F>
  void for_each_neighbour(const std::vector<Vec2>& x, std::size_t i, double radius, F&& f) const {
    const double r2max = checked_radius2(radius);
    for_each_stencil_cell(x[i], [&](std::size_t k0, std::size_t k1) {
      for (std::size_t k = k0; k < k1; ++k) {
        const std::size_t j = sorted_[k];
        if (j == i) continue;
        const Vec2 d = displacement(x[i], x[j]);
        const double r2 = d.squaredNorm();
        if (r2 >= r2max) continue;
        // r2 < radius^2 can hold (rounding) with sqrt(r2) == radius: test r itself, as promised.
        const double r = std::sqrt(r2);
        if (r < radius) f(j, d, r);
      }
    });
  }

  /// Appends to `out` the same particles j, in the same order, as for_each_neighbour visits, all of them or
  /// (upper_only) those with j > i; without a branch per candidate: about a third of the 3 x 3 cells'
  /// particles are within the radius, so the branches of for_each_neighbour are mispredicted often (the pair
  /// lists' collection). sqrt(r2) < radius, the test for_each_neighbour makes, is r2 <= the largest double
  /// whose correctly rounded square root is below the radius (sqrt is monotonic), found once per call.
  /// A cell's particles are in ascending index order (build's stable sort), so with upper_only the scan of a
  /// cell starts at its first particle above i (half the distance tests); and the positions are read from
  /// build's copy in cell order, contiguous, instead of through the index. `x` must be the positions of the
  /// last build (the cells would be stale otherwise).
  void append_neighbours(const std::vector<Vec2>& x, std::size_t i, double radius, std::vector<std::uint32_t>& out,
                         bool upper_only) const {
    const double r2_last = largest_r2_below(checked_radius2(radius), radius);
    const MinimumImage displacement = minimum_image();
    const Vec2 xi = x[i];
    const std::size_t* sorted = sorted_.data();
    const Vec2* xs = x_sorted_.data();
    for_each_stencil_cell(xi, [&](std::size_t k0, std::size_t k1) {
      if (upper_only) k0 = std::upper_bound(sorted + k0, sorted + k1, i) - sorted;
      std::size_t m = out.size();
      out.resize(m + (k1 - k0));
      std::uint32_t* o = out.data();
      std::size_t k = k0;
#if defined(__AVX512F__) && defined(__AVX512VL__)
      // Eight candidates at a time (a box without wrap): the same tests with the same numbers (x_i - x_j by
      // components, |d|^2 = x^2 + y^2 unfused, as Eigen's squaredNorm), the kept indices compress-stored in order.
      if (!displacement.periodic_x && !displacement.periodic_y) {
        const __m512d xv = _mm512_set1_pd(xi.x()), yv = _mm512_set1_pd(xi.y()), limit = _mm512_set1_pd(r2_last);
        const __m512i self = _mm512_set1_epi64(static_cast<long long>(i));
        const __m512i even = _mm512_setr_epi64(0, 2, 4, 6, 8, 10, 12, 14), odd = _mm512_setr_epi64(1, 3, 5, 7, 9, 11, 13, 15);
        constexpr int kAsIs = _MM_FROUND_CUR_DIRECTION;
        for (; k < k1; k += 8) {
          const unsigned count = k1 - k >= 8 ? 8u : static_cast<unsigned>(k1 - k);
          const __mmask8 live = static_cast<__mmask8>((1u << count) - 1u);
          const unsigned both = (1u << (2 * count)) - 1u;
          const __m512i j = _mm512_maskz_loadu_epi64(live, sorted + k);
          const double* p = xs[k].data();
          const __m512d lo = _mm512_maskz_loadu_pd(static_cast<__mmask8>(both), p);
          const __m512d hi = _mm512_maskz_loadu_pd(static_cast<__mmask8>(both >> 8), p + 8);
          const __m512d dx = _mm512_sub_pd(xv, _mm512_permutex2var_pd(lo, even, hi));
          const __m512d dy = _mm512_sub_pd(yv, _mm512_permutex2var_pd(lo, odd, hi));
          const __m512d r2 = _mm512_add_round_pd(_mm512_mul_round_pd(dx, dx, kAsIs), _mm512_mul_round_pd(dy, dy, kAsIs), kAsIs);
          const __mmask8 keep = live & _mm512_cmp_pd_mask(r2, limit, _CMP_LE_OQ) & _mm512_cmpneq_epi64_mask(j, self);
          _mm256_mask_compressstoreu_epi32(o + m, keep, _mm512_cvtepi64_epi32(j));
          m += static_cast<std::size_t>(__builtin_popcount(keep));
        }
      }
#endif
      for (; k < k1; ++k) {
        const std::size_t j = sorted[k];
        const bool in = (j != i) & (displacement(xi, xs[k]).squaredNorm() <= r2_last);
        o[m] = static_cast<std::uint32_t>(j);
        m += in;
      }
      out.resize(m);
    });
  }

  int cells_x() const { return nx_; }
  int cells_y() const { return ny_; }
  const Box2& box() const { return box_; }
  double radius() const { return radius_; }

 private:
  double checked_radius2(double radius) const {
    if (radius > radius_ * (1.0 + 1e-12)) throw_radius_too_large(radius);
    return radius * radius;
  }
  /// The largest r2 < r2max with sqrt(r2) < radius (r2max = radius^2).
  static double largest_r2_below(double r2max, double radius) {
    double t = std::nextafter(r2max, 0.0);
    while (t > 0 && !(std::sqrt(t) < radius)) t = std::nextafter(t, 0.0);
    return t;
  }
  /// f(k0, k1) for the sorted_ ranges of the cells of the stencil around position xi, in stencil order.
  template <class F>
  void for_each_stencil_cell(const Vec2& xi, F&& f) const {
    const int cx = cell_x(xi.x()), cy = cell_y(xi.y());
    for (int oy = -span_y_; oy <= span_y_; ++oy) {
      const int jy = wrap_or_skip(cy + oy, ny_, box_.periodic_y);
      if (jy < 0) continue;
      for (int ox = -span_x_; ox <= span_x_; ++ox) {
        const int jx = wrap_or_skip(cx + ox, nx_, box_.periodic_x);
        if (jx < 0) continue;
        const int c = jy * nx_ + jx;
        f(cell_start_[c], cell_start_[c + 1]);
      }
    }
  }
  int cell_x(double x) const { return cell_index(x, box_.xmin, box_.Lx(), nx_, box_.periodic_x); }
  int cell_y(double y) const { return cell_index(y, box_.ymin, box_.Ly(), ny_, box_.periodic_y); }
  static int cell_index(double v, double vmin, double L, int n, bool periodic) {
    double t = (v - vmin) / L;
    if (periodic) t -= std::floor(t);
    // Clamp before converting: a particle far outside a non-periodic box can have t * n beyond the range
    // of int, and converting that is undefined behaviour.
    const double c = std::floor(t * n);
    return c < 0 ? 0 : (c >= n ? n - 1 : static_cast<int>(c));
  }
  [[noreturn]] void throw_radius_too_large(double radius) const;
  // A periodic direction with fewer than 3 cells is scanned whole once (span 0 covers it: see ctor).
  static int wrap_or_skip(int c, int n, bool periodic) {
    if (c >= 0 && c < n) return c;
    if (!periodic) return -1;
    return ((c % n) + n) % n;
  }

  Box2 box_;
  double radius_;
  int nx_ = 1, ny_ = 1, span_x_ = 1, span_y_ = 1;
  std::vector<std::size_t> cell_start_, sorted_, cell_of_;
  std::vector<Vec2> x_sorted_;  ///< x[sorted_[k]]: the positions of the last build in cell order (append_neighbours)
};

// Inline here, with the class, so that reading a cell list's set-up and its refusals takes one file.
inline CellList2D::CellList2D(const Box2& box, double radius) : box_(box), radius_(radius) {
  if (!(radius > 0)) throw std::invalid_argument("CellList2D: search radius must be positive");
  if (!(box.Lx() > 0) || !(box.Ly() > 0)) throw std::invalid_argument("CellList2D: empty box");
  if ((box.periodic_x && radius > 0.5 * box.Lx()) || (box.periodic_y && radius > 0.5 * box.Ly()))
    throw std::invalid_argument("CellList2D: search radius " + std::to_string(radius) +
                                " exceeds half the period; the minimum image would miss neighbours");
  // Cells slightly wider than the radius: were the width exactly `radius` (e.g. L = 1, radius = 0.1), the
  // rounding in cell_index could put two particles a little closer than `radius` two cells apart, and the
  // 3-cell stencil would miss the pair. The 1e-9 margin covers rounding for positions up to ~1e6 cell
  // widths from the origin.
  const double width = radius * (1.0 + 1e-9);
  nx_ = std::max(1, static_cast<int>(std::floor(box.Lx() / width)));
  ny_ = std::max(1, static_cast<int>(std::floor(box.Ly() / width)));
  // With fewer than 3 cells in a periodic direction the 3-cell stencil would visit a cell twice:
  // scan that direction's cells once each instead.
  if (box.periodic_x && nx_ < 3) { span_x_ = 0; nx_ = 1; }
  if (box.periodic_y && ny_ < 3) { span_y_ = 0; ny_ = 1; }
  cell_start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
}

inline void CellList2D::throw_radius_too_large(double radius) const {
  throw std::invalid_argument("CellList2D: query radius " + std::to_string(radius) +
                              " exceeds the radius the list was built for, " + std::to_string(radius_));
}

/// All pairs (i, j != i) within `radius` by direct O(N^2) search: the reference the cell list is
/// tested against, and nothing else.
std::vector<std::vector<std::size_t>> brute_force_neighbours(const std::vector<Vec2>& x, const Box2& box,
                                                             double radius);

}  // namespace sph
