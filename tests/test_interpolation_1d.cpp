// 1D SPH interpolation (Ismail 2009 eqs 2.24-2.25): particle lines with ghosts, exactness for linear
// functions in the interior, the boundary deficit without ghosts, and convergence under refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "total_lagrangian/interpolation_1d.hpp"
#include "core/kernels.hpp"

namespace {

std::vector<double> sample(const sph::ParticleLine& line, double (*f)(double)) {
  std::vector<double> v(line.size());
  for (std::size_t i = 0; i < line.size(); ++i) v[i] = f(line.x[i]);
  return v;
}

TEST(ParticleLine, UniformLineWithGhosts) {
  const auto line = sph::uniform_line(0.0, 1.0, 0.1, 0.25);  // 2 ghost layers each side
  EXPECT_EQ(line.n_real, 11u);
  EXPECT_EQ(line.first_real, 2u);
  EXPECT_EQ(line.size(), 15u);
  EXPECT_NEAR(line.x.front(), -0.2, 1e-14);
  EXPECT_NEAR(line.x.back(), 1.2, 1e-14);
  EXPECT_TRUE(line.is_real(2) && line.is_real(12));
  EXPECT_FALSE(line.is_real(1) || line.is_real(13));
  EXPECT_THROW(sph::uniform_line(0.0, 1.0, 0.3, 0.0), std::invalid_argument);  // 1/0.3 not whole
  EXPECT_THROW(sph::uniform_line(1.0, 0.0, 0.1, 0.0), std::invalid_argument);
}

TEST(ParticleLine, NeighbourRangeIsStrict) {
  const auto line = sph::uniform_line(0.0, 1.0, 0.1, 0.0);
  const auto [lo, hi] = sph::neighbour_range(line, 0.5, 0.15);  // 0.4, 0.5, 0.6
  EXPECT_EQ(lo, 4u);
  EXPECT_EQ(hi, 7u);
}

double linear(double x) { return 2.0 * x + 1.0; }

// With ghosts the stencil at every real particle is symmetric, so <f> = f * sum W dV and
// <f'> = slope * lattice_gradient_of_linear exactly (the antisymmetric terms cancel).
TEST(Interpolation1D, LinearFunctionExactInTheInteriorWithGhosts) {
  const sph::ModifiedMollifier k(1);
  const double ps = 0.02, h = 5.5 * ps;
  const auto line = sph::uniform_line(0.0, 1.0, ps, 2 * h);
  const double scale = 1.0 / sph::lattice_sum_of_weights(k, h, ps);  // lattice normalisation
  const auto f = sample(line, linear);
  const auto sf = sph::sph_value(k, h, line, f, scale);
  const auto sdf = sph::sph_gradient(k, h, line, f, scale);
  const double g = scale * sph::lattice_gradient_of_linear(k, h, ps);
  for (std::size_t i = line.first_real; i < line.first_real + line.n_real; ++i) {
    EXPECT_NEAR(sf[i], f[i], 1e-12) << line.x[i];
    EXPECT_NEAR(sdf[i], 2.0 * g, 1e-11) << line.x[i];
  }
  // A 5.5-spacing modified-mollifier cover samples the lattice well: the gradient is within 1e-4.
  EXPECT_NEAR(g, 1.0, 1e-4);
}

TEST(Interpolation1D, ConstantHasZeroGradientWithGhosts) {
  const sph::CubicSpline k(1);
  const double ps = 0.05, h = 1.3 * ps;
  const auto line = sph::uniform_line(0.0, 1.0, ps, 2 * k.support() * h);
  const auto sdf = sph::sph_gradient(k, h, line, std::vector<double>(line.size(), 3.0));
  for (std::size_t i = line.first_real; i < line.first_real + line.n_real; ++i) EXPECT_NEAR(sdf[i], 0.0, 1e-12);
}

// The lattice part of the gradient error depends on h/ps only and vanishes as the cover widens; the
// 1.5-spacing modified mollifier keeps only the +-1 neighbours and returns 15% of the slope.
TEST(Interpolation1D, LatticeGradientOfLinear) {
  const sph::ModifiedMollifier k(1);
  EXPECT_NEAR(sph::lattice_gradient_of_linear(k, 7.5, 1.0), 1.0, 1e-6);
  EXPECT_NEAR(sph::lattice_gradient_of_linear(k, 15.0, 3.0), sph::lattice_gradient_of_linear(k, 5.0, 1.0), 1e-12);
  EXPECT_LT(sph::lattice_gradient_of_linear(k, 1.5, 1.0), 0.2);
}

// Without ghosts the end particle has half a cover plus its own weight: sum = (lattice sum + W(0) ps)/2.
TEST(Interpolation1D, EndParticleDeficitWithoutGhosts) {
  const sph::ModifiedMollifier k(1);
  const double ps = 0.01, h = 5.5 * ps;
  const auto line = sph::uniform_line(0.0, 1.0, ps, 0.0);
  const auto sw = sph::sum_of_weights(k, h, line);
  EXPECT_NEAR(sw.front(), 0.5 * (sph::lattice_sum_of_weights(k, h, ps) + k.W(0, h) * ps), 1e-12);
  EXPECT_NEAR(sw.front(), sw.back(), 1e-12);
  EXPECT_LT(sw.front(), 0.7);
  EXPECT_GT(sw.front(), 0.5);
}

// At a fixed cover/spacing ratio in the well-sampled range the error is the smoothing (h^2) part of
// eq (2.35): four times finer spacing, about sixteen times smaller error.
TEST(Interpolation1D, ErrorFallsWithRefinement) {
  const sph::ModifiedMollifier k(1);
  auto rms_gradient_error = [&](int n) {
    const double ps = M_PI / n, h = 4.5 * ps;
    const auto line = sph::uniform_line(0.0, M_PI, ps, 2 * h);
    const auto sdf = sph::sph_gradient(k, h, line, sample(line, [](double x) { return std::sin(x); }));
    double s = 0;
    for (std::size_t i = line.first_real; i < line.first_real + line.n_real; ++i)
      s += std::pow(sdf[i] - std::cos(line.x[i]), 2);
    return std::sqrt(s / line.n_real);
  };
  const double coarse = rms_gradient_error(20), fine = rms_gradient_error(80);
  EXPECT_GT(coarse / fine, 10.0);
  EXPECT_LT(coarse / fine, 20.0);
}

TEST(Interpolation1D, RejectsMismatchedValues) {
  const sph::Lucy k(1);
  const auto line = sph::uniform_line(0.0, 1.0, 0.1, 0.0);
  EXPECT_THROW(sph::sph_value(k, 0.3, line, std::vector<double>(3, 1.0)), std::invalid_argument);
  EXPECT_THROW(sph::sph_gradient(k, 0.3, line, std::vector<double>(3, 1.0)), std::invalid_argument);
}

}  // namespace
