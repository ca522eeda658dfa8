// Every solver stops with a BlowUp that names the failing step, its time and the first particle whose state is
// no longer finite, in the one format of core/blow_up.hpp: SPAM, the molecular dynamics and the total-Lagrangian
// solvers in 1D and 2D, each given one particle with a non-finite value in the middle of the body. (Gray's
// scheme: test_gray_solver.cpp and test_run_loop.cpp.) The value spreads to the neighbours within the step, so
// the particle named is checked to be bad and every particle before it good, rather than to be the one set.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <regex>
#include <string>

#include "core/blow_up.hpp"
#include "core/lattices.hpp"
#include "core/materials.hpp"
#include "ismail2009/scenes/domain_2d.hpp"
#include "spam/molecular_dynamics.hpp"
#include "spam/spam_solver.hpp"
#include "total_lagrangian/solver_1d.hpp"
#include "total_lagrangian/solver_2d.hpp"

namespace {

using sph::Vec2;

struct Named { long step; double time; std::size_t particle; };

// Parses "blow-up at step S, t = T, particle P at (x, y): what"; fails the test on any other form.
Named parse(const std::string& what) {
  static const std::regex form(R"(^blow-up at step (\d+), t = ([^,]+), particle (\d+) at \([^)]*\): .+$)");
  std::smatch m;
  EXPECT_TRUE(std::regex_match(what, m, form)) << what;
  if (m.size() != 4) return {-1, -1, 0};
  return {std::stol(m[1]), std::stod(m[2]), std::stoul(m[3])};
}

// Steps `solver` once with dt and returns what its BlowUp names (a step that does not throw fails the test):
// the message and the exception's members agree; the members are returned.
template <class Solver>
Named blow_up_of_one_step(Solver& solver, double dt) {
  try {
    solver.step(dt);
  } catch (const sph::BlowUp& e) {
    const Named n = parse(e.what());
    EXPECT_EQ(n.step, e.step);
    EXPECT_NEAR(n.time, e.time, 1e-5 * std::abs(e.time));  // the message prints 6 significant digits
    EXPECT_EQ(n.particle, e.particle);
    return {e.step, e.time, e.particle};
  }
  ADD_FAILURE() << "no blow-up detected";
  return {-1, -1, 0};
}

// The particle named is bad, every one before it good.
void expect_first_bad(std::size_t named, std::size_t n, const std::function<bool(std::size_t)>& good) {
  ASSERT_LT(named, n);
  EXPECT_FALSE(good(named)) << "particle " << named;
  for (std::size_t i = 0; i < named; ++i) EXPECT_TRUE(good(i)) << "particle " << i << " before the one named";
}

TEST(BlowUp, SpamNamesStepTimeAndFirstBadParticle) {
  const auto x0 = sph::hexagon(6, 1.0);
  sph::SpamState y(x0.size());
  for (std::size_t i = 0; i < y.size(); ++i) {
    y.x[i] = x0[i];
    y.rho[i] = std::sqrt(4.0 / 3.0);
  }
  sph::SpamParams p;
  p.box = sph::Box2{-12, -12, 12, 12, false, false};
  auto sim = sph::make_spam(sph::SpamOptions{}, p, y);
  const std::size_t k = x0.size() / 2;
  sim->state().v[k].x() = std::nan("");
  const Named n = blow_up_of_one_step(*sim, 0.01);
  EXPECT_EQ(n.step, 1);
  EXPECT_DOUBLE_EQ(n.time, 0.01);
  const auto& s = sim->state();
  expect_first_bad(n.particle, s.size(), [&](std::size_t i) { return s.x[i].allFinite() && s.v[i].allFinite(); });
  EXPECT_FALSE(s.x[k].allFinite() && s.v[k].allFinite());
}

TEST(BlowUp, MolecularDynamicsNamesStepTimeAndFirstBadParticle) {
  const auto x0 = sph::hexagon(6, 1.0);
  sph::MdState s{x0, std::vector<Vec2>(x0.size(), Vec2::Zero())};
  const std::size_t k = x0.size() / 2;
  s.v[k].y() = std::nan("");
  sph::MdSolver md(x0, s, sph::MdParams{});
  const Named n = blow_up_of_one_step(md, 0.05);
  EXPECT_EQ(n.step, 1);
  EXPECT_DOUBLE_EQ(n.time, 0.05);
  const auto& y = md.state();
  expect_first_bad(n.particle, y.x.size(), [&](std::size_t i) { return y.x[i].allFinite() && y.v[i].allFinite(); });
}

TEST(BlowUp, TotalLagrangian1DNamesStepTimeAndFirstBadParticle) {
  sph::TlConfig1D c;
  c.length = 0.15;
  c.ps = 1e-3;
  c.modulus = 200e9;
  c.left.kind = sph::EndCondition1D::Kind::Traction;
  c.left.value = [](double) { return 0.0; };
  c.right.kind = sph::EndCondition1D::Kind::Displacement;
  sph::TlSolver1D bar(c);
  const int k = bar.nearest(0.075);
  bar.scale_displacement(k, std::nan(""));
  const double dt = 0.3 * bar.h() / std::sqrt(200e9 / 8000.0);
  const Named n = blow_up_of_one_step(bar, dt);
  EXPECT_EQ(n.step, 1);
  EXPECT_DOUBLE_EQ(n.time, dt);
  // The solver counts the ghosts in front of the real particles; the middle of the bar is far from them.
  ASSERT_GE(n.particle, static_cast<std::size_t>(bar.first_real()));
  const std::size_t first = static_cast<std::size_t>(bar.first_real());
  expect_first_bad(n.particle - first, bar.size(), [&](std::size_t i) {
    return std::isfinite(bar.u(static_cast<int>(i))) && std::isfinite(bar.stress(static_cast<int>(i)));
  });
}

TEST(BlowUp, TotalLagrangian2DNamesStepTimeAndFirstBadParticle) {
  const double ps = 0.5e-3, Lx = 20 * ps, Ly = 10 * ps;
  auto dom = scenes::rectangle_domain(Lx, Ly, 0, 1, 2, 3);
  const sph::BoundaryCondition2D free;  // the default: traction-free
  auto cfg = scenes::make_body(dom, {free, free, free, free}, ps, 3.5);
  cfg.rho = 8000;
  cfg.lame = sph::lame_from_young_poisson(200e9, 0.3);
  sph::TlSolver2D body(std::move(cfg));
  const Vec2 centre(Lx / 2, Ly / 2);
  const int k = body.nearest(centre);
  body.set_initial_displacement([&](const Vec2& X) { return X == body.X(k) ? Vec2(std::nan(""), 0.0) : Vec2::Zero(); });
  const double dt = 0.3 * body.h() / sph::longitudinal_wave_speed(sph::lame_from_young_poisson(200e9, 0.3), 8000);
  const Named n = blow_up_of_one_step(body, dt);
  EXPECT_EQ(n.step, 1);
  EXPECT_DOUBLE_EQ(n.time, dt);
  expect_first_bad(n.particle, body.size(), [&](std::size_t i) {
    return body.u(static_cast<int>(i)).allFinite() && body.P(static_cast<int>(i)).allFinite();
  });
}

}  // namespace
