// Lattice generators: particle counts, nearest-neighbour geometry, periodic images, input checks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

#include "core/lattices.hpp"

namespace {

using sph::LatticeKind;
using sph::Vec2;

const LatticeKind kAllKinds[] = {LatticeKind::Square, LatticeKind::FaceCentred, LatticeKind::Triangular};

// Distances from point i to every other point, sorted.
std::vector<double> distances_from(const std::vector<Vec2>& p, std::size_t i) {
  std::vector<double> d;
  for (std::size_t j = 0; j < p.size(); ++j)
    if (j != i) d.push_back((p[j] - p[i]).norm());
  std::sort(d.begin(), d.end());
  return d;
}

// Distances from point c to every point of p farther than 1e-12 (so c itself drops out), sorted.
std::vector<double> distances_to(const std::vector<Vec2>& p, const Vec2& c) {
  std::vector<double> d;
  for (const Vec2& q : p)
    if ((q - c).norm() > 1e-12) d.push_back((q - c).norm());
  std::sort(d.begin(), d.end());
  return d;
}

// Index of the point closest to c.
std::size_t closest_to(const std::vector<Vec2>& p, const Vec2& c) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < p.size(); ++i)
    if ((p[i] - c).norm() < (p[best] - c).norm()) best = i;
  return best;
}

// Number of pairs closer than tol: duplicates would show up here.
int count_coincident(const std::vector<Vec2>& p, double tol) {
  int n = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      if ((p[i] - p[j]).norm() < tol) ++n;
  return n;
}

TEST(Lattices, KindNamesRoundTripAndUnknownThrows) {
  for (LatticeKind k : kAllKinds) EXPECT_EQ(sph::lattice_kind_from_string(sph::to_string(k)), k);
  EXPECT_THROW(sph::lattice_kind_from_string("hexagonal"), std::invalid_argument);
  EXPECT_DOUBLE_EQ(sph::area_per_particle(LatticeKind::Triangular, 2.0), 4.0 * std::sqrt(3.0) / 2.0);
  EXPECT_DOUBLE_EQ(sph::area_per_particle(LatticeKind::FaceCentred, 2.0), 4.0);
}

TEST(Lattices, BlockCountsAndSpacings) {
  const double dp = 0.37;
  const Vec2 origin(1.5, -2.0);
  for (LatticeKind k : kAllKinds) {
    const auto p = sph::lattice_block(k, 7, 5, dp, origin);
    ASSERT_EQ(p.size(), 35u) << sph::to_string(k);
    EXPECT_NEAR((p[0] - origin).norm(), 0.0, 1e-15);
    // Row 1 starts one row spacing above row 0, shifted by dp/2 except on the square lattice.
    const double shift = k == LatticeKind::Square ? 0.0 : 0.5 * dp;
    EXPECT_NEAR(p[7].x() - p[0].x(), shift, 1e-14) << sph::to_string(k);
    EXPECT_NEAR(p[7].y() - p[0].y(), sph::row_spacing(k, dp), 1e-14);
    EXPECT_NEAR(p[14].x() - p[0].x(), 0.0, 1e-14) << "even rows are not shifted";
    EXPECT_NEAR(p[1].x() - p[0].x(), dp, 1e-14);
    EXPECT_EQ(count_coincident(p, 1e-3 * dp), 0);
  }
  EXPECT_TRUE(sph::lattice_block(LatticeKind::Square, 0, 4, dp).empty());
}

// The nearest-neighbour shells of an interior particle: square 4 at dp, then 4 at sqrt(2) dp;
// face-centred 2 at dp (in the row), then 4 at sqrt(5)/2 dp (adjacent rows shifted by dp/2);
// triangular 6 at dp, then 6 at sqrt(3) dp.
TEST(Lattices, NearestNeighbourShellsOfAnInteriorParticle) {
  const double dp = 0.25;
  struct Shell { LatticeKind k; int n1; double r2; int n2; };
  const Shell shells[] = {{LatticeKind::Square, 4, std::sqrt(2.0), 4},
                          {LatticeKind::FaceCentred, 2, std::sqrt(5.0) / 2.0, 4},
                          {LatticeKind::Triangular, 6, std::sqrt(3.0), 6}};
  for (const Shell& s : shells) {
    const auto p = sph::lattice_block(s.k, 9, 9, dp);
    const std::size_t centre = 4 * 9 + 4;  // row 4 (even), column 4
    const auto d = distances_from(p, centre);
    for (int i = 0; i < s.n1; ++i) EXPECT_NEAR(d[i], dp, 1e-12) << sph::to_string(s.k) << " shell 1, " << i;
    for (int i = s.n1; i < s.n1 + s.n2; ++i)
      EXPECT_NEAR(d[i], s.r2 * dp, 1e-12) << sph::to_string(s.k) << " shell 2, " << i;
    EXPECT_GT(d[s.n1 + s.n2], s.r2 * dp + 1e-6) << sph::to_string(s.k) << ": shell 2 has too many points";
  }
}

// rectangle(): particles at the centres of their own cells, n per row when the side is a whole number of
// spacings (also on the shifted rows: the lattice point at x0 lies in the half-open [x0, x0 + Lx)).
TEST(Lattices, RectangleCountsAndPlacement) {
  const double dp = 0.1, x0 = -0.3, y0 = 0.2;
  for (LatticeKind k : kAllKinds) {
    const double dy = sph::row_spacing(k, dp);
    const int ny = 8, nx = 12;
    const double Lx = nx * dp, Ly = ny * dy;
    const auto p = sph::rectangle(k, x0, y0, Lx, Ly, dp);
    EXPECT_EQ(p.size(), static_cast<std::size_t>(nx * ny)) << sph::to_string(k);
    for (const Vec2& q : p) {
      EXPECT_GE(q.x(), x0);  // half-open: x0 itself may be taken (shifted rows), nothing left of it
      EXPECT_LT(q.x(), x0 + Lx - 1e-12);
      EXPECT_GT(q.y(), y0);
      EXPECT_LT(q.y(), y0 + Ly);
    }
    EXPECT_NEAR(p.front().x(), x0 + 0.5 * dp, 1e-12);
    EXPECT_NEAR(p.front().y(), y0 + 0.5 * dy, 1e-12);
    EXPECT_EQ(count_coincident(p, 1e-3 * dp), 0);
    // Tiled periodically with periods (Lx, Ly) the particles form the infinite lattice: every particle has
    // the full first shell (ny even, so the row parity is periodic too).
    const auto tiled = sph::periodic_images(p, Lx, Ly, 1);
    const int n1 = k == LatticeKind::Square ? 4 : k == LatticeKind::FaceCentred ? 2 : 6;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const auto d = distances_to(tiled, p[i]);
      ASSERT_NEAR(d[n1 - 1], dp, 1e-12) << sph::to_string(k) << " particle " << i;
      ASSERT_GT(d[n1], dp * 1.01) << sph::to_string(k) << " particle " << i;
    }
  }
  // A side that is not a whole number of spacings: the last cell that fits whole.
  EXPECT_EQ(sph::rectangle(LatticeKind::Square, 0, 0, 0.35, 0.2, 0.1).size(), 6u);
}

// ring(): a disc (r_inner = 0) contains the centre and its first shell exactly.
TEST(Lattices, SmallDiscsAreTheFirstShells) {
  const double dp = 0.2;
  const Vec2 c(0.3, -0.7);
  EXPECT_EQ(sph::ring(LatticeKind::Square, c, 0.0, 1.01 * dp, dp).size(), 5u);
  EXPECT_EQ(sph::ring(LatticeKind::Triangular, c, 0.0, 1.01 * dp, dp).size(), 7u);
  EXPECT_EQ(sph::ring(LatticeKind::FaceCentred, c, 0.0, 1.01 * dp, dp).size(), 3u);
  EXPECT_EQ(sph::ring(LatticeKind::FaceCentred, c, 0.0, 1.2 * dp, dp).size(), 7u);
  // r_inner is inclusive, r_outer exclusive: the square lattice's first shell is exactly at dp.
  EXPECT_EQ(sph::ring(LatticeKind::Square, c, dp, 1.2 * dp, dp).size(), 4u);
  EXPECT_EQ(sph::ring(LatticeKind::Square, c, 0.0, dp, dp).size(), 1u);
  const auto disc = sph::ring(LatticeKind::Triangular, c, 0.0, 3.5 * dp, dp);
  EXPECT_NEAR((disc[closest_to(disc, c)] - c).norm(), 0.0, 1e-12) << "the lattice passes through the centre";
}

// Counting argument: every lattice point owns its Voronoi cell (area A = area_per_particle), which lies
// within delta of the point (delta = the cell's circumradius: dp/sqrt(2) square, 5/8 dp face-centred,
// dp/sqrt(3) triangular). The cells of the points in the annulus cover the annulus shrunk by delta and lie
// inside it grown by delta, so |N A - pi (ro^2 - ri^2)| <= 2 pi delta (ro + ri).
TEST(Lattices, RingCountMatchesAreaWithinTheBoundaryLayer) {
  const double dp = 0.05;
  const Vec2 c(1.0, 2.0);
  const double delta[] = {dp / std::sqrt(2.0), 0.625 * dp, dp / std::sqrt(3.0)};
  int ik = 0;
  for (LatticeKind k : kAllKinds) {
    for (auto [ri, ro] : {std::pair{0.0, 0.5}, std::pair{0.3, 0.8}, std::pair{1.0, 1.1}}) {
      const auto p = sph::ring(k, c, ri, ro, dp);
      const double area = M_PI * (ro * ro - ri * ri);
      const double tol = 2.0 * M_PI * delta[ik] * (ro + ri);
      EXPECT_NEAR(p.size() * sph::area_per_particle(k, dp), area, tol) << sph::to_string(k) << " " << ri << " " << ro;
      for (const Vec2& q : p) {
        ASSERT_GE((q - c).norm(), ri - 1e-12);
        ASSERT_LT((q - c).norm(), ro);
      }
      EXPECT_EQ(count_coincident(p, 1e-3 * dp), 0);
    }
    ++ik;
  }
}

TEST(Lattices, HexagonHas3nnPlus1ParticlesAtSpacingDp) {
  const double dp = 0.1;
  const Vec2 c(2.0, 3.0);
  const auto p = sph::hexagon(8, dp, c);
  ASSERT_EQ(p.size(), 217u);  // 3 n (n + 1) + 1, n = 8 (Hoover et al. 2004 Fig 4)
  for (int n : {0, 1, 2, 5}) EXPECT_EQ(sph::hexagon(n, dp).size(), static_cast<std::size_t>(3 * n * (n + 1) + 1));
  EXPECT_EQ(count_coincident(p, 1e-3 * dp), 0);
  double rmax = 0;
  for (const Vec2& q : p) rmax = std::max(rmax, (q - c).norm());
  EXPECT_NEAR(rmax, 8 * dp, 1e-12);  // the vertices
  // Vertices along +-x.
  EXPECT_NEAR((p[closest_to(p, c + Vec2(8 * dp, 0))] - c - Vec2(8 * dp, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((p[closest_to(p, c - Vec2(8 * dp, 0))] - c + Vec2(8 * dp, 0)).norm(), 0.0, 1e-12);
  // The centre particle has the 6 triangular neighbours at dp and no closer point; a corner has 3.
  auto d = distances_from(p, closest_to(p, c));
  EXPECT_NEAR(d[0], dp, 1e-12);
  EXPECT_NEAR(d[5], dp, 1e-12);
  EXPECT_GT(d[6], 1.5 * dp);
  d = distances_from(p, closest_to(p, c + Vec2(8 * dp, 0)));
  EXPECT_NEAR(d[2], dp, 1e-12);
  EXPECT_GT(d[3], 1.5 * dp);
}

TEST(Lattices, PeriodicImagesCountAndOffsets) {
  const std::vector<Vec2> pts{Vec2(0.1, 0.2), Vec2(0.7, 0.4), Vec2(0.3, 0.9)};
  const double Lx = 1.0, Ly = 1.5;
  for (int layers : {0, 1, 2}) {
    const int side = 2 * layers + 1;
    const auto with = sph::periodic_images(pts, Lx, Ly, layers, true);
    const auto without = sph::periodic_images(pts, Lx, Ly, layers, false);
    EXPECT_EQ(with.size(), pts.size() * side * side);
    EXPECT_EQ(without.size(), pts.size() * (side * side - 1));
    // Every image is an original shifted by (i Lx, j Ly) with |i|, |j| <= layers, each shift exactly once.
    std::multiset<std::pair<long, long>> seen;
    for (const Vec2& q : without) {
      bool found = false;
      for (const Vec2& o : pts) {
        const double fi = (q.x() - o.x()) / Lx, fj = (q.y() - o.y()) / Ly;
        const long i = std::lround(fi), j = std::lround(fj);
        if (std::abs(fi - i) < 1e-12 && std::abs(fj - j) < 1e-12) {
          found = true;
          EXPECT_LE(std::abs(i), layers);
          EXPECT_LE(std::abs(j), layers);
          EXPECT_FALSE(i == 0 && j == 0) << "original included although include_original = false";
          seen.insert({i, j});
          break;
        }
      }
      EXPECT_TRUE(found);
    }
    for (int j = -layers; j <= layers; ++j)
      for (int i = -layers; i <= layers; ++i)
        EXPECT_EQ(seen.count({i, j}), (i == 0 && j == 0) ? 0u : pts.size()) << i << " " << j;
  }
}

TEST(Lattices, InvalidInputThrows) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  const auto sq = LatticeKind::Square;
  EXPECT_THROW(sph::lattice_block(sq, -1, 3, 0.1), std::invalid_argument);
  EXPECT_THROW(sph::lattice_block(sq, 3, 3, 0.0), std::invalid_argument);
  EXPECT_THROW(sph::lattice_block(sq, 3, 3, nan), std::invalid_argument);
  EXPECT_THROW(sph::rectangle(sq, 0, 0, 1, 1, -0.1), std::invalid_argument);
  EXPECT_THROW(sph::rectangle(sq, 0, 0, 0, 1, 0.1), std::invalid_argument);
  EXPECT_THROW(sph::rectangle(sq, 0, 0, inf, 1, 0.1), std::invalid_argument);  // would never end
  EXPECT_THROW(sph::rectangle(sq, 0, 0, 1, 1, inf), std::invalid_argument);
  EXPECT_THROW(sph::ring(sq, Vec2::Zero(), 0.5, 0.5, 0.1), std::invalid_argument);
  EXPECT_THROW(sph::ring(sq, Vec2::Zero(), -0.1, 0.5, 0.1), std::invalid_argument);
  EXPECT_THROW(sph::ring(sq, Vec2::Zero(), 0.0, inf, 0.1), std::invalid_argument);
  EXPECT_THROW(sph::ring(sq, Vec2::Zero(), 0.0, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(sph::hexagon(-1, 0.1), std::invalid_argument);
  EXPECT_THROW(sph::hexagon(3, -0.1), std::invalid_argument);
  EXPECT_THROW(sph::periodic_images({Vec2::Zero()}, 1.0, 1.0, -1), std::invalid_argument);
}

}  // namespace
