// The predictor-corrector leapfrog of Gray, Monaghan & Swift 2001, (6.14)-(6.18)
// (src/core/predictor_corrector.hpp), on problems with exact solutions: a harmonic oscillator x'' = -x
// moved with u = v (for positions and velocities the scheme is then velocity Verlet) and a first-order field
// q' = -q (for it the scheme is Heun's method). Both are second order, so the global error at a fixed time
// must fall by 4 when dt halves. A held particle (u = a = 0, Gray's Fixed particles) must not move at all,
// and the corrector must leave the predicted positions alone (6.15). RK4 has its own tests (test_rk4.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/predictor_corrector.hpp"
#include "core/types.hpp"

namespace {

using sph::Vec2;

struct State {
  std::vector<Vec2> x, v;
  std::vector<double> q;
  auto first_order() { return std::tie(q); }
};

struct Rates {
  std::vector<Vec2> dx, dv;
  std::vector<double> dq;
  auto first_order() const { return std::tie(dq); }
};

using Pc = sph::PredictorCorrector<State, Rates>;

// Particle 0 oscillates (x'' = -x, q' = -q); particle 1, when `hold`, is held: u = a = 0 whatever its
// velocity, but its first-order field still evolves.
auto oscillator_rates(bool hold) {
  return [hold](const State& y, Rates& r) {
    for (std::size_t a = 0; a < y.x.size(); ++a) {
      const bool held = hold && a == 1;
      r.dx[a] = held ? Vec2::Zero() : y.v[a];
      r.dv[a] = held ? Vec2::Zero() : Vec2(-y.x[a]);
      r.dq[a] = -y.q[a];
    }
  };
}

struct Errors { double x, v, q; };

// Integrates x(0) = (1, 0.5), v(0) = (0, 0.5), q(0) = 1 to T = 10 in `steps` steps. Exact:
// x = x0 cos t + v0 sin t, v = -x0 sin t + v0 cos t, q = exp(-t).
Errors errors(int steps) {
  const double T = 10.0, dt = T / steps;
  const Vec2 x0(1.0, 0.5), v0(0.0, 0.5);
  State y{{x0}, {v0}, {1.0}};
  Rates r0{{Vec2::Zero()}, {Vec2::Zero()}, {0.0}}, r1 = r0;
  auto nothing = [](State&) {};
  for (int n = 0; n < steps; ++n) Pc::step(y, dt, r0, r1, oscillator_rates(false), nothing, nothing);
  const Vec2 x = x0 * std::cos(T) + v0 * std::sin(T), v = -x0 * std::sin(T) + v0 * std::cos(T);
  return {(y.x[0] - x).norm(), (y.v[0] - v).norm(), std::abs(y.q[0] - std::exp(-T)) / std::exp(-T)};
}

TEST(PredictorCorrector, SecondOrderGlobalConvergenceOfPositionVelocityAndFirstOrderField) {
  // The error is C dt^2 (1 + c dt^2 + ...), so log2(e(dt)/e(dt/2)) = 2 + log2(1 + 3 c dt^2/4) ~ 2 + 1.1 c dt^2.
  // Velocity Verlet on x'' = -x: phase error T dt^2/24 (1 + O(dt^2)), c = O(1), so offsets of ~0.01 at
  // dt = 0.1: a band of +-0.05. Heun on q' = -q: per step ln(1 - dt + dt^2/2) + dt = dt^3/6 (1 + 3 dt/4),
  // an O(dt) next term, so the observed order is 2 + log2(1 + 3 dt/8) = 2.05 at dt = 0.1, 2.03 at 0.05:
  // a band of +-0.1.
  const Errors e1 = errors(100), e2 = errors(200), e3 = errors(400);
  for (const auto& [coarse, fine] : {std::pair{e1, e2}, std::pair{e2, e3}}) {
    EXPECT_NEAR(std::log2(coarse.x / fine.x), 2.0, 0.05);
    EXPECT_NEAR(std::log2(coarse.v / fine.v), 2.0, 0.05);
    EXPECT_NEAR(std::log2(coarse.q / fine.q), 2.0, 0.1);
  }
  // And the errors are the size the leading terms predict (not second order by accident of a tiny constant):
  // phase error T dt^2/24 = 4.2e-3 times |x0| ~ 1.1 at dt = 0.1; q's relative error T dt^2/6 = 1.7e-2.
  EXPECT_GT(e1.x, 1e-3);
  EXPECT_LT(e1.x, 2e-2);
  EXPECT_GT(e1.q, 5e-3);
  EXPECT_LT(e1.q, 5e-2);
}

TEST(PredictorCorrector, HeldParticleDoesNotMoveAndCorrectorKeepsPredictedPositions) {
  State y{{Vec2(1.0, 0.5), Vec2(0.3, -0.7)}, {Vec2(0.0, 0.5), Vec2(0.2, 0.1)}, {1.0, 2.0}};
  const State y0 = y;
  Rates r0{{Vec2::Zero(), Vec2::Zero()}, {Vec2::Zero(), Vec2::Zero()}, {0.0, 0.0}}, r1 = r0;
  std::vector<Vec2> predicted;
  auto after_predict = [&](State& s) { predicted = s.x; };
  auto after_correct = [&](State& s) {
    for (std::size_t a = 0; a < s.x.size(); ++a) EXPECT_EQ(s.x[a], predicted[a]) << a;  // (6.15) is final
  };
  const double dt = 0.0137;
  for (int n = 0; n < 500; ++n) Pc::step(y, dt, r0, r1, oscillator_rates(true), after_predict, after_correct);
  // Adding dt * 0 and dt^2/2 * 0 is exact: position and velocity of the held particle are unchanged, bit for
  // bit, while its first-order field and the free particle have evolved.
  EXPECT_EQ(y.x[1], y0.x[1]);
  EXPECT_EQ(y.v[1], y0.v[1]);
  EXPECT_NEAR(y.q[1], 2.0 * std::exp(-500 * dt), 1e-3 * 2.0 * std::exp(-500 * dt));  // Heun: T dt^2/6 = 2e-4
  EXPECT_GT((y.x[0] - y0.x[0]).norm(), 0.1);
  // After the step r0 holds the rates at the start of the last step and r1 those at the predicted state.
  EXPECT_EQ(r1.dv[0], Vec2(-predicted[0]));
}

}  // namespace
