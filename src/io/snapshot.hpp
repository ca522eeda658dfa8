// The current state of any solver as an HDF5 snapshot (hdf5_snapshot.hpp): positions, velocities, densities
// and the in-plane Cauchy stress of its particles, read through the solver contract (core/run_loop.hpp).
#pragma once

#include "io/hdf5_snapshot.hpp"

namespace sph {

template <class Solver>
Snapshot snapshot_of(const Solver& s) {
  Snapshot sn;
  sn.time = s.time();
  sn.step = s.steps();
  const std::size_t n = s.size();
  for (auto* v : {&sn.sxx, &sn.syy, &sn.sxy, &sn.density}) v->reserve(n);
  sn.position.reserve(n);
  sn.velocity.reserve(n);
  for (std::size_t a = 0; a < n; ++a) {
    const Tensor2 T = s.stress(a);
    sn.position.push_back(s.position(a));
    sn.velocity.push_back(s.velocity(a));
    sn.density.push_back(s.density(a));
    sn.sxx.push_back(T(0, 0));
    sn.syy.push_back(T(1, 1));
    sn.sxy.push_back(T(0, 1));
  }
  return sn;
}

}  // namespace sph
