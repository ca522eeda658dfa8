// The time loop the ring and slab runs share: step to t_max, measure every sample_dt (and at t = 0), stop
// early when the measurement says so, and turn a blow-up into a message instead of an exception, so that
// a run that blows up still returns its trace (the stability sweeps record where it stopped).
#pragma once

#include <algorithm>
#include <string>

#include "gray_solver.hpp"
#include "progress.hpp"

namespace scenes {

/// Steps `solver` at `dt` until `t_max`; calls `sample()` at t = 0 and every `sample_dt`, and stops after a
/// sample for which `stop()` is true. Returns the blow-up message ("" if the run went through).
template <class Sample, class Stop>
std::string run_sampled(sph::GraySolver& solver, double dt, double t_max, double sample_dt, Sample&& sample, Stop&& stop,
                        sph::Progress& progress) {
  sample();
  double next_sample = sample_dt;
  try {
    while (solver.time() < t_max - 1e-12) {
      solver.step(std::min(dt, t_max - solver.time()));
      if (solver.time() >= next_sample - 1e-12) {
        next_sample += sample_dt;
        sample();
        if (stop()) break;
      }
      progress.update(solver.time(), solver.steps());
    }
  } catch (const sph::BlowUp& e) {
    return e.what();
  }
  return "";
}

}  // namespace scenes
