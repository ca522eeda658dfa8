// Fracture detection by connected components.
#include <gtest/gtest.h>

#include "core/fragments.hpp"

namespace {

TEST(Fragments, CountsPiecesSeparatedByMoreThanTheLinkDistance) {
  const double dp = 0.1;
  auto a = sph::lattice_block(sph::LatticeKind::Square, 10, 5, dp);
  const auto b = sph::lattice_block(sph::LatticeKind::Square, 10, 5, dp, sph::Vec2(1.0 + 0.2, 0.0));  // gap 0.3
  a.insert(a.end(), b.begin(), b.end());
  const sph::Box2 box{-1, -1, 3, 2, false, false};
  EXPECT_EQ(sph::find_fragments(a, box, 1.5 * dp).count, 2u);   // gap 3 dp > link: two pieces
  EXPECT_EQ(sph::find_fragments(a, box, 3.5 * dp).count, 1u);   // link bridges the gap
  const auto f = sph::find_fragments(a, box, 1.5 * dp);
  EXPECT_EQ(f.largest(), 50u);
  EXPECT_NE(f.label.front(), f.label.back());
}

TEST(Fragments, ExcludedParticlesDoNotBridge) {
  const double dp = 0.1;
  auto x = sph::lattice_block(sph::LatticeKind::Square, 21, 1, dp);  // a chain
  std::vector<bool> include(x.size(), true);
  include[10] = false;  // remove the middle link
  const auto f = sph::find_fragments(x, {-1, -1, 3, 1, false, false}, 1.5 * dp, include);
  EXPECT_EQ(f.count, 2u);
  EXPECT_EQ(f.label[10], SIZE_MAX);
}

TEST(Fragments, PeriodicWrapJoinsTheEnds) {
  const double dp = 0.1;
  const auto x = sph::lattice_block(sph::LatticeKind::Square, 10, 1, dp, sph::Vec2(0.05, 0.5));
  // Two chains' worth would wrap: one chain spanning the periodic box is one piece either way, but
  // removing an interior particle leaves one piece only because the ends join across the boundary.
  std::vector<bool> include(x.size(), true);
  include[4] = false;
  EXPECT_EQ(sph::find_fragments(x, {0, 0, 1, 1, true, false}, 1.5 * dp, include).count, 1u);
  EXPECT_EQ(sph::find_fragments(x, {0, 0, 1, 1, false, false}, 1.5 * dp, include).count, 2u);
}

}  // namespace
