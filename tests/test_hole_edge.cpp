// Issue 15 (b): the sheet's mass-proportional damping is chosen as the least that holds the ghost-reflection
// closure's corner mode at the finest resolution, twice its undamped growth rate, with 10% (ismail2009/scenes/hole.hpp; the
// I-hole row damping_over_least_finest). That rests on damping c taking c/2 off the mode's rate: u'' = J u - c u'
// has the roots s = -c/2 +- sqrt(lambda + c^2/4), so Re s = rate - c/2 + c^2 rate / (8 |lambda|) + ..., a correction
// of ~1e-3 omega here. Tested on the resolution driver's linear edge run (Hooke, 1% of the load, no control,
// 12/omega) at 41 per side, undamped and damped, to within the 10% the production damping carries: the rate is
// measured as d ln(largest speed)/dt over the last 3/omega, which also sees the neighbouring modes.
// Noticed: at 21 per side the shift is 10-13% below c/2 (the production damping is 3x what 21 needs); and with
// c >= 2 rate the largest speed no longer follows the corner mode but a slow drift on the symmetry line above
// the hole, which mass-proportional damping cannot hold (the zero-energy-mode control does), so "held" is
// tested in the production runs instead (I-hole's speed_rise_finest).
#include <gtest/gtest.h>
#include <omp.h>

#include "ismail2009/scenes/hole.hpp"

namespace {

scenes::HoleParams linear_edge(double damping) {
  scenes::HoleParams q;
  q.n = 41;
  q = scenes::linear_edge_run(q);
  q.damping = damping;
  return q;
}

TEST(HoleEdgeMode, MassProportionalDampingTakesHalfOfItOffTheCornerModesRate) {
  // One thread: the sheet of 41 x 41 gains nothing from two (2.5 s either way, twice the CPU), and ctest runs the
  // tests side by side, where a second thread per test only oversubscribes the cores (31 s in CI's ctest with two).
  omp_set_num_threads(1);
  const auto free = scenes::run_hole(linear_edge(0.0));
  ASSERT_TRUE(free.finite);
  ASSERT_GT(free.growth_rate, 1.0);  // the mode is there to be damped (1.48 omega at 41 per side)
  const double c = 2.0;  // below 2 x rate: the corner mode still dominates the largest speed
  const auto damped = scenes::run_hole(linear_edge(c));
  ASSERT_TRUE(damped.finite);
  EXPECT_NEAR(free.growth_rate - damped.growth_rate, c / 2, 0.1 * c / 2);
}

}  // namespace
