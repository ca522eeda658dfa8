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
// size.
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
  long collections = 0;              ///< how often the candidates were re-collected (diagnostics)
  /// Every pair once, in the row of its lower index (b > a), for formulations that add a pair's terms to
  /// both of its particles; otherwise every pair twice (a->b and b->a), for those that gather.
  bool half = false;

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
        b.resize(total);
        dx.resize(total);
        W.resize(total);
        F.resize(total);
        active.resize(n);
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
    const std::uint32_t* __restrict start_ = start.data();
    const std::uint32_t* __restrict cand_ = cand.data();
    const Vec2* __restrict x_ = x.data();
    std::uint32_t* __restrict b_ = b.data();
    Vec2* __restrict dx_ = dx.data();
    double* __restrict W_ = W.data();
    double* __restrict F_ = F.data();
    std::uint32_t* __restrict active_ = active.data();
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
    for (long a = 0; a < n; ++a) {
      std::uint32_t j = start_[a];
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
        ++j;
      }
      active_[a] = j - start_[a];
    }
  }

  std::vector<Vec2> x_collected_;
  std::vector<std::vector<std::uint32_t>> buffers_;  ///< per thread: the candidates of its rows (collect)
};

}  // namespace sph
