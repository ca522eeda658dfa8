// One time loop for every solver of the library. The solver contract (GraySolver, SpamSolver, MdSolver,
// TlSolver1D, TlSolver2D):
//   void step(double dt)   one step; throws BlowUp (blow_up.hpp) when the state stops being physical
//   double time() const, long steps() const
//   size(), mass(i), position(i), velocity(i), density(i), stress(i)   what diagnostics (diagnostics.hpp)
//                          and snapshots (io/snapshot.hpp) read
// run(solver, plan, observe, progress) steps until the plan says stop, calls observe(solver) once before the
// first step and after every step (it returns true to end the run early; when to sample is its business:
// see Cadence), progress(solver) after every step, and returns how the run ended, a blow-up included: a
// run that blows up still returns (with the message), so that sweeps record where it stopped.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/blow_up.hpp"

namespace sph {

/// When a run stops: after `steps` steps (if >= 0), or at `t_end`. By default the last step is shortened
/// to land on t_end (a time within 1e-12 of it counts as reached); with whole_steps every step is dt and
/// the run stops at the first time >= t_end.
struct RunPlan {
  double dt = 0;
  long steps = -1;
  double t_end = std::numeric_limits<double>::infinity();
  bool whole_steps = false;
};

struct RunOutcome {
  long steps = 0;         ///< steps taken by this run
  bool stopped = false;   ///< the observer ended it
  std::string blow_up;    ///< the BlowUp message ("" when the run went through)
  double wall_s = 0;      ///< wall time of the loop
  bool blew_up() const { return !blow_up.empty(); }
};

/// Sampling at the first call and then every `interval` of simulated time: due(t) is true at the first
/// call and whenever t has reached the next sample time (within 1e-12), which then moves on by interval.
class Cadence {
 public:
  explicit Cadence(double interval) : interval_(interval) {}
  bool due(double t) {
    if (first_) { first_ = false; return true; }
    if (t < next_ - 1e-12) return false;
    next_ += interval_;
    return true;
  }

 private:
  double interval_, next_ = interval_;
  bool first_ = true;
};

struct NoProgress {
  template <class Solver>
  void operator()(const Solver&) const {}
};

/// Particle-steps taken by every run() of the process so far (summed over threads): the work column of the
/// timing table the driver frame writes (experiments/frame/driver.cpp).
inline std::atomic<long long>& particle_steps_taken() {
  static std::atomic<long long> total{0};
  return total;
}

template <class Solver, class Observe, class Progress = NoProgress>
RunOutcome run(Solver& solver, const RunPlan& plan, Observe&& observe, Progress&& progress = {}) {
  if (!(plan.dt > 0)) throw std::invalid_argument("run: the time step must be positive");
  RunOutcome out;
  const auto start = std::chrono::steady_clock::now();
  try {
    out.stopped = observe(static_cast<const Solver&>(solver));
    while (!out.stopped) {
      if (plan.steps >= 0 && out.steps >= plan.steps) break;
      double dt = plan.dt;
      if (plan.whole_steps) {
        if (!(solver.time() < plan.t_end)) break;
      } else {
        if (!(solver.time() < plan.t_end - 1e-12)) break;
        dt = std::min(dt, plan.t_end - solver.time());
      }
      ++out.steps;  // counted before the step, so that a step that blows up counts
      solver.step(dt);
      out.stopped = observe(static_cast<const Solver&>(solver));
      progress(static_cast<const Solver&>(solver));
    }
  } catch (const BlowUp& e) {
    out.blow_up = e.what();
  }
  out.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  particle_steps_taken() += static_cast<long long>(solver.size()) * out.steps;
  return out;
}

}  // namespace sph
