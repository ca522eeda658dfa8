// 2D total Lagrangian SPH (Ismail 2009 Section 5.4): uniform states are equilibria of the discrete body with
// its boundary treatment (Dirichlet by the modified SPH matrix, traction by ghost reflection), and a plane
// strain wave arrives at x / c_L.
#include <gtest/gtest.h>

#include <cmath>

#include "materials.hpp"
#include "scenes/ismail_plate.hpp"
#include "total_lagrangian_2d.hpp"

namespace {

using sph::Vec2;

sph::BoundaryCondition2D cond(bool d0, double v0, bool d1, double v1, double lam0 = 0, double lam1 = 0) {
  sph::BoundaryCondition2D c;
  c.dirichlet[0] = d0;
  c.dirichlet[1] = d1;
  // Dirichlet values: a linear field lam X (+ v); tractions: the constant v.
  c.value[0] = [=](const Vec2& X, double) { return d0 ? lam0 * X.x() + v0 : v0; };
  c.value[1] = [=](const Vec2& X, double) { return d1 ? lam1 * X.y() + v1 : v1; };
  return c;
}

TEST(Body2D, UniformStretchHeldByDirichletEdgesIsStatic) {
  const double ps = 0.5e-3, Lx = 30 * ps, Ly = 5 * ps, e1 = 0.2, e2 = 0.1;
  auto dom = scenes::rectangle_domain(Lx, Ly, 0, 1, 2, 3);
  // u1 = e1 X on left/right, u2 = e2 Y on bottom/top, the other components traction-free.
  auto cfg = scenes::make_body(dom, {cond(true, 0, false, 0, e1), cond(true, 0, false, 0, e1),
                                     cond(false, 0, true, 0, 0, e2), cond(false, 0, true, 0, 0, e2)}, ps, 3.5);
  cfg.rho = 8000;
  cfg.lame = sph::lame_from_young_poisson(200e9, 0.3);
  sph::Body2D body(std::move(cfg));
  body.set_initial_displacement([&](const Vec2& X) { return Vec2(e1 * X.x(), e2 * X.y()); });
  const double c = sph::longitudinal_wave_speed(sph::lame_from_young_poisson(200e9, 0.3), 8000);
  for (int s = 0; s < 200; ++s) body.step(0.3 * body.h() / c);
  double dev = 0;
  for (int i = 0; i < body.n_real(); ++i) dev = std::max(dev, (body.u(i) - Vec2(e1 * body.X(i).x(), e2 * body.X(i).y())).norm());
  EXPECT_LT(dev, 1e-3 * e1 * Lx);  // the lattice factor of the gradient (1.3e-3 at h = 3.5 ps) may move it slightly
  const int centre = body.nearest({Lx / 2, Ly / 2});
  const sph::Tensor2 T = body.cauchy(centre);
  sph::Tensor2 F;
  F << 1 + e1, 0, 0, 1 + e2;
  const sph::Tensor2 Texact = sph::neo_hookean_cauchy<2>(sph::lame_from_young_poisson(200e9, 0.3), F);
  EXPECT_NEAR(T(0, 0), Texact(0, 0), 0.01 * std::abs(Texact(0, 0)));
}

TEST(Body2D, UniaxialTractionStateIsStatic) {
  // Plane strain, Hooke: traction s on the left/right edges, free top/bottom: the uniform uniaxial stress
  // state is the exact static solution.
  const double ps = 1e-3, Lx = 20 * ps, Ly = 10 * ps, E = 200e9, nu = 0.3, s = 1e8;
  auto dom = scenes::rectangle_domain(Lx, Ly, 0, 1, 2, 2);
  auto cfg = scenes::make_body(dom, {cond(false, -s, false, 0), cond(false, s, false, 0), cond(false, 0, false, 0)}, ps, 3.5);
  cfg.rho = 8000;
  cfg.law = sph::BodyConfig2D::Law::Hooke;
  cfg.lame = sph::lame_from_young_poisson(E, nu);
  sph::Body2D body(std::move(cfg));
  const double e11 = s * (1 - nu * nu) / E;   // plane strain uniaxial stress: eps11 = (1 - nu^2) s / E
  const double e22ps = -nu * (1 + nu) / E * s;  // eps22 = -nu (1 + nu) s / E
  body.set_initial_displacement([&](const Vec2& X) { return Vec2(e11 * (X.x() - Lx / 2), e22ps * (X.y() - Ly / 2)); });
  const double c = sph::longitudinal_wave_speed(cfg.lame, 8000);
  double vmax = 0;
  for (int st = 0; st < 100; ++st) {
    body.step(0.3 * body.h() / c);
  }
  for (int i = 0; i < body.n_real(); ++i)
    vmax = std::max(vmax, (body.u(i) - Vec2(e11 * (body.X(i).x() - Lx / 2), e22ps * (body.X(i).y() - Ly / 2))).norm());
  EXPECT_LT(vmax, 0.01 * e11 * Lx);
  const sph::Tensor2 P = body.P(body.nearest({Lx / 2, Ly / 2}));
  EXPECT_NEAR(P(0, 0), s, 0.01 * s);
  EXPECT_NEAR(P(1, 1), 0.0, 0.01 * s);
}

}  // namespace
