// The Gray-Monaghan-Swift 2001 scheme: conservation, symmetry, the artificial stress in principal axes,
// the objectivity of the stress rate, Driven particles, colliding bodies and the plastic return.
#include <gtest/gtest.h>

#include <omp.h>

#include <Eigen/Eigenvalues>
#include <array>
#include <cstring>
#include <random>
#include <string>
#include <type_traits>
#include <typeinfo>

#include "updated_lagrangian/artificial_stress.hpp"
#include "updated_lagrangian/gray_solver.hpp"
#include "core/diagnostics.hpp"
#include "core/fields.hpp"
#include "core/materials.hpp"

namespace {

using sph::Tensor2;
using sph::Vec2;

// A disordered square block of free particles with random velocities and deviatoric stresses.
sph::ElasticBody random_block(int n, double dp, unsigned seed, bool with_stress) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  sph::ElasticBody body;
  for (const Vec2& p : sph::lattice_block(sph::LatticeKind::Square, n, n, dp)) {
    body.add(p + 0.1 * dp * Vec2(u(rng), u(rng)), 0.05 * Vec2(u(rng), u(rng)), dp * dp, 1.0 + 0.02 * u(rng));
    if (with_stress) {
      const double sxy = 0.03 * u(rng), sxx = 0.05 * u(rng);
      body.S.back() << sxx, sxy, sxy, -sxx + 0.01 * u(rng);
    }
  }
  return body;
}

// The scheme's default parameters, and the body's lattice spacing and domain (h = 1.5 dp).
sph::GrayParameters params_for(sph::ElasticBody& body, double dp, sph::Box2 box = {-1, -1, 2, 2, false, false}) {
  body.dp = dp;
  body.box = box;
  return sph::GrayParameters{};
}

TEST(GraySolver, PairForcesConserveLinearMomentumExactly) {
  for (bool as : {false, true})
    for (bool visc : {false, true}) {
      sph::ElasticBody body = random_block(12, 0.1, 3, true);
      sph::GrayOptions o;
      o.artificial_stress = as;
      o.viscosity = visc;
      sph::GraySolver solver(body, params_for(body, 0.1), o);
      const auto& r = solver.evaluate_now();
      Vec2 total = Vec2::Zero(), scale = Vec2::Zero();
      for (std::size_t a = 0; a < body.size(); ++a) {
        total += body.m[a] * r.dv[a];
        scale += body.m[a] * r.dv[a].cwiseAbs();
      }
      EXPECT_LT(total.norm(), 1e-13 * scale.norm()) << "artificial stress " << as << " viscosity " << visc;
      EXPECT_GT(scale.norm(), 1e-3);  // the forces are not trivially zero
    }
}

// GraySolver::power_budget (issue 15 a): each term's power is sum_a m_a v_a . (the acceleration with the term
// minus without it), and the viscosity's is never positive; XSPH's is sum m (v - vhat) . the stress term's.
TEST(GraySolver, PowerBudgetIsThePowerOfEachTermsAcceleration) {
  sph::ElasticBody body = random_block(12, 0.1, 5, true);
  sph::GrayOptions all;
  const sph::GrayParameters p = params_for(body, 0.1);
  sph::ElasticBody copy = body;
  sph::GraySolver full(body, p, all);
  const auto budget = full.power_budget();
  const auto dv_full = full.evaluate_now().dv;
  auto power_of = [&](bool artificial_stress) {
    sph::ElasticBody b = copy;
    sph::GrayOptions o = all;
    (artificial_stress ? o.artificial_stress : o.viscosity) = false;
    sph::GraySolver without(b, p, o);
    const auto& dv = without.evaluate_now().dv;
    double power = 0, scale = 0;
    for (std::size_t a = 0; a < b.size(); ++a) {
      power += b.m[a] * b.v[a].dot(dv_full[a] - dv[a]);
      scale += b.m[a] * b.v[a].norm() * dv_full[a].norm();
    }
    return std::make_pair(power, scale);
  };
  const auto [p_art, s_art] = power_of(true);
  const auto [p_visc, s_visc] = power_of(false);
  EXPECT_NEAR(budget.artificial_stress, p_art, 1e-12 * s_art);
  EXPECT_NEAR(budget.viscosity, p_visc, 1e-12 * s_visc);
  // XSPH's: sum m (v - vhat) . (the acceleration of the stress term alone), with the evaluation's own vhat.
  {
    sph::ElasticBody b = copy;
    sph::GrayOptions o = all;
    o.artificial_stress = o.viscosity = false;
    sph::GraySolver stress_only(b, p, o);
    const auto& r = stress_only.evaluate_now();
    double power = 0, scale = 0;
    for (std::size_t a = 0; a < b.size(); ++a) {
      power += b.m[a] * (b.v[a] - r.vhat[a]).dot(r.dv[a]);
      scale += b.m[a] * (b.v[a] - r.vhat[a]).norm() * r.dv[a].norm();
    }
    EXPECT_NEAR(budget.xsph, power, 1e-12 * scale);
    EXPECT_GT(std::abs(budget.xsph), 1e-6 * scale);
  }
  EXPECT_LT(budget.viscosity, 0.0);                        // random velocities: some pairs approach
  EXPECT_GT(std::abs(budget.artificial_stress), 1e-6 * s_art);  // not trivially zero
}

// The energy budget of a periodic patch (issue 15 a): no clamp, no boundary, a shear and a compression wave
// with some noise. Over the run, (kinetic + elastic) changes by the works of GraySolver::PowerBudget's three
// terms (trapezoids of the power at every step) plus what they leave: the predictor-corrector's error,
// O(dt^2), and the stress power's own mismatch (the pair weights m_b / rho_a^2 against V_b / rho_a, the
// volume change of the shear energy), O(density change) of the stress power; none of it without shear.
struct PatchBudget { double E0, dE, work, gross; };
PatchBudget run_patch(double mu, double amplitude, double dt, double t_end, bool xsph = true) {
  const int n = 12;
  const double dp = 1.0 / n;
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  sph::ElasticBody body;
  const double k = 2 * M_PI;
  for (const Vec2& x : sph::lattice_block(sph::LatticeKind::Square, n, n, dp, Vec2(0.5 * dp, 0.5 * dp))) {
    const Vec2 v(std::sin(k * x.y()) + 0.5 * std::sin(k * x.x()) + 0.2 * u(rng), 0.7 * std::sin(k * x.x() + 1.0) + 0.2 * u(rng));
    body.add(x, amplitude * v, dp * dp, 1.0);
  }
  sph::GrayParameters p = params_for(body, dp, {0, 0, 1, 1, true, true});
  p.mu = mu;
  sph::GrayOptions o;  // artificial stress and viscosity on
  o.xsph = xsph;
  sph::GraySolver solver(body, p, o);
  auto energy = [&] { return sph::kinetic_energy(solver) + solver.elastic_energy(); };
  auto power = [&](double& gross) {
    const auto b = solver.power_budget();
    gross = std::abs(b.artificial_stress) + std::abs(b.viscosity) + std::abs(b.xsph);
    return b.artificial_stress + b.viscosity + b.xsph;
  };
  PatchBudget r{energy(), 0, 0, 0};
  double g0, g1, P0 = power(g0);
  const int steps = static_cast<int>(std::lround(t_end / dt));
  for (int i = 0; i < steps; ++i) {
    solver.step(dt);
    const double P1 = power(g1);
    r.work += 0.5 * dt * (P0 + P1);
    r.gross += 0.5 * dt * (g0 + g1);
    P0 = P1;
    g0 = g1;
  }
  r.dE = energy() - r.E0;
  return r;
}

TEST(GraySolver, EnergyBudgetOfAPeriodicPatchClosesToTheIntegratorsOrderWithoutShear) {
  // Pressure only (mu = 0): the continuity equation's density rate is the exact counterpart of the pressure
  // term's work, so only the integrator's error is left: second order (the predictor-corrector and the
  // trapezoids), ~4x per halving of the step; asked >= 2.8x (order 1.5) from dt = 0.01 = 0.08 h / c0 on,
  // where the residual falls monotonically (from 0.04 to 0.02 it changes sign: not yet asymptotic). With
  // XSPH the position update (6.15), x + dt vhat + dt^2/2 F, has F the acceleration of v, not of vhat: first
  // order in that part, so only >= 1.5x (order 0.6) is asked of it.
  const double t_end = 2.0, A = 0.02;
  for (const bool xsph : {false, true}) {
    const PatchBudget a = run_patch(0.0, A, 0.01, t_end, xsph), b = run_patch(0.0, A, 0.005, t_end, xsph);
    const double res_a = std::abs(a.dE - a.work), res_b = std::abs(b.dE - b.work);
    EXPECT_GT(a.gross, 0.1 * a.E0) << "xsph " << xsph;    // the terms do work (the noise is dissipated)
    EXPECT_LT(res_a, 1e-3 * a.gross) << "xsph " << xsph;  // and that work is the energy change
    EXPECT_GT(res_a / res_b, xsph ? 1.5 : 2.8) << "xsph " << xsph << ": " << res_a << " " << res_b;
  }
}

TEST(GraySolver, EnergyBudgetOfAPeriodicPatchWithShearLeavesAMismatchThatFallsWithTheAmplitude) {
  // With shear the stress power's own mismatch is left: first order in the density changes, so a bound of
  // amplitude x E0 (velocity amplitude A in units of c0 ~ the strain) and at least 2x less at half the
  // amplitude (asked 1.5x). dt = 0.0025 puts the integrator's part (the test above) well below it.
  const double dt = 0.0025, t_end = 2.0, mu = 0.5;
  const PatchBudget a = run_patch(mu, 0.04, dt, t_end), b = run_patch(mu, 0.02, dt, t_end);
  const double rel_a = std::abs(a.dE - a.work) / a.E0, rel_b = std::abs(b.dE - b.work) / b.E0;
  EXPECT_GT(a.gross, 0.1 * a.E0);
  EXPECT_LT(rel_a, 0.04);
  EXPECT_GT(rel_a / rel_b, 1.5) << rel_a << " " << rel_b;
}

double torque(const sph::ElasticBody& body, const sph::GraySolver::Rates& r) {
  double t = 0;
  for (std::size_t a = 0; a < body.size(); ++a)
    t += body.m[a] * (body.x[a].x() * r.dv[a].y() - body.x[a].y() * r.dv[a].x());
  return t;
}

TEST(GraySolver, AngularMomentumChangesOnlyThroughNonCentralStressTerms) {
  sph::GrayOptions o;
  o.artificial_stress = false;
  // Pressure and viscosity alone are central forces: the total torque vanishes to round-off.
  sph::ElasticBody iso = random_block(12, 0.1, 5, false);
  sph::GraySolver s_iso(iso, params_for(iso, 0.1), o);
  EXPECT_NEAR(torque(iso, s_iso.evaluate_now()), 0.0, 1e-14);
  // A deviatoric stress makes the pair force non-central: the torque is no longer zero.
  sph::ElasticBody dev = random_block(12, 0.1, 5, true);
  sph::GraySolver s_dev(dev, params_for(dev, 0.1), o);
  EXPECT_GT(std::abs(torque(dev, s_dev.evaluate_now())), 1e-6);
}

TEST(GraySolver, UniformStressGivesNoAccelerationOnAPeriodicLattice) {
  const int n = 16;
  const double dp = 1.0 / n;
  sph::ElasticBody body;
  for (const Vec2& p : sph::lattice_block(sph::LatticeKind::Square, n, n, dp, Vec2(0.5 * dp, 0.5 * dp))) {
    body.add(p, Vec2::Zero(), dp * dp, 0.98);  // tension: P = -0.02
    body.S.back() << 0.03, 0.02, 0.02, -0.01;
  }
  const sph::GrayParameters p = params_for(body, dp, {0, 0, 1, 1, true, true});
  sph::GraySolver solver(body, p, sph::GrayOptions{});
  const auto& r = solver.evaluate_now();
  for (std::size_t a = 0; a < body.size(); ++a) {
    EXPECT_LT(r.dv[a].norm(), 1e-12) << a;
    EXPECT_LT(std::abs(r.drho[a]), 1e-14);
  }
}

TEST(ArtificialStress, MatchesAnEigenDecomposition) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double eps = 0.3, rho = 1.1;
  for (int trial = 0; trial < 200; ++trial) {
    Tensor2 sigma;
    const double sxy = trial % 7 == 0 ? 0.0 : u(rng);
    sigma << u(rng), sxy, sxy, trial % 5 == 0 ? sigma(0, 0) : u(rng);  // include s_xx = s_yy
    if (trial % 5 == 0) sigma(1, 1) = sigma(0, 0);
    Eigen::SelfAdjointEigenSolver<Tensor2> es(sigma);
    Tensor2 expected = Tensor2::Zero();
    for (int i = 0; i < 2; ++i) {
      const double s = es.eigenvalues()(i);
      if (s > 0) expected += (-eps * s / (rho * rho)) * es.eigenvectors().col(i) * es.eigenvectors().col(i).transpose();
    }
    const Tensor2 R = sph::artificial_stress(sigma, rho, eps);
    EXPECT_LT((R - expected).norm(), 1e-12) << "sigma =\n" << sigma;
  }
  // Pure compression adds nothing.
  EXPECT_EQ(sph::artificial_stress(-Tensor2::Identity(), 1.0, 0.3).norm(), 0.0);
}

TEST(StressRate, IsObjectiveUnderRigidRotation) {
  // Under a rigid spin grad v = W (antisymmetric) the strain rate vanishes and the Jaumann rate must
  // carry S with the body: S(t) = Q(t) S0 Q(t)^T. Integrate with RK4 and compare.
  const double omega = 0.7, mu = 0.5, T = 2.0;
  Tensor2 W;
  W << 0, -omega, omega, 0;
  Tensor2 S0;
  S0 << 0.3, 0.1, 0.1, -0.2;
  Tensor2 S = S0;
  const int steps = 2000;
  const double dt = T / steps;
  auto f = [&](const Tensor2& s) { return sph::hooke_deviatoric_rate(mu, W, s); };
  for (int i = 0; i < steps; ++i) {
    const Tensor2 k1 = f(S), k2 = f(S + 0.5 * dt * k1), k3 = f(S + 0.5 * dt * k2), k4 = f(S + dt * k3);
    S += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  Tensor2 Q;
  Q << std::cos(omega * T), -std::sin(omega * T), std::sin(omega * T), std::cos(omega * T);
  EXPECT_LT((S - Q * S0 * Q.transpose()).norm(), 1e-10);
  // And a pure strain rate gives 2 mu times its deviator (no rotation terms).
  Tensor2 D;
  D << 0.1, 0.05, 0.05, 0.0;
  const Tensor2 rate = sph::hooke_deviatoric_rate(mu, D, Tensor2::Zero());
  EXPECT_NEAR(rate(0, 0), 2 * mu * (0.1 - 0.1 / 3), 1e-15);
  EXPECT_NEAR(rate(0, 1), 2 * mu * 0.05, 1e-15);
}

TEST(GraySolver, StepConservesMomentumAndStopsOnBlowUp) {
  sph::ElasticBody body = random_block(10, 0.1, 9, true);
  sph::GraySolver solver(body, params_for(body, 0.1), sph::GrayOptions{});
  const Vec2 p0 = sph::linear_momentum(solver);
  for (int i = 0; i < 20; ++i) solver.step(0.01);
  EXPECT_LT((sph::linear_momentum(solver) - p0).norm(), 1e-13);
  body.v[7].x() = std::nan("");
  try {
    solver.step(0.01);
    FAIL() << "no blow-up detected";
  } catch (const sph::BlowUp& e) {
    EXPECT_NE(std::string(e.what()).find("particle 7"), std::string::npos) << e.what();
  }
}

TEST(GraySolver, DrivenParticlesFollowTheirPrescribedMotionExactly) {
  // A block whose left and right columns are driven apart (the slab's end bands), the rest free.
  sph::ElasticBody body;
  const double dp = 0.1, accel = 2e-3;
  for (const Vec2& p : sph::lattice_block(sph::LatticeKind::Square, 10, 6, dp)) {
    const bool left = p.x() < 1.5 * dp, right = p.x() > 7.5 * dp;
    if (left || right)
      body.add(p, Vec2(right ? 0.01 : -0.01, 0.0), dp * dp, 1.0, sph::Motion::Driven, Vec2(right ? accel : -accel, 0.0));
    else
      body.add(p, Vec2::Zero(), dp * dp, 1.0);
  }
  const std::vector<Vec2> x0 = body.x, v0 = body.v;
  sph::GraySolver solver(body, params_for(body, dp), sph::GrayOptions{});
  const double dt = 0.01;
  for (int i = 0; i < 300; ++i) solver.step(dt);
  const double t = solver.time();
  int driven = 0, free_moved = 0;
  for (std::size_t a = 0; a < body.size(); ++a) {
    if (body.motion[a] == sph::Motion::Driven) {
      ++driven;
      const Vec2 exact = x0[a] + v0[a] * t + 0.5 * body.drive[a] * t * t;
      EXPECT_LT((body.x[a] - exact).norm(), 1e-13) << a;
      EXPECT_LT((body.v[a] - (v0[a] + body.drive[a] * t)).norm(), 1e-14) << a;
    } else if ((body.x[a] - x0[a]).norm() > 1e-6) {
      ++free_moved;  // the free particles feel the pull through the SPH forces
    }
  }
  EXPECT_EQ(driven, 24);
  EXPECT_GT(free_moved, 0);
}

TEST(GraySolver, CollidingBodiesConserveMomentumThroughContact) {
  // Two free blocks thrown at each other touch through the ordinary pair sums; with no Fixed or Driven
  // particle the total momentum is conserved to round-off, while each block's momentum changes.
  sph::ElasticBody body;
  const double dp = 0.1, speed = 0.05;
  std::size_t left_count = 0;
  for (int side : {-1, 1})
    for (const Vec2& p : sph::lattice_block(sph::LatticeKind::Square, 6, 6, dp)) {
      body.add(p + Vec2(side < 0 ? -0.65 : 0.05, 0.0), Vec2(-side * speed, 0.0), dp * dp, 1.0);
      if (side < 0) ++left_count;
    }
  sph::GraySolver solver(body, params_for(body, dp), sph::GrayOptions{});
  const Vec2 p0 = sph::linear_momentum(solver);
  auto left_momentum = [&] {
    Vec2 p = Vec2::Zero();
    for (std::size_t a = 0; a < left_count; ++a) p += body.m[a] * body.v[a];
    return p;
  };
  const Vec2 left0 = left_momentum();
  for (int i = 0; i < 400; ++i) solver.step(0.01);
  EXPECT_LT((sph::linear_momentum(solver) - p0).norm(), 1e-14);
  EXPECT_LT(left_momentum().x(), 0.5 * left0.x());  // the contact pushed the left block back
}

TEST(GraySolver, PlasticReturnKeepsEveryStressOnOrInsideTheYieldSurface) {
  sph::ElasticBody body = random_block(10, 0.1, 13, true);
  sph::GrayParameters p = params_for(body, 0.1);
  sph::ElasticBody copy = body;
  sph::GrayOptions o;
  o.plasticity = true;
  p.yield_stress = 0.02;
  sph::GraySolver solver(body, p, o);
  for (int i = 0; i < 20; ++i) solver.step(0.01);
  int on_surface = 0;
  for (std::size_t a = 0; a < body.size(); ++a) {
    const double s = sph::von_mises_stress(body.S[a]);
    EXPECT_LE(s, p.yield_stress * (1 + 1e-12)) << a;
    if (s > p.yield_stress * (1 - 1e-12)) ++on_surface;
  }
  EXPECT_GT(on_surface, 0);
  // A yield stress never reached changes nothing, bit for bit.
  sph::ElasticBody a = copy, b = copy;
  p.yield_stress = 1e9;
  sph::GraySolver with(a, p, o), without(b, p, sph::GrayOptions{});
  for (int i = 0; i < 5; ++i) {
    with.step(0.01);
    without.step(0.01);
  }
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a.x[k], b.x[k]);
    EXPECT_EQ(a.S[k], b.S[k]);
  }
}

// Pass 2 of the evaluation runs a block of pairs at a time, one per lane of lanes::Widest (AVX-512 8, AVX2 4,
// one pair at a time without a SIMD fused multiply-add). Every width must give the bits of a plain scalar
// reference, for every combination of terms: the same pairs, the same operations (products fused where the
// reference fuses them, rounded first where it does not), the same order of every sum. The reference below
// is the scalar loop as it was before the terms were named and written once for every width, on one thread,
// adding each pair to both particles in row order (which is the loop's order on one thread).
double unfused_product(double x, double y) {
  volatile double p = x * y;  // volatile: the compiler cannot contract it into a following addition
  return p;
}

template <class Terms>
sph::GrayRates reference_rates(sph::ElasticBody& body, const sph::GrayParameters& p, const sph::CubicSpline& kernel,
                               double h, double W_dp, const sph::PairList& pairs) {
  constexpr bool as = std::is_same_v<typename Terms::tensile, sph::ArtificialStress>;
  constexpr bool xsph = std::is_same_v<typename Terms::xsph, sph::Xsph>;
  constexpr bool visc = std::is_same_v<typename Terms::viscosity, sph::MonaghanViscosity>;
  constexpr bool summation = std::is_same_v<typename Terms::density, sph::SummationDensity>;
  const std::size_t n = body.size();
  const auto& v = body.v;
  const auto& m = body.m;
  auto& rho = body.rho;
  std::vector<Vec2> xs(n, Vec2::Zero());  // pass 1: the XSPH sum (3.6) and the summation density
  std::vector<double> rs(n, 0.0);
  for (std::size_t a = 0; a < n; ++a)
    for (std::uint32_t k = pairs.first(a); k < pairs.last(a); ++k) {
      const std::uint32_t b = pairs.b[k];
      const Vec2 w = (v[b] - v[a]) * (pairs.W[k] / (0.5 * (rho[a] + rho[b])));
      xs[a] += m[b] * w;
      xs[b] -= m[a] * w;
      rs[a] += m[b] * pairs.W[k];
      rs[b] += m[a] * pairs.W[k];
    }
  std::vector<Vec2> vhat(n);
  std::vector<Tensor2> A(n), R(n, Tensor2::Zero());
  std::vector<double> V(n);
  for (std::size_t a = 0; a < n; ++a) {
    vhat[a] = xsph ? Vec2(v[a] + p.eps_xsph * xs[a]) : v[a];
    if (summation) rho[a] = rs[a] + m[a] * kernel.W(0.0, h);
    const Tensor2 sigma = body.S[a] - sph::linear_eos_pressure(rho[a], p.rho0, p.c0) * Tensor2::Identity();
    A[a] = sigma / (rho[a] * rho[a]);
    if (as) R[a] = sph::artificial_stress(sigma, rho[a], p.eps_artificial);
    V[a] = m[a] / rho[a];
  }
  std::vector<std::array<double, 7>> s(n, std::array<double, 7>{});  // pass 2
  const double eta2 = 0.01 * h * h;
  for (std::size_t a = 0; a < n; ++a)
    for (std::uint32_t k = pairs.first(a); k < pairs.last(a); ++k) {
      const std::uint32_t b = pairs.b[k];
      const Vec2 d = pairs.dx[k], gW = d * pairs.F[k];
      double M[4];
      for (int c = 0; c < 4; ++c) M[c] = A[a].data()[c] + A[b].data()[c];
      if (as) {
        const double f = pairs.W[k] * (1.0 / W_dp);
        double fn = 1.0;
        for (int i = 0; i < p.n_artificial; ++i) fn *= f;
        for (int c = 0; c < 4; ++c) M[c] = std::fma(R[a].data()[c] + R[b].data()[c], fn, M[c]);
      }
      const Vec2 dv = v[a] - v[b];
      const double vr = unfused_product(dv.x(), d.x()) + unfused_product(dv.y(), d.y());
      if (visc && vr < 0.0) {
        const double r2 = unfused_product(d.x(), d.x()) + unfused_product(d.y(), d.y());
        const double mu = h * vr / (r2 + eta2);
        const double Pi = std::fma(-p.alpha * p.c0, mu, p.beta * mu * mu) / (0.5 * (rho[a] + rho[b]));
        M[0] -= Pi;
        M[3] -= Pi;
      }
      const Vec2 u = vhat[a] - vhat[b];
      const double t[7] = {std::fma(M[2], gW.y(), M[0] * gW.x()), std::fma(M[3], gW.y(), M[1] * gW.x()),
                           summation ? 0.0 : unfused_product(u.x(), gW.x()) + unfused_product(u.y(), gW.y()),
                           u.x() * gW.x(), u.y() * gW.x(), u.x() * gW.y(), u.y() * gW.y()};
      for (int c = 0; c < 7; ++c) {
        s[a][c] = std::fma(c < 3 ? m[b] : -V[b], t[c], s[a][c]);
        s[b][c] = std::fma(c < 2 ? -m[a] : c == 2 ? m[a] : -V[a], t[c], s[b][c]);
      }
    }
  sph::GrayRates r;
  sph::resize_fields(r, n);
  for (std::size_t a = 0; a < n; ++a) {
    Tensor2 grad_v;
    for (int c = 0; c < 4; ++c) grad_v.data()[c] = s[a][3 + c];
    r.dv[a] = Vec2(s[a][0], s[a][1]);  // every particle Free
    r.dx[a] = r.vhat[a] = vhat[a];
    r.drho[a] = summation ? 0.0 : s[a][2];
    r.dS[a] = sph::hooke_deviatoric_rate(p.mu, grad_v, body.S[a]);
  }
  return r;
}

// Rows of every length occur (a disordered block: 0 to ~14 pairs per row, so full, partial and empty blocks of
// every width), and n = 4 and n = 3 for f^n.
struct WidthCase {
  sph::ElasticBody body;
  sph::GrayParameters p;
  sph::CubicSpline kernel{2};
  double h, W_dp;
  sph::PairList pairs;
  explicit WidthCase(int nart) : body(random_block(23, 0.1, 11, true)) {
    p = params_for(body, 0.1, {-1, -1, 3, 3, false, false});
    p.n_artificial = nart;
    h = p.h_over_dp * body.dp;
    W_dp = kernel.W(body.dp, h);
    sph::CellList2D cells(body.box, kernel.support() * h + p.skin_over_h * h);
    pairs.half = true;
    pairs.update(cells, body.x, kernel.support() * h, p.skin_over_h * h, kernel.at(h));
  }
  template <class Terms, class V>
  sph::GrayRates rates(sph::ElasticBody& b) const {
    sph::GrayScratch scratch;
    sph::GrayRates r;
    sph::resize_fields(r, b.size());
    sph::evaluate_gray_rates<Terms, V>(b, p, kernel, h, W_dp, pairs, scratch, r);
    return r;
  }
};

template <class U, class W>
bool same_bits(const U& u, const W& w) {
  return u.size() == w.size() && std::memcmp(u.data(), w.data(), u.size() * sizeof(u[0])) == 0;
}
#define EXPECT_SAME_RATES(x, y, what)                                                                      \
  do {                                                                                                     \
    EXPECT_TRUE(same_bits(x.dv, y.dv)) << what;                                                            \
    EXPECT_TRUE(same_bits(x.drho, y.drho)) << what;                                                        \
    EXPECT_TRUE(same_bits(x.dS, y.dS)) << what;                                                            \
    EXPECT_TRUE(same_bits(x.dx, y.dx)) << what;                                                            \
    EXPECT_TRUE(same_bits(x.vhat, y.vhat)) << what;                                                        \
  } while (0)

// Two lanes where the target has a fused multiply-add for them (x86 with FMA: SSE batches; Arm: NEON).
#if defined(__FMA__) && XSIMD_WITH_SSE4_2
using TwoLanes = xsimd::batch<double, xsimd::sse4_2>;
#elif XSIMD_WITH_NEON64
using TwoLanes = xsimd::batch<double, xsimd::neon64>;
#else
using TwoLanes = double;
#endif

template <class Terms>
void expect_every_width_gives_the_reference_bits(int nart) {
  const WidthCase w(nart);
  const std::string terms = std::string(typeid(Terms).name()) + " n = " + std::to_string(nart);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  sph::ElasticBody b_ref = w.body, b1 = w.body, b2 = w.body, bw = w.body;
  const sph::GrayRates ref = reference_rates<Terms>(b_ref, w.p, w.kernel, w.h, w.W_dp, w.pairs);
  const sph::GrayRates one = w.rates<Terms, double>(b1), two = w.rates<Terms, TwoLanes>(b2);
  const sph::GrayRates widest = w.rates<Terms, sph::lanes::Widest>(bw);
  EXPECT_SAME_RATES(ref, one, terms << ", one pair at a time");
  EXPECT_SAME_RATES(ref, two, terms << ", " << sph::lanes::width<TwoLanes> << " lanes");
  EXPECT_SAME_RATES(ref, widest, terms << ", " << sph::lanes::width<sph::lanes::Widest> << " lanes");
  EXPECT_TRUE(same_bits(b_ref.rho, bw.rho)) << terms;
  // On two threads the sums run in another order (the threads' partial sums), the same for every width.
  omp_set_num_threads(2);
  sph::ElasticBody c1 = w.body, cw = w.body;
  const sph::GrayRates one2 = w.rates<Terms, double>(c1), widest2 = w.rates<Terms, sph::lanes::Widest>(cw);
  EXPECT_SAME_RATES(one2, widest2, terms << ", two threads");
  omp_set_num_threads(threads);
  double largest = 0;  // the forces are not trivially zero
  for (const Vec2& a : widest.dv) largest = std::max(largest, a.norm());
  EXPECT_GT(largest, 1e-3) << terms;
}

template <class Tensile, class Xsph, class Viscosity>
void expect_for_both_densities(int nart) {
  expect_every_width_gives_the_reference_bits<sph::GrayTerms<Tensile, Xsph, Viscosity, sph::ContinuityDensity>>(nart);
  expect_every_width_gives_the_reference_bits<sph::GrayTerms<Tensile, Xsph, Viscosity, sph::SummationDensity>>(nart);
}

TEST(GraySolver, EveryWidthOfPassTwoGivesTheScalarReferenceBitsForEveryTerm) {
  using namespace sph;
  for (int nart : {4, 3}) {
    expect_for_both_densities<ArtificialStress, Xsph, MonaghanViscosity>(nart);
    expect_for_both_densities<ArtificialStress, Xsph, NoViscosity>(nart);
    expect_for_both_densities<ArtificialStress, NoXsph, MonaghanViscosity>(nart);
    expect_for_both_densities<ArtificialStress, NoXsph, NoViscosity>(nart);
  }
  expect_for_both_densities<NoArtificialStress, Xsph, MonaghanViscosity>(4);
  expect_for_both_densities<NoArtificialStress, Xsph, NoViscosity>(4);
  expect_for_both_densities<NoArtificialStress, NoXsph, MonaghanViscosity>(4);
  expect_for_both_densities<NoArtificialStress, NoXsph, NoViscosity>(4);
}

// A term that is off leaves no slot in the neighbour record: eight numbers without the artificial stress and
// the viscosity, sixteen with either.
static_assert(sph::NeighbourRecord<sph::GrayTerms<sph::NoArtificialStress, sph::Xsph, sph::NoViscosity, sph::ContinuityDensity>>::size == 8);
static_assert(sph::NeighbourRecord<sph::GrayTerms<sph::ArtificialStress, sph::Xsph, sph::MonaghanViscosity, sph::ContinuityDensity>>::size == 16);

}  // namespace
