// The measured stability limit of experiments/frame/stability_limit.hpp (the margin rows of H-wp and I-hole): the
// bracket it returns holds the threshold of a scene that fails above it, to the relative width asked; a scene whose
// own step fails, or that never fails, is refused rather than given a limit.
#include <gtest/gtest.h>

#include <stdexcept>

#include "frame/stability_limit.hpp"

TEST(StabilityLimit, BracketsTheThresholdToTheWidthAsked) {
  const double threshold = 3.7;
  int runs = 0;
  const auto limit = sph::largest_stable_step(0.3, 0.01, [&](double step) { ++runs; return step <= threshold; });
  EXPECT_LE(limit.stable, threshold);
  EXPECT_GT(limit.failing, threshold);
  EXPECT_LE(limit.failing - limit.stable, 0.01 * limit.stable);
  EXPECT_LT(runs, 20);  // doubling 0.3 -> 4.8 (5 runs), then bisection of [2.4, 4.8] to 1% (8 runs)
}

TEST(StabilityLimit, AThresholdJustAboveTheStartIsFound) {
  const auto limit = sph::largest_stable_step(1.0, 0.001, [](double step) { return step < 1.05; });
  EXPECT_LT(limit.stable, 1.05);
  EXPECT_GE(limit.failing, 1.05);
}

TEST(StabilityLimit, RefusesAFailingStartAndANeverFailingScene) {
  EXPECT_THROW(sph::largest_stable_step(1.0, 0.01, [](double) { return false; }), std::runtime_error);
  EXPECT_THROW(sph::largest_stable_step(1.0, 0.01, [](double) { return true; }), std::runtime_error);
  EXPECT_THROW(sph::largest_stable_step(0.0, 0.01, [](double) { return true; }), std::invalid_argument);
}
