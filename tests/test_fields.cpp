// The structure-of-arrays machinery (src/core/fields.hpp) and the Morton order (src/core/space_filling.hpp).
// Every solver's state, RK4's stage algebra and the space-filling reordering go through these few templates,
// so a field they forget (not visited, not permuted, not zeroed) would silently corrupt a run: the tests
// build states with every kind of field the library uses (double, Vec2, Eigen::Matrix2d, an enum, an
// integer) and check each field separately, bit for bit where the operation is exact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "core/fields.hpp"
#include "core/space_filling.hpp"

namespace {

using sph::Vec2;
using Mat2 = Eigen::Matrix2d;

enum class Kind : unsigned char { A = 0, B = 1, C = 2 };

// The vector-space fields (what FieldAlgebra supports).
struct Numeric {
  std::vector<double> s;
  std::vector<Vec2> u;
  std::vector<Mat2> M;
  auto fields() { return std::tie(s, u, M); }
  auto fields() const { return std::tie(s, u, M); }
};

// Every kind of field a particle state holds (what Reorder and resize_fields support).
struct Mixed {
  std::vector<double> s;
  std::vector<Vec2> u;
  std::vector<Mat2> M;
  std::vector<Kind> kind;
  std::vector<std::uint32_t> id;
  auto fields() { return std::tie(s, u, M, kind, id); }
  auto fields() const { return std::tie(s, u, M, kind, id); }
};

Mixed random_mixed(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mixed m;
  for (std::size_t i = 0; i < n; ++i) {
    m.s.push_back(u(rng));
    m.u.push_back(Vec2(u(rng), u(rng)));
    m.M.push_back(Mat2::Random());
    m.kind.push_back(static_cast<Kind>(rng() % 3));
    m.id.push_back(static_cast<std::uint32_t>(i));
  }
  return m;
}

TEST(Fields, ForEachAndZipVisitEveryFieldOnceInOrder) {
  Mixed a = random_mixed(3, 1), b = random_mixed(3, 2);
  std::vector<const void*> seen;
  sph::for_each_field(a, [&](auto& f) { seen.push_back(&f); });
  const std::vector<const void*> expected = {&a.s, &a.u, &a.M, &a.kind, &a.id};
  EXPECT_EQ(seen, expected);
  // zip_fields hands over the same field of each state, with the same element type.
  std::vector<std::pair<const void*, const void*>> pairs;
  sph::zip_fields([&](auto& fa, auto& fb) {
    static_assert(std::is_same_v<decltype(fa), decltype(fb)>);
    pairs.emplace_back(&fa, &fb);
  }, a, b);
  ASSERT_EQ(pairs.size(), 5u);
  EXPECT_EQ(pairs[2], std::make_pair(static_cast<const void*>(&a.M), static_cast<const void*>(&b.M)));
  EXPECT_EQ(pairs[4], std::make_pair(static_cast<const void*>(&a.id), static_cast<const void*>(&b.id)));
}

TEST(Fields, ResizeKeepsOldEntriesAndZeroFillsNewOnesOfEveryType) {
  Mixed m = random_mixed(4, 3);
  const Mixed old = m;
  sph::resize_fields(m, 9);
  EXPECT_EQ(sph::field_size(m), 9u);
  sph::zip_fields([](auto& now, auto& before) {
    ASSERT_EQ(now.size(), 9u);
    for (std::size_t i = 0; i < before.size(); ++i) EXPECT_TRUE(now[i] == before[i]) << i;
    using T = typename std::decay_t<decltype(now)>::value_type;
    for (std::size_t i = before.size(); i < now.size(); ++i) EXPECT_TRUE(now[i] == sph::zero_of<T>()) << i;
  }, m, old);
  // Eigen's default constructor leaves a matrix uninitialised: the zero must be explicit.
  for (std::size_t i = 4; i < 9; ++i) {
    EXPECT_EQ(m.M[i], Mat2::Zero());
    EXPECT_EQ(m.u[i], Vec2::Zero());
    EXPECT_EQ(m.kind[i], Kind::A);
  }
}

// out = a + s k element by element. With FMA hardware the compiler may fuse s k + a (one rounding) or not
// (two roundings); both are exact element-wise evaluations, so each entry must equal one of the two,
// bit for bit. A wrong pairing of elements or fields would be off by O(1), not by an ulp.
bool one_of_the_roundings(double out, double a, double s, double k) {
  volatile double product = s * k;  // volatile: no fusion here
  const double two_roundings = a + product;
  return out == two_roundings || out == std::fma(s, k, a);
}

TEST(FieldAlgebra, SetAxpyAndAxpyAreElementByElementExact) {
  const Mixed ma = random_mixed(6, 4), mk = random_mixed(6, 5);
  const Numeric a{ma.s, ma.u, ma.M}, k{mk.s, mk.u, mk.M};
  Numeric out = a;  // sized; overwritten
  const double s = 0.7310;
  sph::FieldAlgebra::set_axpy(out, a, s, k);
  Numeric y = a;
  sph::FieldAlgebra::axpy(y, s, k);
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_TRUE(one_of_the_roundings(out.s[i], a.s[i], s, k.s[i])) << i;
    EXPECT_EQ(y.s[i], out.s[i]);
    for (int c = 0; c < 2; ++c) EXPECT_TRUE(one_of_the_roundings(out.u[i](c), a.u[i](c), s, k.u[i](c))) << i;
    for (int c = 0; c < 4; ++c) EXPECT_TRUE(one_of_the_roundings(out.M[i](c), a.M[i](c), s, k.M[i](c))) << i;
  }
  // With dyadic values (multiples of 2^-10 below 4, s = 3/8) every product and sum is exact, so there
  // is one right answer whatever the rounding: compare with the hand computation directly.
  Numeric d{{0.5, -1.25}, {Vec2(0.125, 3.0), Vec2(-2.0, 0.0009765625)}, {Mat2::Constant(1.5), Mat2::Identity()}};
  Numeric e{{2.0, 0.75}, {Vec2(-1.0, 0.5), Vec2(0.25, 1.0)}, {Mat2::Identity(), Mat2::Constant(-0.5)}};
  sph::FieldAlgebra::axpy(d, 0.375, e);
  EXPECT_EQ(d.s, (std::vector<double>{1.25, -0.96875}));
  EXPECT_EQ(d.u[0], Vec2(-0.25, 3.1875));
  EXPECT_EQ(d.u[1], Vec2(-1.90625, 0.3759765625));
  EXPECT_EQ(d.M[0], (Mat2() << 1.875, 1.5, 1.5, 1.875).finished());
  EXPECT_EQ(d.M[1], (Mat2() << 0.8125, -0.1875, -0.1875, 0.8125).finished());
}

// Reorder: new[i] = old[order[i]] for every field, and the inverse permutation restores the state exactly.
template <class State>
void expect_reorder_round_trip(State m) {
  {
    const std::size_t n = m.id.size();
    const State old = m;
    std::vector<std::uint32_t> order(n), inverse(n);
    std::iota(order.begin(), order.end(), 0u);
    std::shuffle(order.begin(), order.end(), std::mt19937(7));
    for (std::size_t i = 0; i < n; ++i) inverse[order[i]] = static_cast<std::uint32_t>(i);
    sph::Reorder r;
    r.apply(m, order);
    sph::zip_fields([&](auto& now, auto& before) {
      ASSERT_EQ(now.size(), n);
      for (std::size_t i = 0; i < n; ++i) ASSERT_TRUE(now[i] == before[order[i]]) << i;
    }, m, old);
    EXPECT_EQ(m.id, order);  // the id field records where every particle came from
    r.apply(m, inverse);     // the same Reorder again: its scratch is reused across field sizes
    sph::zip_fields([&](auto& now, auto& before) {
      for (std::size_t i = 0; i < n; ++i) ASSERT_TRUE(now[i] == before[i]) << i;
    }, m, old);
  }
}

struct Plain {  // the fields of Mixed that are not Eigen types
  std::vector<double> s;
  std::vector<Kind> kind;
  std::vector<std::uint32_t> id;
  auto fields() { return std::tie(s, kind, id); }
  auto fields() const { return std::tie(s, kind, id); }
};

TEST(Reorder, PermutesEveryFieldConsistentlyAndTheInverseRestores) {
  const Mixed m = random_mixed(257, 6);
  expect_reorder_round_trip(Plain{m.s, m.kind, m.id});
}

// Every solver state has Vec2 and Tensor2 fields (not trivially copyable in Eigen 3.4: Reorder permutes by
// assignment, cycle by cycle).
TEST(Reorder, PermutesStatesWithEigenFields) { expect_reorder_round_trip(random_mixed(257, 6)); }

bool is_permutation_of_iota(std::vector<std::uint32_t> order) {
  std::sort(order.begin(), order.end());
  for (std::size_t i = 0; i < order.size(); ++i)
    if (order[i] != i) return false;
  return true;
}

TEST(MortonOrder, IsAStablePermutationAndClampsOutsideTheBox) {
  const sph::Box2 box{0, 0, 1, 1, false, false};
  // Cells of 0.25: points 0 and 2 share the last cell, 1 and 3 the first (3 only after clamping).
  const std::vector<Vec2> x = {{0.9, 0.9}, {0.01, 0.02}, {0.8, 0.95}, {-5.0, -7.0}, {0.3, 0.1}};
  const auto order = sph::morton_order(x, box, 0.25);
  EXPECT_EQ(order, (std::vector<std::uint32_t>{1, 3, 4, 0, 2}));
  EXPECT_THROW(sph::morton_order(x, box, 0.0), std::invalid_argument);
}

// Mean |position difference| over all horizontal and vertical neighbour pairs of a k x k lattice.
double mean_neighbour_distance(const std::vector<std::uint32_t>& position_of, int k) {
  double sum = 0;
  long pairs = 0;
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i)
      for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{0, 1}})
        if (i + di < k && j + dj < k) {
          sum += std::abs(double(position_of[j * k + i]) - double(position_of[(j + dj) * k + i + di]));
          ++pairs;
        }
  return sum / pairs;
}

TEST(MortonOrder, PutsLatticeNeighboursClose) {
  // A 64 x 64 lattice, one point per cell, fed in a random order. With every cell occupied once, the
  // sorted position of a point is its Morton code. Stepping +1 in x through j trailing one bits changes
  // the code by 4^j - (4^j - 1)/3 = (2 4^j + 1)/3, and 2^(5-j) of the 63 steps of a row have j trailing
  // ones: a row sums to sum_j 2^(5-j) (2 4^j + 1)/3 = 1365 = (4096 - 1)/3. A step in y moves odd bits, twice
  // as far: 2730 per column. The mean over the 2 * 64 * 63 pairs is (1365 + 2730)/126 = 32.5, exactly.
  // A random order gives E|U - V| = (N + 1)/3 = 1365.7 for N = 4096 positions.
  const int k = 64;
  const double dp = 1.0 / k;
  std::vector<Vec2> lattice;
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) lattice.emplace_back((i + 0.5) * dp, (j + 0.5) * dp);
  std::vector<std::uint32_t> shuffle(k * k);
  std::iota(shuffle.begin(), shuffle.end(), 0u);
  std::shuffle(shuffle.begin(), shuffle.end(), std::mt19937(8));
  std::vector<Vec2> x(k * k);
  for (int p = 0; p < k * k; ++p) x[p] = lattice[shuffle[p]];  // input slot p holds lattice point shuffle[p]

  const auto order = sph::morton_order(x, {0, 0, 1, 1, false, false}, dp);
  ASSERT_TRUE(is_permutation_of_iota(order));
  std::vector<std::uint32_t> sorted_position(k * k), random_position(k * k);
  for (int i = 0; i < k * k; ++i) {
    sorted_position[shuffle[order[i]]] = static_cast<std::uint32_t>(i);
    random_position[shuffle[i]] = static_cast<std::uint32_t>(i);
  }
  EXPECT_EQ(mean_neighbour_distance(sorted_position, k), 32.5);
  // The random order's mean has a standard error of ~ (N/(3 sqrt 2)) / sqrt(8064) = 11, so 10% (136) is
  // more than 10 standard errors.
  EXPECT_NEAR(mean_neighbour_distance(random_position, k), (k * k + 1) / 3.0, 0.1 * (k * k + 1) / 3.0);
}

}  // namespace
