// Cover functions: normalisation in 1, 2, 3 dimensions, derivatives against finite differences, and the
// closed-form constants against quadrature.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "same_bits.hpp"
#include "core/kernels.hpp"

namespace {

template <class K>
class KernelTest : public ::testing::Test {};
using AllKernels = ::testing::Types<sph::CubicSpline, sph::Lucy, sph::Gaussian, sph::Mollifier, sph::ModifiedMollifier>;
TYPED_TEST_SUITE(KernelTest, AllKernels);

// integral of W over R^d = S_d integral_0^R W(r) r^(d-1) dr, by composite Simpson on a fine grid
// (independent of the GSL quadrature used to normalise the mollifiers).
template <class K>
double integral(const K& k, double h) {
  const int n = 20000;
  const double R = k.support() * h, dr = R / n;
  double s = 0;
  for (int i = 0; i <= n; ++i) {
    // The truncated Gaussian jumps to 0 at its support radius: take the left limit there.
    const double r = (i == n) ? std::nextafter(R, 0.0) : i * dr;
    const double wgt = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
    s += wgt * k.W(r, h) * std::pow(r, k.dim() - 1);
  }
  return sph::unit_sphere_measure(k.dim()) * s * dr / 3.0;
}

TYPED_TEST(KernelTest, NormalisedInEveryDimension) {
  for (int dim = 1; dim <= 3; ++dim) {
    const TypeParam k(dim);
    for (double h : {0.3, 1.0, 2.5}) EXPECT_NEAR(integral(k, h), 1.0, 1e-9) << "dim " << dim << " h " << h;
  }
}

TYPED_TEST(KernelTest, DerivativesMatchFiniteDifferences) {
  for (int dim = 1; dim <= 3; ++dim) {
    const TypeParam k(dim);
    const double h = 1.3, eps = 1e-5 * h;
    for (double q = 0.05; q < k.support() - 0.05; q += 0.0731) {
      const double r = q * h;
      const double fd1 = (k.W(r + eps, h) - k.W(r - eps, h)) / (2 * eps);
      const double fd2 = (k.dWdr(r + eps, h) - k.dWdr(r - eps, h)) / (2 * eps);
      const double scale = k.W(0, h) / h;
      // Central differences carry O(eps^2) truncation error, large where the mollifiers steepen near
      // q = 1: an absolute floor plus a relative part.
      EXPECT_NEAR(k.dWdr(r, h), fd1, 1e-7 * scale + 1e-7 * std::abs(fd1)) << "q " << q;
      EXPECT_NEAR(k.d2Wdr2(r, h), fd2, 1e-7 * scale / h + 1e-7 * std::abs(fd2)) << "q " << q;
    }
  }
}

TYPED_TEST(KernelTest, VanishesOutsideSupportAndIsRadiallyDecreasing) {
  const TypeParam k(2);
  EXPECT_EQ(k.W(k.support() * 1.0001, 1.0), 0.0);
  EXPECT_EQ(k.dWdr(k.support() * 1.0001, 1.0), 0.0);
  for (double q = 0.01; q < k.support(); q += 0.05) EXPECT_LE(k.dWdr(q, 1.0), 0.0) << q;
}

TEST(KernelConstants, ClosedFormsEqualQuadrature) {
  for (int dim = 1; dim <= 3; ++dim) {
    EXPECT_NEAR(sph::CubicSplineShape::normalisation(dim), sph::numerical_normalisation<sph::CubicSplineShape>(dim), 1e-12);
    EXPECT_NEAR(sph::LucyShape::normalisation(dim), sph::numerical_normalisation<sph::LucyShape>(dim), 1e-12);
  }
  // Gray et al. 2001 eq (3.3): 10 / (7 pi h^2) at the origin in 2D.
  EXPECT_DOUBLE_EQ(sph::CubicSpline(2).W(0.0, 1.0), 10.0 / (7.0 * M_PI));
}

TEST(KernelConstants, RejectsBadDimensionAndName) {
  EXPECT_THROW(sph::CubicSpline(4), std::invalid_argument);
  EXPECT_THROW(sph::with_kernel("quintic", 2, [](auto) { return 0; }), std::invalid_argument);
  EXPECT_EQ(sph::with_kernel("lucy", 2, [](auto k) { return k.support(); }), 1.0);
}

}  // namespace

TEST(KernelConstants, FusedWAndFEqualTheSeparateCalls) {
  const sph::CubicSpline k(2);
  for (double r : {0.0, 1e-14, 0.3, 0.99, 1.0, 1.7, 2.0, 2.5}) {
    double W, F;
    k.W_and_F(r, 1.0, W, F);
    EXPECT_DOUBLE_EQ(W, k.W(r, 1.0)) << r;
    EXPECT_DOUBLE_EQ(F, k.F(r, 1.0)) << r;
  }
}

// Kernel::at(h), the refreshes' evaluator with its constants computed once, against the separate W and F at
// several smoothing lengths. q = r * (1/h) and r / h differ by at most ~2 ulp of q (2.2e-16 q); W and F move
// by |w'| or |(w'/q)'| times that, below 2.2e-16 * 2.5 * max|w'| * c ~ 1e-15 of the peak value for both shapes:
// 1e-14 of W(0) and F(0) bounds it (at h = 1 the two agree to the bit: FusedWAndFEqualTheSeparateCalls).
TEST(KernelConstants, AtFixedHEqualsTheSeparateCalls) {
  const sph::CubicSpline k(2);
  const sph::Lucy lucy(2);
  for (double h : {0.15, 1.0, 3.0}) {
    const auto at = k.at(h);
    const auto lat = lucy.at(h);
    for (double q : {0.0, 1e-14, 0.3, 0.99, 1.0, 1.7, 2.0, 2.5}) {
      double W, F;
      at(q * h, W, F);
      EXPECT_NEAR(W, k.W(q * h, h), 1e-14 * k.W(0.0, h)) << h << " " << q;
      EXPECT_NEAR(F, k.F(q * h, h), 1e-14 * std::abs(k.F(0.0, h))) << h << " " << q;
      lat(q * h, W, F);
      EXPECT_NEAR(W, lucy.W(q * h, h), 1e-14 * lucy.W(0.0, h)) << h << " " << q;
      EXPECT_NEAR(F, lucy.F(q * h, h), 1e-14 * std::abs(lucy.F(0.0, h))) << h << " " << q;
    }
  }
}

// The closed forms of dw(q)/q that the pair-list refreshes use instead of a division: equal to dw(q) / q to
// round-off (a few ulp of the largest |dw/q|, which is at q = 0), and to d2w(0) at q = 0.
TEST(KernelShapes, DwOverQIsTheClosedFormOfTheQuotient) {
  auto check = [](auto shape, double peak) {
    using S = decltype(shape);
    EXPECT_DOUBLE_EQ(S::dw_over_q(0.0), S::d2w(0.0));
    for (int i = 1; i <= 400; ++i) {
      const double q = i * 0.00625 * S::support;  // through both pieces of the spline and past the support
      EXPECT_NEAR(S::dw_over_q(q), S::dw(q) / q, 4e-16 * peak) << S::name << " q = " << q;
    }
  };
  check(sph::CubicSplineShape{}, 3.0);
  check(sph::LucyShape{}, 12.0);
}

#if defined(__AVX512F__) && defined(__AVX512VL__)
// The eight-wide forms that PairList::refresh uses on AVX-512 (kernels.hpp) give the scalar forms' bits, at
// random distances across the support and its edge and at the branch points q = 0, 1, 2 exactly: the
// refresh must not change a result (the quick values of every driver are bit-identical, see the notes of
// the commit that introduced it). A compiler that fused the scalar forms differently would fail here (in the
// Release build; the sanitizer build does not fuse: same_bits.hpp).
template <class K>
void expect_eight_wide_equals_scalar(const K& kernel, double h) {
  const auto g = kernel.at(h);
  static_assert(decltype(g)::batch8, "the kernel has an eight-wide form");
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.1 * K::support() * h);
  std::vector<double> r;
  for (double q : {0.0, 0.5, 1.0, 1.5, 2.0, 2.5}) r.push_back(q * h);
  r.push_back(std::nextafter(h, 0.0));
  r.push_back(std::nextafter(K::support() * h, 0.0));
  while (r.size() < 80000) r.push_back(u(rng));
  double Wscale = 0, Fscale = 0;  // the largest |W|, |F| sampled: what "a few roundings" is relative to
  for (double ri : r) {
    double Ws, Fs;
    g(ri, Ws, Fs);
    Wscale = std::max(Wscale, std::abs(Ws));
    Fscale = std::max(Fscale, std::abs(Fs));
  }
  for (std::size_t i = 0; i < r.size(); i += 8) {
    double W8[8], F8[8];
    __m512d W, F;
    g(_mm512_loadu_pd(&r[i]), W, F);
    _mm512_storeu_pd(W8, W);
    _mm512_storeu_pd(F8, F);
    for (int l = 0; l < 8; ++l) {
      double Ws, Fs;
      g(r[i + l], Ws, Fs);
      ASSERT_TRUE(same_bits(Ws, W8[l], Wscale)) << K::name() << " W at r/h = " << r[i + l] / h;
      ASSERT_TRUE(same_bits(Fs, F8[l], Fscale)) << K::name() << " F at r/h = " << r[i + l] / h;
    }
  }
}

TEST(KernelConstants, EightWideFormsGiveTheScalarBits) {
  expect_eight_wide_equals_scalar(sph::CubicSpline(2), 0.15);
  expect_eight_wide_equals_scalar(sph::Lucy(2), 3.0);
}
#endif
