// When a loop over particles runs in parallel. Below kParallelMin particles an OpenMP region costs more
// than it saves (the 217-particle hexagon; the 72-variant sweep parallelises over whole runs instead), so
// the per-particle loops of the library carry `if (n >= kParallelMin)`. A loop whose particles are
// independent gives the same result either way.
#pragma once

#include <cstddef>

namespace sph {

inline constexpr long kParallelMin = 1000;

/// Rows [begin, end) of thread t of T: the partition of OpenMP's schedule(static) in libgomp (the first
/// n % T threads take one row more), for a parallel region that splits its rows itself (the Gray pair loop:
/// the sums keep the order they had under `omp for`; the pair lists' collection: each thread's rows are one block).
inline void static_rows(std::size_t n, int t, int T, std::size_t& begin, std::size_t& end) {
  std::size_t q = n / T, r = n % T;
  if (static_cast<std::size_t>(t) < r) { ++q; r = 0; }
  begin = q * t + r;
  end = begin + q;
}

}  // namespace sph
