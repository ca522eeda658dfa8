// Scene set-ups of the drivers (experiments/*/scenes): what an ensemble member differs in, and nothing else.
#include <gtest/gtest.h>

#include <cmath>

#include "gray2001/scenes/slab.hpp"

namespace {

scenes::SlabSpec small_slab() {
  scenes::SlabSpec s;
  s.dp = 0.1;
  return s;
}

}  // namespace

TEST(Slab, JitterDisplacesEveryParticleWithinItsBoundRepeatablyAndKeepsTheBands) {
  const scenes::SlabSpec lattice_spec = small_slab();
  scenes::SlabSpec a = lattice_spec, b = lattice_spec, c = lattice_spec;
  a.jitter = b.jitter = c.jitter = 1e-3;
  a.seed = b.seed = 7;
  c.seed = 8;
  const auto lattice = scenes::make_slab(lattice_spec, 1.0), ja = scenes::make_slab(a, 1.0), jb = scenes::make_slab(b, 1.0),
             jc = scenes::make_slab(c, 1.0);
  ASSERT_EQ(ja.body.size(), lattice.body.size());
  EXPECT_EQ(ja.left_band, lattice.left_band);  // band membership is the lattice site's
  EXPECT_EQ(ja.right_band, lattice.right_band);
  double largest = 0, differs_from_other_seed = 0;
  for (std::size_t i = 0; i < lattice.body.size(); ++i) {
    const sph::Vec2 d = ja.body.x[i] - lattice.body.x[i];
    largest = std::max({largest, std::abs(d.x()), std::abs(d.y())});
    EXPECT_EQ(ja.body.x[i], jb.body.x[i]);  // the same seed, the same member
    differs_from_other_seed = std::max(differs_from_other_seed, (ja.body.x[i] - jc.body.x[i]).norm());
    EXPECT_EQ(ja.body.m[i], lattice.body.m[i]);
  }
  EXPECT_LE(largest, 1e-3 * 0.1);
  EXPECT_GT(largest, 0.5e-3 * 0.1);  // ~every particle moved: the largest of hundreds of draws is near the bound
  EXPECT_GT(differs_from_other_seed, 0.0);
}

TEST(Slab, NoJitterIsTheLatticeAndABadJitterIsRefused) {
  const auto s = scenes::make_slab(small_slab(), 1.0);
  for (std::size_t a = 0; a < s.body.size(); ++a) {  // added row by row: column a % nx, row a / nx
    EXPECT_EQ(s.body.x[a].x(), (static_cast<long>(a) % s.nx + 0.5) * 0.1);
    EXPECT_EQ(s.body.x[a].y(), (static_cast<long>(a) / s.nx + 0.5) * 0.1);
  }
  scenes::SlabSpec bad = small_slab();
  bad.jitter = -1e-3;
  EXPECT_THROW(scenes::make_slab(bad, 1.0), std::invalid_argument);
  bad.jitter = 0.2;
  EXPECT_THROW(scenes::make_slab(bad, 1.0), std::invalid_argument);
}

#include "gray2001/scenes/hexagon_gray.hpp"

TEST(GrayHexagon, MaterialIsHooversLatticeAndAShortRunStaysWholeAndFinite) {
  const sph::SpamParams spam;
  const sph::GrayParameters p = scenes::gray_hexagon_scheme(spam, 0.5);
  EXPECT_NEAR(p.rho0 * p.c0 * p.c0, spam.lambda + spam.eta, 1e-14);  // the 2D bulk modulus
  EXPECT_NEAR(p.mu * p.rho0 * p.c0 * p.c0, spam.eta, 1e-14);          // mu in units of rho0 c0^2
  scenes::GrayHexagonSpec s;
  s.hexagon.shells = 3;
  s.angle = 0.3;
  const auto r = scenes::run_gray_hexagon(s, "test hexagon");
  EXPECT_TRUE(r.blow_up.empty()) << r.blow_up;
  EXPECT_EQ(r.particles, 37u);  // 1 + 3n + 3n^2
  EXPECT_EQ(r.max_fragments, 1u);
  EXPECT_TRUE(std::isfinite(r.L_loss));
  EXPECT_LT(std::abs(r.L_loss), 0.5);
}
