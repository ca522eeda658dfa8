// What every solver throws when its state stops being physical (non-finite values, a vanishing density,
// speeds far beyond the signal speed): a message naming the step, the time and the first bad particle, in
// one format for all formulations. The run loop (run_loop.hpp) turns it into the outcome of a run.
#pragma once

#include <algorithm>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/parallel.hpp"
#include "core/types.hpp"

namespace sph {

struct BlowUp : std::runtime_error {
  BlowUp(const std::string& message, long step, double time, std::size_t particle)
      : std::runtime_error(message), step(step), time(time), particle(particle) {}
  long step;
  double time;
  std::size_t particle;
};

/// Throws "blow-up at step <step>, t = <time>, particle <particle> at (<x>, <y>): <what>".
[[noreturn]] inline void throw_blow_up(long step, double time, std::size_t particle, const Vec2& at, const std::string& what) {
  std::ostringstream msg;
  msg << "blow-up at step " << step << ", t = " << time << ", particle " << particle << " at (" << at.x() << ", "
      << at.y() << "): " << what;
  throw BlowUp(msg.str(), step, time, particle);
}

/// The first index i < n for which bad(i) holds, or n; a parallel reduction from parallel_from particles (a
/// caller whose other per-step loops stay serial longer passes its own threshold: the fork and join of a
/// region would otherwise be most of a cheap check).
template <class Bad>
std::size_t first_bad_particle(std::size_t n, Bad&& bad, long parallel_from = kParallelMin) {
  // Whether any particle is bad first: an OR over the particles vectorises where the search for the first index
  // does not (a check that runs three times a step), and the search runs only after a blow-up.
  int any = 0;
#pragma omp parallel for reduction(| : any) schedule(static) if (static_cast<long>(n) >= parallel_from)
  for (std::size_t a = 0; a < n; ++a) any |= static_cast<int>(bad(a));
  if (!any) return n;
  std::size_t first = n;
  for (std::size_t a = 0; a < n && first == n; ++a)
    if (bad(a)) first = a;
  return first;
}

}  // namespace sph
