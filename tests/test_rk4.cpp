// RK4 (src/core/rk4.hpp): fourth-order convergence on the harmonic oscillator, exactness on a cubic in t,
// and no reallocation of the stage buffers after the first step.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/rk4.hpp"

namespace {

struct Osc {  // x'' = -x as (x, v): one field of two entries
  std::vector<double> y;
  auto fields() { return std::tie(y); }
  auto fields() const { return std::tie(y); }
};

double oscillator_error(int steps) {
  const double T = 10.0, dt = T / steps;
  Osc s{{1.0, 0.0}};
  sph::Rk4<Osc> rk;
  auto f = [](double, const Osc& y, Osc& d) { d.y[0] = y.y[1]; d.y[1] = -y.y[0]; };
  for (int n = 0; n < steps; ++n) rk.step(s, n * dt, dt, f);
  return std::hypot(s.y[0] - std::cos(T), s.y[1] + std::sin(T));
}

TEST(Rk4, FourthOrderOnHarmonicOscillator) {
  const double e1 = oscillator_error(100), e2 = oscillator_error(200), e3 = oscillator_error(400);
  const double p1 = std::log2(e1 / e2), p2 = std::log2(e2 / e3);
  EXPECT_NEAR(p1, 4.0, 0.1);
  EXPECT_NEAR(p2, 4.0, 0.05);
}

TEST(Rk4, ExactForCubicInTime) {  // y' = 3 t^2 + 2 t: RK4 integrates polynomials of degree <= 3 exactly
  Osc s{{0.0}};
  sph::Rk4<Osc> rk;
  auto f = [](double t, const Osc&, Osc& d) { d.y[0] = 3 * t * t + 2 * t; };
  const double dt = 0.37;
  for (int n = 0; n < 7; ++n) rk.step(s, n * dt, dt, f);
  const double T = 7 * dt;
  EXPECT_NEAR(s.y[0], T * T * T + T * T, 1e-12);
}

TEST(Rk4, StageBuffersKeepTheirStorage) {
  Osc s{{1.0, 0.0}};
  sph::Rk4<Osc> rk;
  const double* before = nullptr;
  auto f = [&](double, const Osc& y, Osc& d) {
    if (!before) before = d.y.data();
    d.y[0] = y.y[1]; d.y[1] = -y.y[0];
  };
  rk.step(s, 0, 0.1, f);
  const double* first = before;
  before = nullptr;
  rk.step(s, 0.1, 0.1, f);
  EXPECT_EQ(first, before);
}

}  // namespace
