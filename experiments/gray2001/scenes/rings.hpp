// Two rubber rings on a square grid moving toward each other (Gray, Monaghan & Swift 2001 Section 7.2;
// the same layout as PySPH's examples/solid_mech/rings.py, which the benchmark compares against).
// When r_outer is a multiple of dp (the paper's 0.1 and PySPH's 0.05) the grid passes through each ring's
// centre (points i dp, j dp from it with r_inner <= r < r_outer), so
// each ring has the square lattice's mirror and 90-degree symmetry, as a "grid of square cells" in the
// paper: 4406 particles in the two rings at dp = 0.1, 17 582 at PySPH's dp = 0.05 (PySPH's example reports
// 17 592, likely because grid points lying exactly on r = 3 or r = 4 round to either side of the test).
#pragma once

#include "updated_lagrangian/elastic_body.hpp"
#include "core/neighbours.hpp"

namespace scenes {

struct RingsSpec {
  double r_inner = 3.0, r_outer = 4.0;  ///< Gray 2001 Section 7.2
  double dp = 0.1;                      ///< Gray 2001: 0.1; PySPH's rings example: 0.05
  double gap = 0.2;                     ///< distance between the outer edges at t = 0 (PySPH: 0.2)
  double speed = 0.059;                 ///< each ring's speed toward the other / c0
};

struct Rings {
  sph::ElasticBody body;
  std::size_t first_right = 0;  ///< particles [0, first_right) are the left ring (moving +x), the rest the right
};

/// Square-grid points x = -r_outer + i dp (as numpy.mgrid[-ro:ro:dx] in PySPH's example) with
/// r_inner^2 <= |x|^2 < r_outer^2, one ring left of the other, velocities +-speed along x.
/// Refuses (std::invalid_argument, before anything is allocated) a rings whose particles cannot fit in memory
/// (sph::check_particle_count); make_rings calls it, and a driver that runs several scenes calls it for each
/// before its first run, so that a spacing typed wrong stops at once, not after the other scenes.
void check_size(const RingsSpec& s);
Rings make_rings(const RingsSpec& s, double rho0);

}  // namespace scenes
