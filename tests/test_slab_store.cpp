// The slab runs in the store of runs (experiments/gray2001/scenes/slab_store.hpp; issue 17: the runs of Figs 8-10
// as jobs of their own): a stored run is served with every number of the stepped one and the bytes of its files,
// bit for bit; the key names every parameter and the files the observer wrote; the store is off without a directory.
#include <gtest/gtest.h>

#include <cstring>
#include <set>

#include "gray2001/scenes/slab.hpp"
#include "gray2001/scenes/slab_store.hpp"
#include "run_store_fixture.hpp"

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

scenes::SlabRunSpec small_slab() {
  scenes::SlabRunSpec s;
  s.slab.dp = 0.1;
  s.t_max = 20;
  s.sample_dt = 2;
  return s;
}

class SlabStore : public RunStoreTest {
 protected:
  SlabStore() : RunStoreTest("slab_store") {}
};

TEST_F(SlabStore, AServedRunIsTheStoredRunBitForBit) {
  const auto s = small_slab();
  scenes::StoredSlabRun run;
  run.result = scenes::run_slab(s);
  run.files = {{"frames_eps0.3.csv", "t,x\n1,2\n"}, {"snapshots_eps0.3.h5", std::string("\0\x01\xff binary", 10)}};
  scenes::store_slab_run(s, "frames", run);  // store off: nothing kept
  EXPECT_FALSE(scenes::serve_slab_run(s, "frames").has_value());
  store_on();
  scenes::store_slab_run(s, "frames", run);
  EXPECT_FALSE(scenes::serve_slab_run(s, "none").has_value());  // another observer's files: another run
  const auto served = scenes::serve_slab_run(s, "frames");
  ASSERT_TRUE(served.has_value());
  const auto &a = served->result, &b = run.result;
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.particles, b.particles);
  EXPECT_EQ(a.blow_up, b.blow_up);
  for (auto f : {&scenes::SlabRunResult::dt, &scenes::SlabRunResult::wall_s, &scenes::SlabRunResult::first_split_time,
                 &scenes::SlabRunResult::fracture_time, &scenes::SlabRunResult::crack_x,
                 &scenes::SlabRunResult::crack_from_junction, &scenes::SlabRunResult::neck_before_fracture,
                 &scenes::SlabRunResult::onset_strain, &scenes::SlabRunResult::onset_time, &scenes::SlabRunResult::clumping_time,
                 &scenes::SlabRunResult::opening_time, &scenes::SlabRunResult::opening_from_junction})
    EXPECT_TRUE(same_bits(a.*f, b.*f));
  ASSERT_EQ(a.trace.size(), b.trace.size());
  ASSERT_GT(b.trace.size(), 5u);
  for (std::size_t k = 0; k < a.trace.size(); ++k) {
    const auto &x = a.trace[k], &y = b.trace[k];
    for (auto f : {&scenes::SlabSample::t, &scenes::SlabSample::extension, &scenes::SlabSample::strain, &scenes::SlabSample::ke,
                   &scenes::SlabSample::ee, &scenes::SlabSample::neck_width, &scenes::SlabSample::neck_x,
                   &scenes::SlabSample::median_width, &scenes::SlabSample::closest, &scenes::SlabSample::widest_gap,
                   &scenes::SlabSample::gap_x})
      EXPECT_TRUE(same_bits(x.*f, y.*f)) << k;
    EXPECT_EQ(x.pieces, y.pieces);
    EXPECT_EQ(x.parted, y.parted);
  }
  EXPECT_EQ(served->files, run.files);
  EXPECT_GT(b.wall_s, 0.0);  // served: the stepping run's wall time
}

TEST_F(SlabStore, TheKeyNamesEveryParameter) {
  const auto s = small_slab();
  std::set<std::string> keys{scenes::slab_run_key(s, "none")};
  std::size_t expected = 1;
  auto changed = [&](auto&& set) { auto q = s; set(q); keys.insert(scenes::slab_run_key(q, "none")); ++expected; };
  changed([](auto& q) { q.slab.L = 2; });
  changed([](auto& q) { q.slab.H = 2; });
  changed([](auto& q) { q.slab.dp = 0.05; });
  changed([](auto& q) { q.slab.band = 0.3; });
  changed([](auto& q) { q.slab.end_accel = 5e-6; });
  changed([](auto& q) { q.slab.margin = 3; });
  changed([](auto& q) { q.slab.jitter = 0.01; });
  changed([](auto& q) { q.slab.seed = 7; });
  changed([](auto& q) { q.scheme.mu = 0.5; });
  changed([](auto& q) { q.scheme.cfl = 0.25; });
  changed([](auto& q) { q.scheme.yield_stress = 0.05; });
  changed([](auto& q) { q.scheme.eps_artificial = 0; });
  changed([](auto& q) { q.options.artificial_stress = false; });
  changed([](auto& q) { q.options.plasticity = false; });
  changed([](auto& q) { q.t_max = 30; });
  changed([](auto& q) { q.run_after_fracture = -1; });
  changed([](auto& q) { q.sample_dt = 1; });
  changed([](auto& q) { q.fracture_link = 1.2; });
  changed([](auto& q) { q.neck_bin = 3; });
  changed([](auto& q) { q.neck_ratio_onset = 0.8; });
  changed([](auto& q) { q.clump_ratio = 0.5; });
  changed([](auto& q) { q.opening_gap = 3; });
  keys.insert(scenes::slab_run_key(s, "frames"));
  ++expected;
  EXPECT_EQ(keys.size(), expected);
}

}  // namespace
