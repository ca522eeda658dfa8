// The largest stable time step (or time-step factor) of a scene, measured: the step doubled from the scene's own
// until a run fails, then bisected between the last stable and the first failing step to a relative width. The
// margin rows of H-wp and I-hole (issue 43 item 6: every scene's step against its measured limit).
#pragma once

#include <stdexcept>

namespace sph {

struct StabilityLimit {
  double stable = 0;   ///< largest step of the bisection whose run survived
  double failing = 0;  ///< smallest step of the bisection whose run failed
};

/// `stable(step)` runs the scene at `step` and says whether it survived. `start` (the scene's own step) must be
/// stable; a scene still stable at 1000 x start is refused, as is a failing start.
template <class Stable>
StabilityLimit largest_stable_step(double start, double relative_width, Stable&& stable) {
  if (!(start > 0) || !(relative_width > 0)) throw std::invalid_argument("stability limit: need start, width > 0");
  if (!stable(start)) throw std::runtime_error("stability limit: the scene's own step fails: no margin to measure");
  double lo = start, hi = 2 * start;
  while (stable(hi)) {
    lo = hi;
    hi *= 2;
    if (hi > 1e3 * start) throw std::runtime_error("stability limit: no failing step below 1000 x the scene's own");
  }
  while (hi - lo > relative_width * lo) {
    const double mid = 0.5 * (lo + hi);
    (stable(mid) ? lo : hi) = mid;
  }
  return {lo, hi};
}

}  // namespace sph
