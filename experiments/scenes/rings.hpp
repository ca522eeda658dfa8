// Two rubber rings on a square grid moving toward each other (Gray, Monaghan & Swift 2001 Section 7.2;
// the same layout as PySPH's examples/solid_mech/rings.py, which the benchmark compares against).
#pragma once

#include "elastic_body.hpp"
#include "neighbours.hpp"

namespace scenes {

struct RingsSpec {
  double r_inner = 3.0, r_outer = 4.0;  ///< Gray 2001 Section 7.2
  double dp = 0.1;                      ///< Gray 2001: 0.1; PySPH's rings example: 0.05 (17 592 particles)
  double gap = 0.2;                     ///< distance between the outer edges at t = 0 (PySPH: 0.2)
  double speed = 0.059;                 ///< each ring's speed toward the other / c0
  double rho0 = 1.0;
};

struct Rings {
  sph::ElasticBody body;
  sph::Box2 box;
};

/// Square-grid points x = -r_outer + i dp (as numpy.mgrid[-ro:ro:dx] in PySPH's example) with
/// r_inner^2 <= |x|^2 < r_outer^2, one ring left of the other, velocities +-speed along x.
Rings make_rings(const RingsSpec& s);

}  // namespace scenes
