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

// The measurement of a sample is a function of the particle state (what peer_slab feeds a peer's frames to): on
// the lattice nothing is stretched, narrowed or open; with the right half moved 0.5 to the right the ends have
// parted between the halves, and the summary dates the parting, the opening and the crack from the samples.
TEST(Slab, MeterOnTheLatticeAndOnASlabCutInTwo) {
  const auto slab = scenes::make_slab(small_slab(), 1.0);  // 30 x 10 particles, dp = 0.1, bands 2 columns wide
  const scenes::SlabGeometry g = scenes::slab_geometry(slab);
  const scenes::SlabRunSpec spec;
  scenes::SlabMeter meter(g, spec);
  const auto whole = meter.measure(0.0, slab.body.x, NAN, NAN);
  EXPECT_EQ(whole.sample.extension, 0.0);
  EXPECT_EQ(whole.sample.pieces, 1u);
  EXPECT_EQ(whole.sample.parted, 0);
  EXPECT_NEAR(whole.sample.closest, 0.1, 1e-12);
  EXPECT_NEAR(whole.sample.widest_gap, 0.1, 1e-12);
  EXPECT_NEAR(whole.sample.neck_width, 1.0, 1e-12);  // 10 rows: y extent 0.9 plus dp
  EXPECT_TRUE(std::isnan(whole.sample.ke));
  std::vector<sph::Vec2> cut = slab.body.x;
  for (std::size_t a = 0; a < cut.size(); ++a)
    if (g.column[a] >= 15) cut[a].x() += 0.5;
  const auto apart = meter.measure(1.0, cut, NAN, NAN);
  EXPECT_NEAR(apart.sample.extension, 0.5, 1e-12);
  EXPECT_EQ(apart.sample.pieces, 2u);
  EXPECT_EQ(apart.sample.parted, 1);
  EXPECT_NEAR(apart.reach_l, 1.45, 1e-12);
  EXPECT_NEAR(apart.reach_r, 2.05, 1e-12);
  EXPECT_NEAR(apart.sample.widest_gap, 0.6, 1e-12);
  EXPECT_NEAR(apart.sample.gap_x, 1.75, 1e-12);
  const auto sum = scenes::summarise_slab({whole, apart}, spec, 0.1);
  EXPECT_EQ(sum.fracture_time, 1.0);
  EXPECT_EQ(sum.first_split_time, 1.0);
  EXPECT_NEAR(sum.crack_x, 1.75, 1e-12);
  EXPECT_NEAR(sum.crack_from_junction, 1.3, 1e-12);  // the left piece reaches 1.45, its band edge is at 0.15
  EXPECT_EQ(sum.neck_before_fracture, whole.sample.neck_width);
  EXPECT_EQ(sum.opening_time, 1.0);
  EXPECT_NEAR(sum.opening_from_junction, 1.6, 1e-12);  // 1.75 - 0.15 = 3.35 - 1.75
  EXPECT_EQ(sum.clumping_time, -1.0);
  EXPECT_TRUE(std::isnan(sum.onset_time));  // the lattice has no neck, and a parted sample is not an onset
  EXPECT_TRUE(scenes::slab_stops_at(1.0, 11.0, spec));
  EXPECT_FALSE(scenes::slab_stops_at(1.0, 10.5, spec));
  EXPECT_FALSE(scenes::slab_stops_at(-1.0, 100.0, spec));
  EXPECT_THROW(meter.measure(2.0, std::vector<sph::Vec2>(3, sph::Vec2::Zero()), NAN, NAN), std::invalid_argument);
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
