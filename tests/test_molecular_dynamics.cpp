// Molecular-dynamics reference (src/spam/molecular_dynamics.*): elastic constants of the bonded triangular
// lattice, and conservation of energy and angular momentum by RK4 to the integrator's order (halving dt
// divides the drift by ~16) on the rotating 217-particle hexagon of Hoover et al. 2004.
#include <gtest/gtest.h>

#include <cmath>

#include "core/lattices.hpp"
#include "core/diagnostics.hpp"
#include "spam/molecular_dynamics.hpp"

namespace {

using sph::Vec2;

struct Drift { double energy, angular_momentum; };

Drift rotating_hexagon_drift(double dt, double t_end) {
  const auto x0 = sph::hexagon(8, 1.0);
  sph::MdState s{x0, std::vector<Vec2>(x0.size())};
  const double omega = 0.1 / 8.0;  // speed 0.1 at the vertices
  for (std::size_t i = 0; i < x0.size(); ++i) s.v[i] = omega * Vec2(-x0[i].y(), x0[i].x());
  sph::MdSolver md(x0, s, sph::MdParams{});
  auto energy = [&] { return sph::kinetic_energy(md) + md.potential_energy(); };
  const double e0 = energy(), l0 = sph::centre_of_mass_frame(md).angular_momentum;
  const int steps = static_cast<int>(std::lround(t_end / dt));
  for (int n = 0; n < steps; ++n) md.step(dt);
  return {std::abs(energy() - e0) / e0, std::abs(sph::centre_of_mass_frame(md).angular_momentum - l0) / std::abs(l0)};
}

TEST(MdSolver, SixBondsPerInteriorParticle) {
  const auto x0 = sph::hexagon(3, 1.0);
  sph::MdSolver md(x0, sph::MdState{x0, std::vector<Vec2>(x0.size(), Vec2::Zero())}, sph::MdParams{});
  // 37 particles: 3 n (3 n + 1) bonds for a hexagon of n shells = 90 for n = 3.
  EXPECT_EQ(md.bonds().size(), 90u);
}

TEST(MdSolver, ConservesEnergyAndAngularMomentumToFourthOrder) {
  const Drift a = rotating_hexagon_drift(0.4, 80.0), b = rotating_hexagon_drift(0.2, 80.0);
  EXPECT_LT(a.energy, 1e-5);
  EXPECT_GT(a.energy / b.energy, 10.0);  // 2^4 = 16 for RK4
  EXPECT_LT(a.angular_momentum, 1e-5);
  EXPECT_GT(a.angular_momentum / b.angular_momentum, 10.0);
}

TEST(MdSolver, ConservesLinearMomentumExactly) {
  const auto x0 = sph::hexagon(4, 1.0);
  sph::MdState s{x0, std::vector<Vec2>(x0.size(), Vec2::Zero())};
  for (std::size_t i = 0; i < x0.size(); ++i) s.x[i] += 0.05 * Vec2(std::sin(3.0 * i), std::cos(7.0 * i));
  sph::MdSolver md(x0, s, sph::MdParams{});
  for (int n = 0; n < 200; ++n) md.step(0.05);
  EXPECT_LT(sph::linear_momentum(md).norm(), 1e-13);
}

}  // namespace
