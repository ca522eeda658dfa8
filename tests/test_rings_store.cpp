// The rings' runs in the store of runs (experiments/gray2001/scenes/rings_store.hpp; issue 17: the stability sweeps'
// points as jobs of their own): a stored run is served with every number of the stepped one, bit for bit; the key
// names every parameter; the store is off without a directory.
#include <gtest/gtest.h>

#include <cstring>
#include <set>

#include "gray2001/scenes/rings_store.hpp"
#include "run_store_fixture.hpp"

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

scenes::RingsRunSpec small_rings() {
  scenes::RingsRunSpec s;
  s.rings.dp = 0.4;
  s.rings.gap = 0.8;
  s.rings.speed = 0.2;  // contact within the run
  s.t_max = 12;
  s.run_after_contact = -1;
  return s;
}

class RingsStore : public RunStoreTest {
 protected:
  RingsStore() : RunStoreTest("rings_store") {}
};

TEST_F(RingsStore, AServedRunIsTheSteppedRunBitForBit) {
  const auto s = small_rings();
  const auto stepped = scenes::run_rings(s);
  ASSERT_GT(stepped.trace.size(), 5u);
  scenes::run_rings_stored(s, "rings");  // store off: nothing kept
  store_on();
  const auto first = scenes::run_rings_stored(s, "rings");
  const auto served = scenes::run_rings_stored(s, "rings");
  EXPECT_EQ(served.steps, stepped.steps);
  EXPECT_EQ(served.particles, stepped.particles);
  EXPECT_EQ(served.blow_up, stepped.blow_up);
  EXPECT_EQ(served.max_fragments, stepped.max_fragments);
  EXPECT_EQ(served.max_stray, stepped.max_stray);
  for (auto f : {&scenes::RingsRunResult::dt, &scenes::RingsRunResult::contact_start, &scenes::RingsRunResult::contact_end,
                 &scenes::RingsRunResult::rebound_speed, &scenes::RingsRunResult::restitution,
                 &scenes::RingsRunResult::fracture_time, &scenes::RingsRunResult::min_main_share})
    EXPECT_TRUE(same_bits(served.*f, stepped.*f));
  EXPECT_TRUE(same_bits(served.wall_s, first.wall_s));  // the stepping run's time
  ASSERT_EQ(served.trace.size(), stepped.trace.size());
  int contact = 0;
  for (std::size_t k = 0; k < served.trace.size(); ++k) {
    const auto &x = served.trace[k], &y = stepped.trace[k];
    for (auto f : {&scenes::RingsSample::t, &scenes::RingsSample::ke, &scenes::RingsSample::ke_com, &scenes::RingsSample::ee,
                   &scenes::RingsSample::v_left, &scenes::RingsSample::v_right, &scenes::RingsSample::x_left,
                   &scenes::RingsSample::x_right, &scenes::RingsSample::min_distance, &scenes::RingsSample::main_share})
      EXPECT_TRUE(same_bits(x.*f, y.*f)) << k;
    EXPECT_EQ(x.contact, y.contact) << k;
    EXPECT_EQ(x.fragments_left, y.fragments_left) << k;
    EXPECT_EQ(x.fragments_right, y.fragments_right) << k;
    EXPECT_EQ(x.stray, y.stray) << k;
    contact += x.contact;
  }
  EXPECT_GT(contact, 0);  // the test run reaches the collision
}

TEST_F(RingsStore, OffWithoutADirectoryAndTheKeyNamesEveryParameter) {
  const auto s = small_rings();
  scenes::run_rings_stored(s, "rings");
  EXPECT_FALSE(std::filesystem::exists(dir_));
  std::set<std::string> keys{scenes::rings_run_key(s)};
  std::size_t expected = 1;
  auto changed = [&](auto&& set) { auto q = s; set(q); keys.insert(scenes::rings_run_key(q)); ++expected; };
  changed([](auto& q) { q.rings.r_inner = 2.5; });
  changed([](auto& q) { q.rings.r_outer = 4.5; });
  changed([](auto& q) { q.rings.dp = 0.2; });
  changed([](auto& q) { q.rings.gap = 0.4; });
  changed([](auto& q) { q.rings.speed = 0.059; });
  changed([](auto& q) { q.scheme.mu = 0.3; });
  changed([](auto& q) { q.scheme.cfl = 0.25; });
  changed([](auto& q) { q.scheme.eps_artificial = 0; });
  changed([](auto& q) { q.options.artificial_stress = false; });
  changed([](auto& q) { q.t_max = 13; });
  changed([](auto& q) { q.run_after_contact = 60; });
  changed([](auto& q) { q.sample_dt = 0.5; });
  changed([](auto& q) { q.fracture_link = 1.2; });
  changed([](auto& q) { q.min_fragment = 5; });
  EXPECT_EQ(keys.size(), expected);
}

}  // namespace
