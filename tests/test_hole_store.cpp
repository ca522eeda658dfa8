// The sheet-with-a-hole runs in the store of runs (experiments/ismail2009/scenes/hole_store.hpp; issue 17: the
// resolution study's runs as jobs of their own): a stored run is served with every number of the stepped one,
// bit for bit; the key names every parameter; a run with snapshots is never served; the store is off without
// a directory.
#include <gtest/gtest.h>

#include <cstring>
#include <set>

#include "ismail2009/scenes/hole.hpp"
#include "ismail2009/scenes/hole_store.hpp"
#include "run_store_fixture.hpp"

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

scenes::HoleParams small_sheet() {
  scenes::HoleParams p;
  p.n = 11;
  p.settle = 1;
  return p;
}

class HoleStore : public RunStoreTest {
 protected:
  HoleStore() : RunStoreTest("hole_store") {}
};

TEST_F(HoleStore, AServedRunIsTheSteppedRunBitForBit) {
  const auto p = small_sheet();
  const auto stepped_alone = scenes::run_hole(p);  // store off
  EXPECT_FALSE(scenes::serve_hole_run(p).has_value());
  store_on();
  const auto stepped = scenes::run_hole(p);  // stored
  const auto served = scenes::serve_hole_run(p);
  ASSERT_TRUE(served.has_value());
  const auto via_run = scenes::run_hole(p);  // served by run_hole itself
  for (const auto* r : {&*served, &via_run, &stepped_alone}) {
    EXPECT_EQ(r->particles, stepped.particles);
    EXPECT_EQ(r->steps, stepped.steps);
    EXPECT_EQ(r->finite, stepped.finite);
    for (auto field : {&scenes::HoleResult::peak_sigma1, &scenes::HoleResult::sigma1_hole_top,
                       &scenes::HoleResult::peak_sigma1_dynamic, &scenes::HoleResult::smoothed_peak_sigma1,
                       &scenes::HoleResult::smoothed_sigma1_hole_top, &scenes::HoleResult::settle_change,
                       &scenes::HoleResult::zigzag, &scenes::HoleResult::speed_rise, &scenes::HoleResult::rest_speed_ratio,
                       &scenes::HoleResult::growth_rate})
      EXPECT_TRUE(same_bits(r->*field, stepped.*field));
    EXPECT_TRUE(same_bits(r->fastest_X.x(), stepped.fastest_X.x()) && same_bits(r->fastest_X.y(), stepped.fastest_X.y()));
    ASSERT_EQ(r->history.size(), stepped.history.size());
    for (std::size_t k = 0; k < r->history.size(); ++k) {
      const auto &a = r->history[k], &b = stepped.history[k];
      EXPECT_TRUE(same_bits(a.t, b.t) && same_bits(a.smoothed_top, b.smoothed_top) && same_bits(a.peak, b.peak) &&
                  same_bits(a.vmax, b.vmax)) << k;
    }
  }
  EXPECT_TRUE(same_bits(via_run.wall_s, stepped.wall_s));  // served: the stepping run's wall time, not 0 (plotted against n)
  EXPECT_GT(stepped.wall_s, 0.0);
  EXPECT_GT(stepped.history.size(), 10u);
}

TEST_F(HoleStore, RunsWithSnapshotsAreSteppedAndTheKeyNamesEveryParameter) {
  store_on();
  const auto p = small_sheet();
  int calls = 0;
  scenes::run_hole(p, {0.5}, [&](const sph::TlSolver2D&, double) { ++calls; });
  EXPECT_GT(calls, 0);
  EXPECT_FALSE(scenes::serve_hole_run(p).has_value());  // a run with snapshots is not stored
  // Changing any one parameter changes the key.
  std::set<std::string> keys{scenes::hole_run_key(p)};
  auto changed = [&](auto&& set) { auto q = p; set(q); keys.insert(scenes::hole_run_key(q)); };
  changed([](auto& q) { q.n = 12; });
  changed([](auto& q) { q.a *= 1.5; });
  changed([](auto& q) { q.R *= 1.5; });
  changed([](auto& q) { q.E *= 1.5; });
  changed([](auto& q) { q.nu = 0.3; });
  changed([](auto& q) { q.rho *= 1.5; });
  changed([](auto& q) { q.traction *= 1.5; });
  changed([](auto& q) { q.h_over_ps = 3.0; });
  changed([](auto& q) { q.dt_factor = 0.1; });
  changed([](auto& q) { q.ramp_transits = 3; });
  changed([](auto& q) { q.settle = 2; });
  changed([](auto& q) { q.damping = 2; });
  changed([](auto& q) { q.variational = true; });
  changed([](auto& q) { q.hourglass = 0.01; });
  changed([](auto& q) { q.hooke = true; });
  changed([](auto& q) { q.closure_passes = 2; });
  EXPECT_EQ(keys.size(), 17u);
  store_off();
  EXPECT_FALSE(scenes::serve_hole_run(p).has_value());  // off without a directory
}

}  // namespace
