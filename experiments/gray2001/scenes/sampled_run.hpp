// What the plate, ring and slab runs share: the solver parameters from a run spec, and the time loop that
// steps to t_max, measures every sample_dt (and at t = 0), stops early when the measurement says so, and
// turns a blow-up into a message instead of an exception, so that a run that blows up still returns its
// trace (the stability sweeps record where it stopped).
#pragma once

#include <algorithm>
#include <string>

#include "updated_lagrangian/gray_solver.hpp"
#include "frame/progress.hpp"

namespace scenes {

/// The scheme's parameters from a run spec's fields (mu, h_over_dp, eps_artificial, n_artificial, alpha,
/// beta) for a scene of spacing dp and reference density rho0 in the cell-list box `box`.
template <class RunSpec>
sph::GrayParameters gray_parameters(const RunSpec& s, double rho0, double dp, const sph::Box2& box) {
  sph::GrayParameters p;
  p.rho0 = rho0;
  p.mu = s.mu;
  p.dp = dp;
  p.h = s.h_over_dp * dp;
  p.eps_artificial = s.eps_artificial;
  p.n_artificial = s.n_artificial;
  p.alpha = s.alpha;
  p.beta = s.beta;
  p.box = box;
  return p;
}

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
