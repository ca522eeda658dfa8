// Cell list against an independent O(N^2) search: neighbour sets, displacements and distances, with and
// without periodic wrap, tiny periodic boxes, particles outside the box, rebuilds and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <random>

#include "core/lattices.hpp"
#include "core/neighbours.hpp"

namespace {

using sph::Box2;
using sph::CellList2D;
using sph::Vec2;

struct Pair { std::size_t j; Vec2 d; double r; };

// Minimum image by the IEEE remainder (exact): written independently of CellList2D::displacement.
Vec2 reference_displacement(const Vec2& a, const Vec2& b, const Box2& box) {
  Vec2 d = a - b;
  if (box.periodic_x) d.x() = std::remainder(d.x(), box.Lx());
  if (box.periodic_y) d.y() = std::remainder(d.y(), box.Ly());
  return d;
}

std::vector<std::vector<Pair>> reference_pairs(const std::vector<Vec2>& x, const Box2& box, double radius) {
  std::vector<std::vector<Pair>> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j) {
      if (j == i) continue;
      const Vec2 d = reference_displacement(x[i], x[j], box);
      if (d.norm() < radius) out[i].push_back({j, d, d.norm()});
    }
  return out;
}

std::vector<std::vector<Pair>> cell_list_pairs(const CellList2D& cl, const std::vector<Vec2>& x, double radius) {
  std::vector<std::vector<Pair>> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    cl.for_each_neighbour(x, i, radius, [&](std::size_t j, const Vec2& d, double r) { out[i].push_back({j, d, r}); });
    std::sort(out[i].begin(), out[i].end(), [](const Pair& a, const Pair& b) { return a.j < b.j; });
  }
  return out;
}

// Same neighbour sets (each neighbour once), and displacement and distance per pair to round-off.
// Returns the total number of pairs so that callers can check the test is not vacuous.
std::size_t expect_same_pairs(const std::vector<Vec2>& x, const Box2& box, double radius, double query_radius = -1) {
  if (query_radius < 0) query_radius = radius;
  CellList2D cl(box, radius);
  cl.build(x);
  const auto got = cell_list_pairs(cl, x, query_radius);
  const auto ref = reference_pairs(x, box, query_radius);
  const double scale = std::max(box.Lx(), box.Ly());
  std::size_t total = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    std::vector<std::size_t> gj, rj;
    for (const Pair& p : got[i]) gj.push_back(p.j);
    for (const Pair& p : ref[i]) rj.push_back(p.j);
    EXPECT_EQ(gj, rj) << "particle " << i << " at (" << x[i].transpose() << ")";
    if (gj != rj) return total;
    for (std::size_t k = 0; k < got[i].size(); ++k) {
      EXPECT_LT((got[i][k].d - ref[i][k].d).norm(), 1e-13 * scale) << i << " -> " << got[i][k].j;
      EXPECT_NEAR(got[i][k].r, ref[i][k].r, 1e-13 * scale);
      EXPECT_NEAR(got[i][k].r, got[i][k].d.norm(), 1e-15 * scale);
    }
    total += got[i].size();
  }
  // The library's own brute-force reference agrees as well.
  const auto bf = sph::brute_force_neighbours(x, box, query_radius);
  for (std::size_t i = 0; i < x.size(); ++i) {
    std::vector<std::size_t> gj;
    for (const Pair& p : got[i]) gj.push_back(p.j);
    EXPECT_EQ(gj, bf[i]) << "brute_force_neighbours, particle " << i;
  }
  return total;
}

std::vector<Vec2> random_points(std::size_t n, double x0, double x1, double y0, double y1, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(x0, x1), uy(y0, y1);
  std::vector<Vec2> p(n);
  for (auto& q : p) q = Vec2(ux(rng), uy(rng));
  return p;
}

Box2 make_box(double xmin, double ymin, double xmax, double ymax, bool px, bool py) {
  Box2 b;
  b.xmin = xmin; b.ymin = ymin; b.xmax = xmax; b.ymax = ymax; b.periodic_x = px; b.periodic_y = py;
  return b;
}

TEST(CellList, RandomPointsNonPeriodic) {
  const Box2 box = make_box(-0.5, 0.2, 0.5, 0.9, false, false);
  const auto x = random_points(500, -0.5, 0.5, 0.2, 0.9, 1);
  // ~ N^2 pi r^2 / A = 500^2 * 0.0254 / 0.7 pairs ~ 9000, minus edge losses.
  EXPECT_GT(expect_same_pairs(x, box, 0.09), 5000u);
  // A query with a smaller radius than the grid was built for.
  EXPECT_GT(expect_same_pairs(x, box, 0.09, 0.031), 500u);
}

TEST(CellList, LatticePointsNonPeriodic) {
  for (auto kind : {sph::LatticeKind::Square, sph::LatticeKind::FaceCentred, sph::LatticeKind::Triangular}) {
    const double dp = 0.1;
    const auto x = sph::lattice_block(kind, 15, 12, dp, Vec2(0.05, 0.05));
    const Box2 box = make_box(0, 0, 1.5, 1.2, false, false);
    EXPECT_GT(expect_same_pairs(x, box, 2.05 * dp), 15u * 12u * 8u) << sph::to_string(kind);
  }
}

// Radius exactly a lattice distance: the pairs at r = radius must be treated alike by the cell list and the
// brute force (r < radius, nothing at r = radius).
TEST(CellList, LatticeWithRadiusExactlyALatticeDistance) {
  for (double dp : {0.1, 0.3, 1.0 / 3.0}) {
    const auto x = sph::rectangle(sph::LatticeKind::Square, 0, 0, 12 * dp, 10 * dp, dp);
    for (double k : {1.0, 2.0, 3.0, std::sqrt(2.0), std::sqrt(5.0)}) {
      for (bool periodic : {false, true}) {
        // eps = 0: the radius equals a lattice distance (computed distances are that +- round-off);
        // eps > 0: clearly above it, where a periodic lattice must look the same from every particle.
        for (double eps : {0.0, 1e-9}) {
          const Box2 box = make_box(0, 0, 12 * dp, 10 * dp, periodic, periodic);
          const double radius = k * dp * (1 + eps);
          CellList2D cl(box, radius);
          cl.build(x);
          const auto got = cell_list_pairs(cl, x, radius);
          const auto bf = sph::brute_force_neighbours(x, box, radius);
          for (std::size_t i = 0; i < x.size(); ++i) {
            std::vector<std::size_t> gj;
            for (const Pair& p : got[i]) {
              gj.push_back(p.j);
              EXPECT_LT(p.r, radius);
            }
            ASSERT_EQ(gj, bf[i]) << "dp " << dp << " radius/dp " << k << " periodic " << periodic << " particle " << i;
          }
          if (periodic && eps > 0) {
            for (std::size_t i = 1; i < x.size(); ++i) ASSERT_EQ(got[i].size(), got[0].size()) << i;
          }
        }
      }
    }
  }
}

// append_neighbours (the pair lists' branch-free collection) gives for_each_neighbour's particles in its
// order, with and without a filter, where distances round onto the radius (lattices at radius = a lattice
// distance) and at random.
TEST(CellList, AppendNeighboursListsForEachNeighboursParticlesInItsOrder) {
  std::mt19937_64 rng(71);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> random_points(400);
  for (Vec2& p : random_points) p = Vec2(u(rng), u(rng));
  const double dp = 1.0 / 12.0;
  const auto lattice = sph::rectangle(sph::LatticeKind::Square, 0, 0, 1.0, 1.0, dp);
  int compared = 0;
  for (const std::vector<Vec2>* x : std::initializer_list<const std::vector<Vec2>*>{&random_points, &lattice})
    for (bool periodic : {false, true})
      for (double radius : {2 * dp, std::sqrt(5.0) * dp, 0.137}) {
        const Box2 box = make_box(0, 0, 1.0, 1.0, periodic, periodic);
        CellList2D cl(box, radius);
        cl.build(*x);
        for (bool upper_only : {false, true})
          for (std::size_t i = 0; i < x->size(); ++i) {
            std::vector<std::uint32_t> want, got;
            cl.for_each_neighbour(*x, i, radius, [&](std::size_t j, const Vec2&, double) {
              if (!upper_only || j > i) want.push_back(static_cast<std::uint32_t>(j));
            });
            cl.append_neighbours(*x, i, radius, got, upper_only);
            ASSERT_EQ(got, want) << "periodic " << periodic << " radius " << radius << " particle " << i;
            compared += static_cast<int>(want.size());
          }
      }
  EXPECT_GT(compared, 10000);
}

// Cell width equal to the radius up to rounding (L = n radius): a pair a little closer than the radius,
// straddling a cell boundary, must still be found. Before the cells got a margin, rounding in the cell
// index placed ~0.6% of such pairs two cells apart and the stencil missed them.
TEST(CellList, PairsJustInsideTheRadiusAcrossCellBoundaries) {
  std::mt19937_64 rng(70);
  std::uniform_real_distribution<double> length(0.5, 2.0), offset(-3.0, 3.0);
  int tried = 0, missed = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double L = length(rng), radius = L / static_cast<double>(3 + rng() % 20);
    Box2 box = make_box(0, 0, L, L, rng() % 2 == 0, false);
    box.xmin = offset(rng);
    box.xmax = box.xmin + L;
    CellList2D cl(box, radius);
    if (cl.cells_x() < 3) continue;
    // x1 on (or a few ulps above) an interior cell boundary, x2 the largest double closer than radius.
    double x1 = box.xmin + static_cast<double>(1 + rng() % (cl.cells_x() - 1)) * radius;
    for (int s = static_cast<int>(rng() % 4); s > 0; --s) x1 = std::nextafter(x1, INFINITY);
    double x2 = x1 + radius;
    while (!((Vec2(x2, 0.5) - Vec2(x1, 0.5)).norm() < radius)) x2 = std::nextafter(x2, -INFINITY);
    const std::vector<Vec2> x{Vec2(x1, 0.5), Vec2(x2, 0.5)};
    cl.build(x);
    int found = 0;
    cl.for_each_neighbour(x, 0, radius, [&](std::size_t, const Vec2&, double) { ++found; });
    ++tried;
    if (found != 1) {
      if (++missed <= 3) ADD_FAILURE() << std::setprecision(17) << "L " << L << " radius " << radius << " xmin " << box.xmin << " x1 " << x1 << " x2 " << x2;
    }
  }
  EXPECT_GT(tried, 15000);
  EXPECT_EQ(missed, 0);
}

TEST(CellList, QueryRadiusLargerThanBuiltForThrows) {
  const Box2 box = make_box(0, 0, 1, 1, false, false);
  const auto x = random_points(50, 0, 1, 0, 1, 80);
  CellList2D cl(box, 0.1);
  cl.build(x);
  EXPECT_THROW(cl.for_each_neighbour(x, 0, 0.15, [](std::size_t, const Vec2&, double) {}), std::invalid_argument);
  EXPECT_THROW(cl.for_each_neighbour(x, 0, 0.1 * (1 + 1e-10), [](std::size_t, const Vec2&, double) {}), std::invalid_argument);
  EXPECT_NO_THROW(cl.for_each_neighbour(x, 0, 0.1, [](std::size_t, const Vec2&, double) {}));
  // The same radius computed another way (an ulp or two larger) is accepted.
  EXPECT_NO_THROW(cl.for_each_neighbour(x, 0, std::nextafter(0.1, 1.0), [](std::size_t, const Vec2&, double) {}));
}

TEST(CellList, PeriodicInX_InY_AndBoth) {
  for (int mode = 0; mode < 3; ++mode) {
    const bool px = mode != 1, py = mode != 0;
    const Box2 box = make_box(-1.0, 2.0, 0.0, 2.8, px, py);
    // Points in periodic directions may lie outside the box by up to a period: they are wrapped.
    const auto x = random_points(400, px ? -2.0 : -1.0, px ? 1.0 : 0.0, py ? 1.2 : 2.0, py ? 3.6 : 2.8, 10 + mode);
    const std::size_t n = expect_same_pairs(x, box, 0.13);
    EXPECT_GT(n, 5000u) << "mode " << mode;
    // Some pairs must actually be found through the wrap (|raw difference| > radius).
    std::size_t wrapped = 0;
    CellList2D cl(box, 0.13);
    cl.build(x);
    for (std::size_t i = 0; i < x.size(); ++i)
      cl.for_each_neighbour(x, i, 0.13, [&](std::size_t j, const Vec2&, double) { wrapped += (x[i] - x[j]).norm() >= 0.13; });
    EXPECT_GT(wrapped, 100u) << "mode " << mode;
  }
}

// A periodic direction with fewer than 3 cells: the stencil must not visit a cell twice (pairs would be
// reported twice) nor miss the wrapped neighbours.
TEST(CellList, TinyPeriodicBoxWithFewerThanThreeCells) {
  for (double radius : {0.5, 0.45, 0.34}) {
    for (int mode = 0; mode < 3; ++mode) {
      const bool px = mode != 1, py = mode != 0;
      const Box2 box = make_box(0, 0, 1.0, 1.0, px, py);
      CellList2D cl(box, radius);
      if (px) {
        EXPECT_LT(cl.cells_x(), 3);
      }
      if (py) {
        EXPECT_LT(cl.cells_y(), 3);
      }
      const auto x = random_points(120, 0, 1, 0, 1, 20 + mode);
      EXPECT_GT(expect_same_pairs(x, box, radius), 1000u) << radius << " " << mode;
    }
  }
  // One periodic direction tiny, the other wide and periodic.
  const Box2 box = make_box(0, 0, 0.6, 5.0, true, true);
  const auto x = random_points(300, 0, 0.6, 0, 5.0, 30);
  EXPECT_GT(expect_same_pairs(x, box, 0.25), 1000u);
}

TEST(CellList, ParticlesOutsideANonPeriodicBox) {
  const Box2 box = make_box(0, 0, 1, 1, false, false);
  auto x = random_points(400, -1.0, 2.0, -0.5, 1.5, 40);
  x.push_back(Vec2(50.0, -30.0));  // far away, alone
  x.push_back(Vec2(50.01, -30.0)); // ... with one neighbour
  // Escaped particles very far out (cell coordinates beyond the range of int), in pairs.
  for (double far : {1e12, -1e12}) {
    x.push_back(Vec2(far, 0.5));
    x.push_back(Vec2(far + 0.05, 0.5));
    x.push_back(Vec2(0.5, far));
    x.push_back(Vec2(0.5, far - 0.05));
  }
  x.push_back(Vec2(0.999, 0.5));  // near the edge of the box, next to nothing far out
  EXPECT_GT(expect_same_pairs(x, box, 0.12), 1000u);
  // The same with one direction periodic: outside in y (non-periodic) only.
  const Box2 half = make_box(0, 0, 1, 1, true, false);
  const auto y = random_points(300, 0.0, 1.0, -1.0, 2.0, 41);
  EXPECT_GT(expect_same_pairs(y, half, 0.12), 500u);
}

TEST(CellList, RadiusLargerThanHalfAPeriodThrows) {
  EXPECT_THROW(CellList2D(make_box(0, 0, 1, 1, true, false), 0.51), std::invalid_argument);
  EXPECT_THROW(CellList2D(make_box(0, 0, 1, 3, false, true), 1.6), std::invalid_argument);
  EXPECT_NO_THROW(CellList2D(make_box(0, 0, 1, 3, true, false), 0.5));
  EXPECT_NO_THROW(CellList2D(make_box(0, 0, 1, 1, false, false), 0.8));  // non-periodic: any radius
  EXPECT_THROW(CellList2D(make_box(0, 0, 1, 1, false, false), 0.0), std::invalid_argument);
  EXPECT_THROW(CellList2D(make_box(0, 0, 0, 1, false, false), 0.1), std::invalid_argument);
  EXPECT_THROW(sph::brute_force_neighbours({Vec2::Zero()}, make_box(0, 0, 1, 1, true, true), 0.7),
               std::invalid_argument);
}

TEST(CellList, NonFinitePositionThrows) {
  CellList2D cl(make_box(0, 0, 1, 1, true, false), 0.2);
  auto x = random_points(10, 0, 1, 0, 1, 50);
  EXPECT_NO_THROW(cl.build(x));
  x[3].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(cl.build(x), std::runtime_error);
  x[3].x() = 0.5;
  x[7].y() = -std::numeric_limits<double>::infinity();
  EXPECT_THROW(cl.build(x), std::runtime_error);
}

TEST(CellList, RebuildAfterMovingParticles) {
  const Box2 box = make_box(0, 0, 2, 1, true, false);
  CellList2D cl(box, 0.1);
  auto x = random_points(300, 0, 2, 0, 1, 60);
  cl.build(x);
  std::mt19937_64 rng(61);
  std::normal_distribution<double> kick(0.0, 0.2);
  for (int round = 0; round < 3; ++round) {
    for (auto& q : x) q += Vec2(kick(rng), kick(rng));  // far enough to change cells
    if (round == 1) x.resize(200);                        // fewer particles
    if (round == 2) { auto more = random_points(150, 0, 2, 0, 1, 62); x.insert(x.end(), more.begin(), more.end()); }
    cl.build(x);
    const auto got = cell_list_pairs(cl, x, 0.1);
    const auto ref = reference_pairs(x, box, 0.1);
    std::size_t total = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      std::vector<std::size_t> gj, rj;
      for (const Pair& p : got[i]) gj.push_back(p.j);
      for (const Pair& p : ref[i]) rj.push_back(p.j);
      ASSERT_EQ(gj, rj) << "round " << round << " particle " << i;
      total += gj.size();
    }
    EXPECT_GT(total, 200u);
  }
}

}  // namespace

TEST(CellList, BoundingBoxHoldsEveryPointAndRejectsEmpty) {
  const std::vector<sph::Vec2> pts{{1.0, -2.0}, {-3.0, 4.0}, {0.5, 0.5}};
  const sph::Box2 b = sph::bounding_box(pts);
  EXPECT_DOUBLE_EQ(b.xmin, -3.0);
  EXPECT_DOUBLE_EQ(b.xmax, 1.0);
  EXPECT_DOUBLE_EQ(b.ymin, -2.0);
  EXPECT_DOUBLE_EQ(b.ymax, 4.0);
  EXPECT_THROW(sph::bounding_box({}), std::invalid_argument);
}
