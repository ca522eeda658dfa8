// The Verlet pair list of Gray's scheme and SPAM (src/core/pair_list.hpp) against the O(N^2) search
// (sph::brute_force_neighbours), with and without periodic wrap and skin: every pair within the support must
// be listed exactly once in each direction with its minimum-image x_a - x_b and the formulation's W and F;
// a skin must save re-collections while particles move less than half of it (no pair can then have come
// within the support unseen), and must not save one once a particle has moved further.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <random>
#include <vector>

#include "same_bits.hpp"
#include "core/kernels.hpp"
#include "core/neighbours.hpp"
#include "core/pair_list.hpp"

namespace {

using sph::Box2;
using sph::Vec2;

constexpr double eps = std::numeric_limits<double>::epsilon();
const double R = 0.1;  // the support radius

// W = (1 - r/R)^2 and grad_a W = dx F, F = W'(r)/r = -2 (1 - r/R)/(R r); both zero beyond the support.
void geometry(double r, double& W, double& F) {
  const double q = 1.0 - r / R;
  W = r < R ? q * q : 0.0;
  F = r < R ? -2.0 * q / (R * r) : 0.0;
}

std::vector<Vec2> random_points(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> x(n);
  for (Vec2& p : x) p = Vec2(u(rng), u(rng));
  return x;
}

// Minimum image by the IEEE remainder, exact and independent of CellList2D::displacement. The library's
// d - L nearbyint(d/L) is exact too for the |d| < L/2 of listed pairs (L n with n in {-1, 0, 1} is exact,
// and so is the difference, being representable), so dx is compared bit for bit.
Vec2 min_image(const Vec2& a, const Vec2& b, const Box2& box) {
  Vec2 d = a - b;
  if (box.periodic_x) d.x() = std::remainder(d.x(), box.Lx());
  if (box.periodic_y) d.y() = std::remainder(d.y(), box.Ly());
  return d;
}

// Checks the list against the direct search; returns the number of pairs within the support and the number
// of candidates.
std::pair<std::size_t, std::size_t> expect_matches_brute_force(const sph::PairList& list, const std::vector<Vec2>& x,
                                                               const Box2& box, double skin) {
  const auto near = sph::brute_force_neighbours(x, box, R);
  std::size_t within = 0, candidates = 0;
  for (std::size_t a = 0; a < x.size(); ++a) {
    std::set<std::uint32_t> cand;  // the candidates: within support + skin, each once
    for (std::uint32_t k = list.start[a]; k < list.start[a + 1]; ++k) {
      EXPECT_TRUE(cand.insert(list.cand[k]).second) << "candidate " << a << "-" << list.cand[k] << " listed twice";
      EXPECT_LT(min_image(x[a], x[list.cand[k]], box).norm(), R + skin);
    }
    candidates += cand.size();
    std::map<std::size_t, std::uint32_t> slot;  // the pairs inside the support: neighbour -> its entry
    for (std::uint32_t k = list.first(a); k < list.last(a); ++k) {
      EXPECT_TRUE(slot.emplace(list.b[k], k).second) << "pair " << a << "-" << list.b[k] << " listed twice";
      EXPECT_TRUE(cand.count(list.b[k])) << "pair " << a << "-" << list.b[k] << " is not a candidate";
      EXPECT_EQ(list.dx[k], min_image(x[a], x[list.b[k]], box)) << a << "-" << list.b[k];
    }
    for (std::size_t b : near[a]) {
      const auto it = slot.find(b);
      if (it == slot.end()) {
        ADD_FAILURE() << "pair " << a << "-" << b << " within the support is missing";
        continue;
      }
      // |dx| may differ by an ulp from the list's (fused or not): |W'| <= 2/R makes that <= 2 ulp(r)/R
      // <= 4 eps in W, and F, a ratio of O(1) factors, is within a few eps relative.
      double W, F;
      geometry(list.dx[it->second].norm(), W, F);
      EXPECT_GT(W, 0.0);
      EXPECT_NEAR(list.W[it->second], W, 4 * eps);
      EXPECT_NEAR(list.F[it->second], F, 8 * eps * std::abs(F));
      slot.erase(it);
      ++within;
    }
    EXPECT_TRUE(slot.empty()) << a << ": " << slot.size() << " pairs listed beyond the support";
  }
  return {within, candidates};
}

TEST(PairList, MatchesTheDirectSearchWithAndWithoutPeriodicWrapAndSkin) {
  const std::vector<Vec2> x = random_points(400, 1);
  for (bool periodic : {false, true})
    for (double skin : {0.0, 0.03}) {
      const Box2 box{0, 0, 1, 1, periodic, periodic};
      sph::CellList2D cells(box, R + skin);
      sph::PairList list;
      list.update(cells, x, R, skin, geometry);
      EXPECT_EQ(list.collections, 1);
      // ~ pi R^2 N = 12.6 neighbours per particle inside (fewer near open edges): thousands of pairs.
      const auto [within, candidates] = expect_matches_brute_force(list, x, box, skin);
      EXPECT_GT(within, 3000u) << "periodic " << periodic << " skin " << skin;
      if (skin > 0) EXPECT_GT(candidates, within);  // the skin holds candidates beyond the support
      else EXPECT_EQ(candidates, within);
    }
}

// Moves every particle by `length` in a random direction.
std::vector<Vec2> jiggle(std::vector<Vec2> x, double length, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI);
  for (Vec2& p : x) {
    const double t = angle(rng);
    p += length * Vec2(std::cos(t), std::sin(t));
  }
  return x;
}

TEST(PairList, SkinSavesRecollectionsOnlyWhileEveryMoveIsBelowHalfTheSkin) {
  const double skin = 0.04;
  const Box2 box{0, 0, 1, 1, true, true};
  sph::CellList2D cells(box, R + skin);
  sph::PairList list;
  const std::vector<Vec2> x0 = random_points(400, 2);
  list.update(cells, x0, R, skin, geometry);
  ASSERT_EQ(list.collections, 1);
  // Every particle 0.45 skin away: no re-collection, yet the geometry is that of the new positions and
  // no pair within the support is missed (two moves of < skin/2 cannot close a gap of more than skin).
  const std::vector<Vec2> x1 = jiggle(x0, 0.45 * skin, 3);
  const std::vector<Vec2> dx_before = list.dx;
  list.update(cells, x1, R, skin, geometry);
  EXPECT_EQ(list.collections, 1);
  EXPECT_NE(list.dx, dx_before);
  EXPECT_GT(expect_matches_brute_force(list, x1, box, 2 * skin).first, 3000u);  // candidates now up to R + 2 skin
  // One particle 0.55 skin from where it was at the collection: collected again.
  std::vector<Vec2> x2 = x0;
  x2[7] += Vec2(0.55 * skin, 0.0);
  list.update(cells, x2, R, skin, geometry);
  EXPECT_EQ(list.collections, 2);
  expect_matches_brute_force(list, x2, box, skin);
}

TEST(PairList, WithoutSkinAnyMoveRecollects) {
  const Box2 box{0, 0, 1, 1, false, false};
  sph::CellList2D cells(box, R);
  sph::PairList list;
  std::vector<Vec2> x = random_points(300, 4);
  list.update(cells, x, R, 0.0, geometry);
  list.update(cells, x, R, 0.0, geometry);  // nothing moved: nothing to collect
  EXPECT_EQ(list.collections, 1);
  x[123].y() += 1e-12;  // the smallest move counts
  list.update(cells, x, R, 0.0, geometry);
  EXPECT_EQ(list.collections, 2);
  EXPECT_GT(expect_matches_brute_force(list, x, box, 0.0).first, 1000u);
}

}  // namespace

#if defined(__AVX512F__) && defined(__AVX512VL__)
// A kernel with an eight-wide form (the cubic spline) takes PairList::refresh's AVX-512 path on an open box:
// the same pairs in the same order as the scalar path (the same kernel wrapped in a lambda, which has no
// eight-wide form), x_a - x_b exact, and W, F those of the kernel at the square root of x^2 + y^2 summed
// without a fused multiply-add (volatile keeps the compiler from fusing the reference), bit for bit where the
// build fixes the arithmetic (same_bits.hpp).
TEST(PairList, EightWideRefreshGivesTheScalarPairsAndBits) {
  const double h = 0.04;
  const sph::CubicSpline kernel(2);
  const auto g = kernel.at(h);
  auto scalar = [g](double r, double& W, double& F) { g(r, W, F); };
  const std::vector<Vec2> x = random_points(600, 5);
  const Box2 box{0, 0, 1, 1, false, false};
  for (bool half : {true, false}) {
    sph::CellList2D cells_a(box, 2.2 * h), cells_b(box, 2.2 * h);
    sph::PairList wide, one;
    wide.half = one.half = half;
    wide.update(cells_a, x, 2 * h, 0.2 * h, g);
    one.update(cells_b, x, 2 * h, 0.2 * h, scalar);
    ASSERT_EQ(wide.active, one.active) << "half " << half;
    ASSERT_EQ(wide.b.size(), one.b.size());
    double Wscale = 0, Fscale = 0;  // what "a few roundings" is relative to where the build does not fix the bits
    for (std::size_t k = 0; k < one.W.size(); ++k) {
      Wscale = std::max(Wscale, std::abs(one.W[k]));
      Fscale = std::max(Fscale, std::abs(one.F[k]));
    }
    std::size_t pairs = 0;
    for (std::size_t a = 0; a < x.size(); ++a)
      for (std::uint32_t k = wide.first(a); k < wide.last(a); ++k, ++pairs) {
        ASSERT_EQ(wide.b[k], one.b[k]) << a;
        const Vec2 d = x[a] - x[wide.b[k]];
        EXPECT_EQ(wide.dx[k], d);
        volatile double xx = d.x() * d.x(), yy = d.y() * d.y();
        double W, F;
        g(std::sqrt(xx + yy), W, F);
        EXPECT_TRUE(same_bits(W, wide.W[k], Wscale)) << a << "-" << wide.b[k];
        EXPECT_TRUE(same_bits(F, wide.F[k], Fscale)) << a << "-" << wide.b[k];
      }
    // pi (2h)^2 N = 12 neighbours per particle (fewer near the open edges): ~3600 pairs, each once in a half list
    EXPECT_GT(pairs, half ? 3000u : 6000u);
  }
}
#endif
