// Work done once (experiments/gray2001/scenes/plate_run_cache.hpp): a plate run served from a stored longer
// run of the same key gives the numbers stepping gives, bit for bit; a run the store cannot hold is stepped.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "gray2001/scenes/plate_run.hpp"
#include "gray2001/scenes/plate_run_cache.hpp"
#include "run_store_fixture.hpp"

namespace {

// A short, coarse plate: L = 5 oscillates 16x faster than the tables' L = 20.
scenes::PlateRunSpec short_plate(int crossings) {
  scenes::PlateRunSpec s;
  s.plate.L = 5.0;
  s.plate.H = 1.0;
  s.plate.dp = 0.25;
  s.plate.clamp_length = 1.0;
  s.plate.Vf = 0.05;
  s.t_end = 2000;
  s.sample_dt = 0.5;
  s.fracture_check_dt = 10;
  s.stop_after_crossings = crossings;
  return s;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_identical(const scenes::PlateRunResult& a, const scenes::PlateRunResult& b) {
  ASSERT_EQ(a.trace.size(), b.trace.size());
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.particles, b.particles);
  EXPECT_TRUE(same_bits(a.dt, b.dt));
  EXPECT_TRUE(same_bits(a.fracture_time, b.fracture_time));
  for (std::size_t k = 0; k < a.trace.size(); ++k) {
    const auto &x = a.trace[k], &y = b.trace[k];
    EXPECT_TRUE(same_bits(x.t, y.t) && same_bits(x.y, y.y) && same_bits(x.ke, y.ke) && same_bits(x.ee, y.ee)) << k;
    EXPECT_EQ(x.fragments, y.fragments) << k;
    EXPECT_EQ(std::isnan(x.p_art), std::isnan(y.p_art)) << k;
    if (!std::isnan(x.p_art)) {
      EXPECT_TRUE(same_bits(x.p_art, y.p_art) && same_bits(x.p_visc, y.p_visc)) << k;
    }
  }
}

class PlateRunCache : public RunStoreTest {
 protected:
  PlateRunCache() : RunStoreTest("plate_cache") {}
};

}  // namespace

TEST_F(PlateRunCache, AServedPrefixIsTheSteppedRunBitForBit) {
  store_off();
  const auto stepped = scenes::run_plate(short_plate(1));
  ASSERT_FALSE(stepped.reused);
  ASSERT_TRUE(stepped.blow_up.empty());
  ASSERT_GT(stepped.steps, 100);

  store_on();
  const auto longer = scenes::run_plate(short_plate(3));  // stepped, and stored
  EXPECT_FALSE(longer.reused);
  EXPECT_GT(longer.steps, stepped.steps);
  const auto served = scenes::run_plate(short_plate(1));
  EXPECT_TRUE(served.reused);
  // A prefix reports the stepping run's time loop up to its last sample: measured, within the longer run's time.
  EXPECT_GT(served.wall_s, 0.0);
  EXPECT_LE(served.wall_s, longer.wall_s);
  expect_identical(served, stepped);
  EXPECT_EQ(scenes::period_from_crossings(scenes::zero_crossings(served.trace)),
            scenes::period_from_crossings(scenes::zero_crossings(stepped.trace)));
}

TEST_F(PlateRunCache, RunsTheStoreCannotHoldAreStepped) {
  store_on();
  scenes::run_plate(short_plate(2));
  EXPECT_TRUE(scenes::run_plate(short_plate(2)).reused);  // the same run again: all of it stored
  EXPECT_FALSE(scenes::run_plate(short_plate(4)).reused);  // longer than the store
  auto other_mu = short_plate(1);
  other_mu.scheme.mu = 0.3;
  EXPECT_FALSE(scenes::run_plate(other_mu).reused);  // another key
  auto other_sampling = short_plate(1);
  other_sampling.sample_dt = 1.0;
  EXPECT_FALSE(scenes::run_plate(other_sampling).reused);
  auto budget = short_plate(1);
  budget.power_budget = true;  // the stored runs did not record it
  const auto with_budget = scenes::run_plate(budget);
  EXPECT_FALSE(with_budget.reused);
  EXPECT_FALSE(std::isnan(with_budget.trace.back().p_art));
  EXPECT_TRUE(scenes::run_plate(budget).reused);  // now it is stored
  auto early_end = short_plate(4);
  early_end.t_end = 10;  // stops at t_end before its crossings: its last step is shortened, never served
  EXPECT_FALSE(scenes::run_plate(early_end).reused);
  auto limited = short_plate(1);
  limited.max_steps = 50;
  EXPECT_FALSE(scenes::run_plate(limited).reused);
}

TEST_F(PlateRunCache, StoringRemovesTheRunsOfOtherCodeVersions) {
  std::filesystem::create_directories(dir_);
  const auto stale = dir_ / "plate-0.run", foreign = dir_ / "notes.txt";
  std::ofstream(stale) << "sph-plate-run-1\ncode 0123abc isa base threads 1 plate ...\n";
  std::ofstream(foreign) << "not a stored run\n";
  store_on();
  scenes::run_plate(short_plate(1));
  EXPECT_FALSE(std::filesystem::exists(stale));
  EXPECT_TRUE(std::filesystem::exists(foreign));  // only the store's own files
  EXPECT_TRUE(scenes::run_plate(short_plate(1)).reused);  // this version's run stays
}

TEST_F(PlateRunCache, OffWithoutADirectoryAndTheKeyNamesEveryParameter) {
  store_off();
  scenes::run_plate(short_plate(1));
  EXPECT_FALSE(scenes::run_plate(short_plate(1)).reused);
  EXPECT_FALSE(std::filesystem::exists(dir_));
  const auto base = scenes::plate_run_key(short_plate(1));
  EXPECT_EQ(base, scenes::plate_run_key(short_plate(5)));  // the stop is not part of the trajectory
  auto s = short_plate(1);
  s.scheme.cfl = 0.25;
  EXPECT_NE(base, scenes::plate_run_key(s));
  s = short_plate(1);
  s.options.xsph = false;
  EXPECT_NE(base, scenes::plate_run_key(s));
  s = short_plate(1);
  s.plate.seed = 2;
  EXPECT_NE(base, scenes::plate_run_key(s));
  s = short_plate(1);
  s.scheme.mu = std::nextafter(s.scheme.mu, 1.0);  // one bit
  EXPECT_NE(base, scenes::plate_run_key(s));
}

// A sweep point (G-stab) stops at a fracture, a blow-up or t_end: the prefix store cannot serve it, the whole-run
// store does, with every number of the stepped run and its message.
TEST_F(PlateRunCache, AWholeRunIsServedBitForBitUnderTheKeyOfItsStop) {
  auto point = short_plate(-1);
  point.t_end = 30;
  point.run_after_fracture = 0;
  point.scheme.cfl = 3.0;  // far past the plate's stable factor (1.25): it blows up or breaks before t_end
  store_off();
  const auto stepped = scenes::run_plate_stored(point, "point");
  EXPECT_FALSE(stepped.reused);
  EXPECT_TRUE(!stepped.blow_up.empty() || stepped.fracture_time >= 0);
  EXPECT_FALSE(scenes::run_plate_stored(point, "point").reused);  // the store is off
  store_on();
  const auto first = scenes::run_plate_stored(point, "point");
  EXPECT_FALSE(first.reused);
  const auto served = scenes::run_plate_stored(point, "point");
  EXPECT_TRUE(served.reused);
  expect_identical(served, stepped);
  EXPECT_EQ(served.blow_up, stepped.blow_up);
  EXPECT_TRUE(same_bits(served.wall_s, first.wall_s));  // the stepping run's time
  EXPECT_FALSE(scenes::run_plate(point).reused);          // not a run the prefix store holds
  // Every field that decides where a run stops is in the whole-run key (not in the trajectory's).
  const auto base = scenes::plate_whole_run_key(point);
  auto s = point;
  s.t_end = 31;
  EXPECT_NE(base, scenes::plate_whole_run_key(s));
  s = point;
  s.max_steps = 10;
  EXPECT_NE(base, scenes::plate_whole_run_key(s));
  s = point;
  s.run_after_fracture = 1;
  EXPECT_NE(base, scenes::plate_whole_run_key(s));
  s = point;
  s.stop_after_crossings = 2;
  EXPECT_NE(base, scenes::plate_whole_run_key(s));
  s = point;
  s.power_budget = true;
  EXPECT_NE(base, scenes::plate_whole_run_key(s));
  s = point;
  s.scheme.cfl = 2.5;
  EXPECT_NE(base, scenes::plate_whole_run_key(s));
  EXPECT_FALSE(scenes::run_plate_stored(s, "point").reused);
}
