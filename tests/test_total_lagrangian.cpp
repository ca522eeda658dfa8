// Total Lagrangian SPH (Ismail 2009 Chapters 2, 4, 5): sparse SPH matrices, the boundary corrections of
// Sections 2.8.3 and 2.9, central differences (4.4) and the 1D bar of Algorithms 4.1/5.1.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "total_lagrangian/boundary_correction.hpp"
#include "core/central_difference.hpp"
#include "total_lagrangian/interpolation_1d.hpp"
#include "core/kernels.hpp"
#include "core/lattices.hpp"
#include "core/materials.hpp"
#include "total_lagrangian/sph_matrices.hpp"
#include "total_lagrangian/solver_1d.hpp"

namespace {

using sph::KernelFn;

TEST(SphMatrices1D, LinearFieldAndGradientInTheInterior) {
  const double ps = 0.01;
  const auto line = sph::uniform_line(0.0, 1.0, ps, 0.0);
  const KernelFn k = sph::make_kernel_fn("modified_mollifier", 1, 5.5 * ps);
  const auto m = sph::build_sph_matrices_1d(k, line.x, line.volume);
  Eigen::VectorXd f(line.size()), one = Eigen::VectorXd::Ones(line.size()), g(line.size()), s(line.size());
  for (std::size_t i = 0; i < line.size(); ++i) f[i] = 2.0 * line.x[i] + 1.0;
  sph::spmv(m.X, f, g);
  sph::spmv(m.W, f, s);
  const double sumw = sph::lattice_sum_of_weights(sph::ModifiedMollifier(1), k.h, ps);
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line.x[i] < k.radius || line.x[i] > 1.0 - k.radius) continue;
    EXPECT_NEAR(g[i], 2.0, 2e-4) << i;                    // lattice gradient error of h = 5.5 ps: 4e-5
    EXPECT_NEAR(s[i], f[i] * sumw, 1e-12 * (1 + f[i]));   // <f> of a linear f: exact up to the lattice sum
  }
  EXPECT_NEAR(sumw, 1.0, 1e-3);
}

TEST(SphMatrices2D, LinearFieldAndGradientsInTheInteriorMatchBruteForce) {
  const double ps = 0.05;
  const auto x = sph::lattice_block(sph::LatticeKind::Square, 41, 41, ps);
  std::vector<double> dV(x.size(), ps * ps);
  const KernelFn k = sph::make_kernel_fn("modified_mollifier", 2, 3.5 * ps);
  const auto m = sph::build_sph_matrices_2d(k, x, dV);
  Eigen::VectorXd f(x.size()), gx(x.size()), gy(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) f[i] = 3.0 * x[i].x() - 2.0 * x[i].y() + 0.5;
  sph::spmv(m.X, f, gx);
  sph::spmv(m.Y, f, gy);
  int checked = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double lo = k.radius, hi = 40 * ps - k.radius;
    if (x[i].x() < lo || x[i].x() > hi || x[i].y() < lo || x[i].y() > hi) continue;
    // Exact up to the lattice factor of the gradient of x (0.17% for h = 3.5 ps), the same at every
    // interior particle and in both directions.
    EXPECT_NEAR(gx[i] / 3.0, gx[20 * 41 + 20] / 3.0, 1e-12);
    EXPECT_NEAR(gy[i] / -2.0, gx[20 * 41 + 20] / 3.0, 1e-12);
    EXPECT_NEAR(gx[i], 3.0, 0.005 * 3.0);
    ++checked;
  }
  EXPECT_GT(checked, 100);
  // Row 0 against a direct evaluation of every pair.
  const int p = 20 * 41 + 20;
  double sx = 0, sw = 0;
  for (std::size_t q = 0; q < x.size(); ++q) {
    const Eigen::Vector2d d = x[p] - x[q];
    const double r = d.norm();
    if (r >= k.radius) continue;
    sw += k.W(r) * dV[q];
    if (r > 0) sx += k.dWdr(r) * d.x() / r * dV[q] * f[q];
  }
  EXPECT_NEAR(m.W.row(p).sum(), sw, 1e-12);
  EXPECT_NEAR(gx[p], sx, 1e-10);
}

TEST(CorrectiveFactor1D, MakesTheBoundaryValueAndGradientExact) {
  const double ps = 0.01;
  const KernelFn k = sph::make_kernel_fn("modified_mollifier", 1, 4.5 * ps);
  const auto line = sph::uniform_line(0.0, 1.0, ps, k.radius);
  const auto m = sph::build_sph_matrices_1d(k, line.x, line.volume);
  const int b0 = static_cast<int>(line.first_real), b1 = b0 + static_cast<int>(line.n_real) - 1;
  std::vector<int> left, right;
  for (int g = 0; g < b0; ++g) left.push_back(g);
  for (int g = b1 + 1; g < static_cast<int>(line.size()); ++g) right.push_back(g);
  sph::CorrectiveFactor1D neu(m, k, line.x, b0, left, sph::CorrectiveFactor1D::Kind::Neumann);
  sph::CorrectiveFactor1D dir(m, k, line.x, b1, right, sph::CorrectiveFactor1D::Kind::Dirichlet);
  Eigen::VectorXd f(line.size());
  for (std::size_t i = 0; i < line.size(); ++i) f[i] = std::sin(3.0 * line.x[i]) + (line.is_real(i) ? 0.0 : 0.3);
  neu.apply(f, -0.7);
  dir.apply(f, 2.5);
  EXPECT_NEAR(m.X.row(b0).dot(f), -0.7, 1e-12);
  EXPECT_NEAR(m.W.row(b1).dot(f), 2.5, 1e-12);
}

TEST(ModifiedSphMatrix, DirichletValuesAreExactOnTheSet) {
  const double ps = 0.1;
  auto x = sph::lattice_block(sph::LatticeKind::Square, 16, 12, ps, sph::Vec2(-0.3, -0.3));
  std::vector<double> dV(x.size(), ps * ps);
  const KernelFn k = sph::make_kernel_fn("modified_mollifier", 2, 3.0 * ps);
  const auto m = sph::build_sph_matrices_2d(k, x, dV);
  std::vector<int> set;  // the left boundary column x = 0 and the ghost columns x < 0
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i].x() < 1e-9) set.push_back(static_cast<int>(i));
  }
  sph::ModifiedSphMatrix msm(m.W, set);
  Eigen::VectorXd f(x.size()), fbar(set.size());
  for (std::size_t i = 0; i < x.size(); ++i) f[i] = std::cos(x[i].x() + 2 * x[i].y());
  for (std::size_t k2 = 0; k2 < set.size(); ++k2) fbar[k2] = 0.25 * x[set[k2]].y();
  msm.apply(f, fbar);
  Eigen::VectorXd s(x.size());
  sph::spmv(m.W, f, s);
  for (std::size_t k2 = 0; k2 < set.size(); ++k2) EXPECT_NEAR(s[set[k2]], fbar[k2], 1e-9);
}

TEST(CentralDifference, SecondOrderOnAHarmonicOscillator) {
  auto error = [](double dt) {
    const double w = 2.0, T = 3.0;
    Eigen::VectorXd u(1), up(1), a(1);
    up[0] = std::cos(-w * dt);  // exact u_{-1}, u_0 = 1
    u[0] = 1.0;
    const int n = static_cast<int>(std::lround(T / dt));
    for (int i = 0; i < n; ++i) {
      a[0] = -w * w * u[0];
      sph::central_difference_step(u, up, a, dt, 0, 1);
    }
    return std::abs(u[0] - std::cos(w * n * dt));
  };
  const double e1 = error(0.01), e2 = error(0.005);
  EXPECT_NEAR(std::log2(e1 / e2), 2.0, 0.05);
  // Stable just below dt w = 2, unstable just above.
  auto grows = [](double dtw) {
    Eigen::VectorXd u(1), up(1), a(1);
    u[0] = up[0] = 1.0;
    for (int i = 0; i < 2000; ++i) { a[0] = -u[0]; sph::central_difference_step(u, up, a, dtw, 0, 1); }
    return std::abs(u[0]) > 10.0;
  };
  EXPECT_FALSE(grows(1.99));
  EXPECT_TRUE(grows(2.01));
}

sph::TlConfig1D steel_bar(double ps) {
  sph::TlConfig1D c;
  c.length = 0.15;
  c.ps = ps;
  c.modulus = 200e9;
  c.left.kind = sph::EndCondition1D::Kind::Traction;
  c.left.value = [](double t) { return t < 4e-6 ? -1e5 : 0.0; };
  c.right.kind = sph::EndCondition1D::Kind::Displacement;
  return c;
}

TEST(TlSolver1D, TractionExactAtTheEndAndWaveArrivesAtXOverC) {
  auto cfg = steel_bar(0.5e-3);
  sph::TlSolver1D bar(cfg);
  const double c = std::sqrt(200e9 / 8000.0), dt = 0.3 * bar.h() / c;
  const int g = bar.nearest(0.1);
  double t_half = -1;
  while (bar.time() < 0.1 / c + 3e-6) {
    bar.step(dt);
    if (bar.time() < 3e-6) {
      EXPECT_NEAR(bar.stress(0), -1e5, 1e-9 * 1e5);  // Neumann condition exact (eq 2.45)
    }
    if (t_half < 0 && bar.stress(g) < -0.5e5) t_half = bar.time() - dt;
  }
  ASSERT_GT(t_half, 0);
  EXPECT_NEAR(t_half, 0.1 / c, 0.02 * 0.1 / c);
}

TEST(TlSolver1D, MomentumBalanceWithFreeEnds) {
  // A displacement bump in the middle, no load: total momentum sum rho v dV stays 0 while the waves are in
  // the interior (X is antisymmetric on the uniform lattice, so sum_p dV_p (X P)_p = 0 there).
  auto cfg = steel_bar(1e-3);
  cfg.left.value = [](double) { return 0.0; };
  cfg.right.kind = sph::EndCondition1D::Kind::Traction;
  sph::TlSolver1D bar(cfg);
  bar.set_initial_displacement([](double x) { return 1e-6 * std::exp(-std::pow((x - 0.075) / 0.004, 2)); });
  const double c = 5000.0, dt = 0.3 * bar.h() / c;
  double pmax = 0, vmax = 0;
  for (int s = 0; s < 14; ++s) {  // before the (dispersive) wave tails reach the ends
    bar.step(dt);
    double p = 0;
    for (int i = 0; i < bar.n_real(); ++i) {
      p += bar.velocity(i, dt);
      vmax = std::max(vmax, std::abs(bar.velocity(i, dt)));
    }
    pmax = std::max(pmax, std::abs(p));
  }
  EXPECT_GT(vmax, 0);
  EXPECT_LT(pmax, 1e-12 * vmax * bar.n_real());
}

TEST(TlSolver1D, UpdatedAndTotalLagrangianAgreeToFirstOrderInTheStrain) {
  // The same pulse through the bar with the SPH matrices built once (TL) and rebuilt from the current
  // positions every step (UL, Section 4.7.2): the two describe the same linear bar and part only through the
  // geometry, so the gauge histories differ at second order in the amplitude -- relative difference
  // proportional to the strain (5e-7 at the -100 kPa pulse). Both halves are checked: small at the thesis's
  // pulse, and 10x the pulse gives 10x the relative difference (a UL that fell back to TL, or one that
  // differs at first order, fails).
  auto run = [](double amp) {
    auto cfg = steel_bar(0.5e-3);
    cfg.left.value = [=](double t) { return t < 4e-6 ? -1e5 * amp : 0.0; };
    sph::TlSolver1D tl(cfg);
    cfg.updated_lagrangian = true;
    sph::TlSolver1D ul(cfg);
    const double c = std::sqrt(200e9 / 8000.0), dt = 0.3 * tl.h() / c;
    const int g = tl.nearest(0.1);
    double diff = 0, peak = 0;
    while (tl.time() < 0.1 / c + 6e-6) {
      tl.step(dt);
      ul.step(dt);
      diff = std::max(diff, std::abs(tl.stress(g) - ul.stress(g)));
      peak = std::max(peak, std::abs(tl.stress(g)));
    }
    EXPECT_TRUE(ul.finite());
    EXPECT_GT(peak, 0.9e5 * amp);  // the pulse has arrived (unsmoothed, it overshoots: Fig 4.8)
    return diff / peak;
  };
  const double rel1 = run(1.0), rel10 = run(10.0);
  EXPECT_LT(rel1, 1e-4);
  EXPECT_NEAR(rel10 / rel1, 10.0, 1.0);
}

TEST(TlSolver1D, NeoHookeanInverseLaw) {
  auto cfg = steel_bar(1e-3);
  cfg.law = sph::TlConfig1D::Law::NeoHookean;
  cfg.lame = sph::lame_from_young_poisson(200e9, 0.3);
  sph::TlSolver1D bar(cfg);
  for (double T : {-1e9, 1e5, 3e10}) EXPECT_NEAR(bar.law(bar.inverse_law(T)), T, 1e-6 * std::abs(T));
}

}  // namespace

namespace {

TEST(CorrectiveFactorSet, BoundaryValuesExactInTwoDimensions) {
  // Left boundary column of a 2D block with three ghost columns: all boundary values exact at once.
  const double ps = 0.1;
  const auto x = sph::lattice_block(sph::LatticeKind::Square, 14, 10, ps, sph::Vec2(-0.3, 0.0));
  const sph::KernelFn k = sph::make_kernel_fn("modified_mollifier", 2, 3.5 * ps);
  const auto m = sph::build_sph_matrices_2d(k, x, std::vector<double>(x.size(), ps * ps));
  std::vector<int> b, g;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (std::abs(x[i].x()) < 1e-9) b.push_back(static_cast<int>(i));
    if (x[i].x() < -1e-9) g.push_back(static_cast<int>(i));
  }
  sph::CorrectiveFactorSet cs(m.W, k, x, b, g);
  Eigen::VectorXd f(x.size()), fbar(b.size());
  for (std::size_t i = 0; i < x.size(); ++i) f[i] = std::sin(2 * x[i].x() + x[i].y());
  for (std::size_t j = 0; j < b.size(); ++j) fbar[j] = 1.0 + 0.5 * x[b[j]].y();
  cs.apply(f, fbar);
  for (std::size_t j = 0; j < b.size(); ++j) EXPECT_NEAR(m.W.row(b[j]).dot(f), fbar[j], 1e-9);
}

}  // namespace
