// The one time loop of the library (src/core/run_loop.hpp): when it stops (a number of steps, an end time
// reached by a shortened last step or by whole steps), when it calls the observer, how a blow-up becomes
// the outcome of a run, and the sampling Cadence. A fake solver that only advances its clock makes every
// step length visible; a real GraySolver checks that a state corrupted between steps is reported with the
// particle that went bad.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/lattices.hpp"
#include "core/run_loop.hpp"
#include "updated_lagrangian/gray_solver.hpp"

namespace {

using sph::Vec2;

// The solver contract, reduced to the clock. Blows up during its step number `blow_at` (1-based).
struct Clock {
  double t = 0;
  long n = 0, blow_at = -1;
  std::vector<double> dts;
  std::size_t size() const { return 3; }  // three particles: the run loop tallies particle-steps
  void step(double dt) {
    if (n + 1 == blow_at) sph::throw_blow_up(n + 1, t, 17, Vec2(0.5, -0.25), "test");
    t += dt;
    ++n;
    dts.push_back(dt);
  }
  double time() const { return t; }
  long steps() const { return n; }
};

auto never = [](const Clock&) { return false; };

TEST(RunLoop, StopsAfterThePlannedNumberOfSteps) {
  Clock c;
  const auto out = sph::run(c, {0.25, 7}, never);
  EXPECT_EQ(out.steps, 7);
  EXPECT_EQ(c.steps(), 7);
  EXPECT_EQ(c.time(), 1.75);  // 0.25 is exact in binary: no round-off
  EXPECT_FALSE(out.stopped);
  EXPECT_FALSE(out.blew_up());
  EXPECT_THROW(sph::run(c, {0.0, 1}, never), std::invalid_argument);
}

TEST(RunLoop, LandsExactlyOnTheEndTimeByShorteningTheLastStep) {
  Clock c;
  const auto out = sph::run(c, {0.3, -1, 1.0}, never);
  // 0.3 + 0.3 + 0.3 = 0.8999999999999999; the last step is 1.0 - that. Both times lie within a factor 2 of
  // each other, so the subtraction is exact (Sterbenz) and t + (t_end - t) rounds to t_end exactly.
  ASSERT_EQ(out.steps, 4);
  EXPECT_EQ(c.dts[0], 0.3);
  EXPECT_EQ(c.dts[2], 0.3);
  EXPECT_NEAR(c.dts[3], 0.1, 1e-15);
  EXPECT_EQ(c.time(), 1.0);
  // The end time also bounds a plan with a step count: whichever comes first.
  Clock d;
  EXPECT_EQ(sph::run(d, {0.3, 100, 1.0}, never).steps, 4);
  EXPECT_EQ(sph::run(d = Clock{}, {0.3, 2, 1.0}, never).steps, 2);
}

TEST(RunLoop, ATimeWithinToleranceOfTheEndCountsAsReached) {
  Clock close, short_of;
  close.t = 1.0 - 1e-13;  // within 1e-12: no sliver of a step
  EXPECT_EQ(sph::run(close, {0.3, -1, 1.0}, never).steps, 0);
  short_of.t = 1.0 - 1e-11;  // beyond it: one step of the remaining 1e-11
  EXPECT_EQ(sph::run(short_of, {0.3, -1, 1.0}, never).steps, 1);
  EXPECT_NEAR(short_of.dts[0], 1e-11, 1e-16);
  EXPECT_EQ(short_of.time(), 1.0);
}

TEST(RunLoop, WholeStepsRunUntilTheTimeReachesTheEnd) {
  Clock c;
  sph::RunPlan plan{0.3, -1, 1.0, true};
  EXPECT_EQ(sph::run(c, plan, never).steps, 4);  // 0.3, 0.6, 0.9 < 1.0, then 1.2 >= 1.0
  for (double dt : c.dts) EXPECT_EQ(dt, 0.3);
  EXPECT_NEAR(c.time(), 1.2, 1e-15);
  Clock d;
  plan.t_end = 1.2;  // 0.3 * 4 accumulates to exactly 1.2 in binary: no fifth step
  EXPECT_EQ(sph::run(d, plan, never).steps, 4);
}

TEST(RunLoop, ObserverSeesTheStartAndEveryStepAndCanStopTheRun) {
  Clock c;
  std::vector<long> observed;
  long progressed = 0;
  auto observe = [&](const Clock& s) {
    observed.push_back(s.steps());
    return s.steps() == 3;
  };
  const auto out = sph::run(c, {0.1, 10}, observe, [&](const Clock&) { ++progressed; });
  EXPECT_EQ(observed, (std::vector<long>{0, 1, 2, 3}));
  EXPECT_TRUE(out.stopped);
  EXPECT_EQ(out.steps, 3);
  EXPECT_EQ(progressed, 3);
  // An observer that says stop at the start: no step at all.
  Clock d;
  const auto none = sph::run(d, {0.1, 10}, [](const Clock&) { return true; });
  EXPECT_TRUE(none.stopped);
  EXPECT_EQ(none.steps, 0);
  EXPECT_EQ(d.steps(), 0);
}

TEST(RunLoop, BlowUpBecomesTheOutcomeAndCountsTheFailingStep) {
  Clock c;
  c.blow_at = 5;
  const auto out = sph::run(c, {0.25, 10}, never);
  EXPECT_TRUE(out.blew_up());
  EXPECT_EQ(out.steps, 5);  // the failing step counts
  EXPECT_EQ(c.steps(), 4);  // the solver completed four
  EXPECT_EQ(out.blow_up, "blow-up at step 5, t = 1, particle 17 at (0.5, -0.25): test");
}

TEST(RunLoop, TalliesTheParticleStepsItTakes) {
  Clock c;
  const long long before = sph::particle_steps_taken();
  sph::run(c, {0.1, 7}, [](const Clock&) { return false; });
  EXPECT_EQ(sph::particle_steps_taken() - before, 3 * 7);
}

TEST(Cadence, SamplesAtTheFirstCallAndThenEveryInterval) {
  // dt = 0.3, interval 1: sample k is due at the first step n with 0.3 n >= k, n = ceil(10 k / 3) =
  // 4, 7, 10, 14, 17, 20. At n = 10 the accumulated time is 2.9999999999999996 < 3: only the 1e-12
  // tolerance catches that sample (else it would slip to n = 11).
  Clock c;
  sph::Cadence samples(1.0);
  std::vector<long> at_step;
  std::vector<double> at_time;
  sph::run(c, {0.3, 20}, [&](const Clock& s) {
    if (samples.due(s.time())) {
      at_step.push_back(s.steps());
      at_time.push_back(s.time());
    }
    return false;
  });
  EXPECT_EQ(at_step, (std::vector<long>{0, 4, 7, 10, 14, 17, 20}));
  for (std::size_t i = 0; i < at_time.size(); ++i) EXPECT_NEAR(at_time[i], 0.3 * at_step[i], 1e-14) << i;
}

TEST(RunLoop, CorruptedGrayStateBlowsUpNamingTheParticle) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double dp = 0.1;
  sph::ElasticBody body;
  for (const Vec2& p : sph::lattice_block(sph::LatticeKind::Square, 8, 8, dp))
    body.add(p + 0.05 * dp * Vec2(u(rng), u(rng)), 0.02 * Vec2(u(rng), u(rng)), dp * dp, 1.0);
  body.dp = dp;
  body.box = {-1, -1, 2, 2, false, false};
  sph::GraySolver solver(body, sph::GrayParameters{}, sph::GrayOptions{});
  // The observer corrupts particle 23's velocity after step 3; step 4 finds it before moving anything.
  auto observe = [&](const sph::GraySolver& s) {
    if (s.steps() == 3) body.v[23].y() = std::nan("");
    return false;
  };
  const auto out = sph::run(solver, {0.01, 10}, observe);
  ASSERT_TRUE(out.blew_up());
  EXPECT_EQ(out.steps, 4);
  EXPECT_EQ(solver.steps(), 3);
  // The time is the solver's at detection (0.03, before step 4 moved anything). The step number is left
  // out: GraySolver names its completed steps (3) when it checks before or inside a step, but the step
  // just completed (= the failing one) when it checks after it, as SpamSolver and MdSolver always do.
  EXPECT_EQ(out.blow_up.rfind("blow-up at step ", 0), 0u) << out.blow_up;
  EXPECT_NE(out.blow_up.find(", t = 0.03, particle 23 at ("), std::string::npos) << out.blow_up;
  const auto what = out.blow_up.find("): |v| = ");
  ASSERT_NE(what, std::string::npos) << out.blow_up;
  EXPECT_NE(out.blow_up.find("nan", what), std::string::npos) << out.blow_up;  // the bad value is named
}

}  // namespace
