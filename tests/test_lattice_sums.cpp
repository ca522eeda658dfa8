// Lattice sums of Gray et al. 2001 Section 5: symmetries and the closed forms of (5.21).
#include <gtest/gtest.h>

#include <cmath>

#include "updated_lagrangian/lattice_sums.hpp"

namespace {

using sph::LatticeKind;
const sph::CubicSpline W2(2);

TEST(LatticeSums, SquareLatticeHasNoOddOrMixedTerms) {
  for (double h : {1.0, 1.3, 1.5}) {
    const auto s = sph::dispersion_sums(W2, LatticeKind::Square, h, 4, M_PI, 0.0);
    EXPECT_NEAR(s.A_x, 0.0, 1e-12);
    EXPECT_NEAR(s.A_y, 0.0, 1e-12);
    EXPECT_NEAR(s.C, 0.0, 1e-12);
    EXPECT_NEAR(s.f_xy, 0.0, 1e-12);
  }
}

TEST(LatticeSums, SquareLatticeIsSymmetricUnderQuarterTurn) {
  // Propagating along y on the square lattice is propagating along x rotated by 90 degrees.
  for (double h : {1.0, 1.25, 1.6}) {
    const auto sx = sph::dispersion_sums(W2, LatticeKind::Square, h, 4, M_PI, 0.0);
    const auto sy = sph::dispersion_sums(W2, LatticeKind::Square, h, 4, 0.0, M_PI);
    EXPECT_NEAR(sx.B_x, sy.B_y, 1e-12);
    EXPECT_NEAR(sx.B_y, sy.B_x, 1e-12);
    EXPECT_NEAR(sx.f_xx, sy.f_yy, 1e-10);
    EXPECT_NEAR(sx.beta, sy.beta, 1e-12);
  }
}

TEST(LatticeSums, FaceCentredLatticeIsMirrorSymmetricInY) {
  const auto s = sph::dispersion_sums(W2, LatticeKind::FaceCentred, 1.0, 4, M_PI, 0.0);
  EXPECT_NEAR(s.A_y, 0.0, 1e-12);
  EXPECT_NEAR(s.C, 0.0, 1e-12);
  EXPECT_LT(s.A_x, -0.1);  // nonzero on this lattice (Section 5.3.2)
}

TEST(LatticeSums, VanishAtZeroWaveNumber) {
  const auto s = sph::dispersion_sums(W2, LatticeKind::FaceCentred, 1.3, 4, 0.0, 0.0);
  for (double v : {s.A_x, s.A_y, s.B_x, s.B_y, s.C, s.beta, s.f_xx, s.f_yy, s.f_xy}) EXPECT_EQ(v, 0.0);
}

TEST(LatticeSums, SquareCellsAtHEqualDpMatchClosedForms) {
  // Gray et al. 2001 eq (5.21). B_x is exact at h = dp; the f_xx closed form drops the diagonal
  // neighbours, whose share is (W(sqrt2 dp)/W(dp))^n ~ 1e-3 at n = 4 and vanishes as n grows.
  const double s2 = std::sqrt(2.0);
  const auto s = sph::dispersion_sums(W2, LatticeKind::Square, 1.0, 4, M_PI, 0.0);
  EXPECT_NEAR(s.B_x, 30.0 / (7 * M_PI) * (2 + (2 - s2) * (3 - s2)), 1e-12);
  double prev_gap = 1e9;
  for (int n = 2; n <= 10; n += 2) {
    const double fxx = sph::dispersion_sums(W2, LatticeKind::Square, 1.0, n, M_PI, 0.0).f_xx;
    const double gap = std::abs(fxx / (30.0 * (3 * n + 2) / (7 * M_PI)) - 1.0);
    EXPECT_LT(gap, prev_gap) << n;
    prev_gap = gap;
  }
  EXPECT_LT(prev_gap, 1e-5);
  // beta = (10/7pi)(1/2 + (2 - sqrt2)^3), derived by hand from (5.5).
  EXPECT_NEAR(s.beta, 10.0 / (7 * M_PI) * (0.5 + std::pow(2 - s2, 3)), 1e-12);
}

TEST(LatticeSums, RejectsMeaninglessInput) {
  EXPECT_THROW(sph::dispersion_sums(sph::CubicSpline(3), LatticeKind::Square, 1.0, 4, M_PI, 0.0), std::invalid_argument);
  EXPECT_THROW(sph::dispersion_sums(W2, LatticeKind::Square, 0.4, 4, M_PI, 0.0), std::invalid_argument);  // W(dp) = 0
}

}  // namespace
