// Whole-body diagnostics (src/core/diagnostics.hpp), the one convention every solver's energies and momenta
// are reported in: hand-computed values for three particles, the centre-of-mass decomposition of a rigid
// rotation about a moving centre (L_lab = L_c + M X x V, L_c = omega I, König's T = M V^2/2 + omega^2 I/2)
// with unequal masses, the ParticleArrays adaptor, and the shape fit used for Hoover's rotating hexagon.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "core/diagnostics.hpp"

namespace {

using sph::Vec2;

struct Particles {  // a particle set with one mass per particle
  std::vector<double> m;
  std::vector<Vec2> x, v;
  std::size_t size() const { return m.size(); }
  double mass(std::size_t a) const { return m[a]; }
  const Vec2& position(std::size_t a) const { return x[a]; }
  const Vec2& velocity(std::size_t a) const { return v[a]; }
};

constexpr double eps = std::numeric_limits<double>::epsilon();

TEST(Diagnostics, HandComputedEnergyAndMomenta) {
  // Small integers: every product and sum is exact, so the values are compared exactly.
  const Particles p{{1, 2, 3}, {{1, 0}, {0, 2}, {-1, -1}}, {{0, 1}, {1, 0}, {2, -1}}};
  EXPECT_EQ(sph::kinetic_energy(p), 0.5 * (1 * 1 + 2 * 1 + 3 * 5));   // 9
  EXPECT_EQ(sph::linear_momentum(p), Vec2(0 + 2 + 6, 1 + 0 - 3));   // (8, -2)
  // m (x v_y - y v_x): 1 (1 - 0) + 2 (0 - 2) + 3 (1 + 2) = 6, about the origin.
  EXPECT_EQ(sph::angular_momentum(p), 6.0);
  const sph::CentreOfMassFrame f = sph::centre_of_mass_frame(p);
  EXPECT_EQ(f.centre, Vec2(-2.0 / 6, 1.0 / 6));    // (1 + 0 - 3, 0 + 4 - 3) / 6
  EXPECT_EQ(f.velocity, Vec2(8.0 / 6, -2.0 / 6));
  EXPECT_EQ(f.kinetic, 9.0);
}

TEST(Diagnostics, RigidRotationAboutAMovingCentre) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0), mass(0.5, 3.0);
  const int n = 50;
  Particles body;
  std::vector<Vec2> r;
  Vec2 c = Vec2::Zero();
  double M = 0;
  for (int a = 0; a < n; ++a) {
    body.m.push_back(mass(rng));
    r.emplace_back(u(rng), u(rng));
    c += body.m.back() * r.back();
    M += body.m.back();
  }
  c /= M;
  const Vec2 X(3.0, -2.0), V(0.4, 0.7);
  const double omega = 1.3;
  double I = 0, scale = 0;
  for (int a = 0; a < n; ++a) {
    r[a] -= c;  // about the centre of mass
    body.x.push_back(X + r[a]);
    body.v.push_back(V + omega * Vec2(-r[a].y(), r[a].x()));
    I += body.m[a] * r[a].squaredNorm();
    scale += body.m[a] * body.x[a].norm() * body.v[a].norm();
  }
  // Each diagnostic is a sum of n terms of size <= m |x| |v|: recursive summation errs by at most
  // ~n eps sum |terms|; a factor 4 covers the products and the rounding of the centre: 4 n eps scale.
  const double tol = 4 * n * eps * scale;
  const sph::CentreOfMassFrame f = sph::centre_of_mass_frame(body);
  EXPECT_LT((f.centre - X).norm(), tol);
  EXPECT_LT((f.velocity - V).norm(), tol);
  EXPECT_NEAR(f.inertia, I, tol);
  EXPECT_NEAR(f.angular_momentum, omega * I, tol);
  const double L_orbit = M * (X.x() * V.y() - X.y() * V.x());
  EXPECT_NEAR(sph::angular_momentum(body), f.angular_momentum + L_orbit, tol);
  EXPECT_NEAR(f.kinetic, 0.5 * M * V.squaredNorm() + 0.5 * omega * omega * I, tol);
  EXPECT_EQ(f.kinetic, sph::kinetic_energy(body));  // the same sum in the same order
  EXPECT_NEAR(sph::linear_momentum(body).x(), M * V.x(), tol);
  EXPECT_GT(f.angular_momentum, 0.1 * std::abs(L_orbit));  // both parts are sizeable: an error in either shows
}

TEST(Diagnostics, ParticleArraysIsAnEqualMassParticleSet) {
  const std::vector<Vec2> x = {{0.3, -1.2}, {2.0, 0.7}, {-0.4, 0.1}}, v = {{1.5, 0.2}, {-0.3, 0.9}, {0.0, -2.2}};
  const sph::ParticleArrays arrays{x, v, 2.5};
  const Particles same{{2.5, 2.5, 2.5}, x, v};
  // The same sums over the same terms in the same order, equal up to rounding: the compiler may contract
  // m v + s into a fused multiply-add in one instantiation and not in the other (with -march=znver3 GCC 12
  // does so for linear_momentum, a difference in the last bit), so a few ulps of the sums' size (~10).
  const double ulps = 8 * std::numeric_limits<double>::epsilon() * 10;
  EXPECT_EQ(arrays.size(), 3u);
  EXPECT_NEAR(sph::kinetic_energy(arrays), sph::kinetic_energy(same), ulps);
  EXPECT_LT((sph::linear_momentum(arrays) - sph::linear_momentum(same)).norm(), ulps);
  EXPECT_NEAR(sph::angular_momentum(arrays), sph::angular_momentum(same), ulps);
  EXPECT_NEAR(sph::centre_of_mass_frame(arrays).angular_momentum, sph::centre_of_mass_frame(same).angular_momentum, ulps);
  // And the adaptor's default mass is 1.
  EXPECT_DOUBLE_EQ(sph::kinetic_energy(sph::ParticleArrays{x, v}), 0.5 * (1.5 * 1.5 + 0.2 * 0.2 + 0.3 * 0.3 + 0.9 * 0.9 + 2.2 * 2.2));
}

TEST(ShapeFit, RecoversTheRotationOfARigidMotionAndMeasuresAStretch) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec2> ref;
  for (int i = 0; i < 30; ++i) ref.emplace_back(u(rng), u(rng));
  const Vec2 shift(5.0, -3.0);
  for (double theta : {2.0, -2.9, 0.01}) {
    const double cs = std::cos(theta), sn = std::sin(theta);
    auto move = [&](double stretch) {
      std::vector<Vec2> x;
      for (const Vec2& a : ref) x.push_back(stretch * Vec2(cs * a.x() - sn * a.y(), sn * a.x() + cs * a.y()) + shift);
      return x;
    };
    // Rigid: the coordinates carry round-off of ~eps |shift| = 1.3e-15 each, which is all the rms and the
    // angle (a ratio of sums of 30 such terms) can see: 1e-13 leaves a margin of ~100 ulps.
    const sph::ShapeFit rigid = sph::shape_fit(ref, move(1.0));
    EXPECT_NEAR(rigid.angle, theta, 1e-13);
    EXPECT_LT(rigid.rms, 1e-13);
    // A uniform stretch s about the centroid leaves the best angle unchanged (both sums scale by s), and the
    // residual (s - 1) R a gives rms = |s - 1| sqrt(mean |a|^2), a the reference about its centroid.
    Vec2 c0 = Vec2::Zero();
    for (const Vec2& a : ref) c0 += a / 30.0;
    double mean2 = 0;
    for (const Vec2& a : ref) mean2 += (a - c0).squaredNorm() / 30.0;
    const sph::ShapeFit stretched = sph::shape_fit(ref, move(1.1));
    EXPECT_NEAR(stretched.angle, theta, 1e-13);
    EXPECT_NEAR(stretched.rms, 0.1 * std::sqrt(mean2), 1e-13);
  }
}

}  // namespace
