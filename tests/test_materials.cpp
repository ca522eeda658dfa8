// Material laws (src/core/materials.hpp): neo-Hookean stress against its strain energy, objectivity, symmetry,
// the stress-free reference state, the small-strain limit against Hooke's law, plane strain against 3D,
// the elastic constants and wave speeds against the numbers Ismail 2009 states, and the von Mises radial
// return (on the surface after return, unchanged inside, objective, idempotent).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>
#include <stdexcept>

#include "core/materials.hpp"

namespace {

using sph::Lame;
using sph::Tensor;

// Steel of Ismail 2009 Section 5.3.1 in GPa: E = 200, nu = 0.3; and the nearly incompressible nu = 0.49.
const Lame kSteel = sph::lame_from_young_poisson(200.0, 0.3);
const Lame kRubbery = sph::lame_from_young_poisson(200.0, 0.49);

// A deterministic general deformation gradient (non-symmetric, det F > 0) of size `amplitude` around I.
template <int D>
Tensor<D> random_F(unsigned seed, double amplitude = 0.4) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Tensor<D> F;
  do {
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) F(i, j) = (i == j ? 1.0 : 0.0) + amplitude * u(gen);
  } while (F.determinant() < 0.2);
  return F;
}

template <int D>
Tensor<D> rotation(unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  if constexpr (D == 2) {
    return Eigen::Rotation2Dd(3.0 * u(gen)).toRotationMatrix();
  } else {
    const Eigen::Vector3d axis = Eigen::Vector3d(u(gen), u(gen), u(gen)).normalized();
    return Eigen::AngleAxisd(3.0 * u(gen), axis).toRotationMatrix();
  }
}

template <class T>
class NeoHookeanTest : public ::testing::Test {};
using Dims = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(NeoHookeanTest, Dims);

TYPED_TEST(NeoHookeanTest, ReferenceStateIsStressFree) {
  constexpr int D = TypeParam::value;
  const Tensor<D> I = Tensor<D>::Identity();
  for (const Lame& m : {kSteel, kRubbery}) {
    EXPECT_EQ(sph::neo_hookean_P<D>(m, I).norm(), 0.0);
    EXPECT_EQ(sph::neo_hookean_cauchy<D>(m, I).norm(), 0.0);
    EXPECT_EQ(sph::neo_hookean_S<D>(m, I).norm(), 0.0);
    EXPECT_EQ(sph::neo_hookean_energy<D>(m, I), 0.0);
  }
}

// Frame indifference: a rotation Q after the deformation leaves Psi unchanged and rotates the stresses,
// P(QF) = Q P(F), T(QF) = Q T(F) Q^T.
TYPED_TEST(NeoHookeanTest, Objectivity) {
  constexpr int D = TypeParam::value;
  for (unsigned s = 1; s <= 20; ++s) {
    const Tensor<D> F = random_F<D>(s), Q = rotation<D>(100 + s);
    const Tensor<D> P = sph::neo_hookean_P<D>(kSteel, F), T = sph::neo_hookean_cauchy<D>(kSteel, F);
    const double scale = P.norm() + kSteel.mu;
    EXPECT_LE((sph::neo_hookean_P<D>(kSteel, Q * F) - Q * P).norm(), 1e-13 * scale) << "seed " << s;
    EXPECT_LE((sph::neo_hookean_cauchy<D>(kSteel, Q * F) - Q * T * Q.transpose()).norm(), 1e-13 * scale);
    EXPECT_NEAR(sph::neo_hookean_energy<D>(kSteel, Q * F), sph::neo_hookean_energy<D>(kSteel, F),
                1e-13 * scale);
  }
}

// Balance of angular momentum: T = J^-1 (mu (F F^T - I) + lambda ln J I) is symmetric for any F, even
// though P is not.
TYPED_TEST(NeoHookeanTest, CauchyStressIsSymmetric) {
  constexpr int D = TypeParam::value;
  for (unsigned s = 1; s <= 20; ++s) {
    const Tensor<D> F = random_F<D>(s, 0.8);
    const Tensor<D> T = sph::neo_hookean_cauchy<D>(kRubbery, F);
    EXPECT_LE((T - T.transpose()).norm(), 1e-13 * T.norm()) << "seed " << s;
    const Tensor<D> P = sph::neo_hookean_P<D>(kRubbery, F);
    EXPECT_GT((P - P.transpose()).norm(), 1e-3 * P.norm()) << "P of a general F should not be symmetric";
  }
}

// P is the derivative of the strain energy (3.62) with respect to F: central differences of Psi.
TYPED_TEST(NeoHookeanTest, PiolaIsDerivativeOfStrainEnergy) {
  constexpr int D = TypeParam::value;
  for (const Lame& m : {kSteel, kRubbery}) {
    for (unsigned s = 1; s <= 10; ++s) {
      const Tensor<D> F = random_F<D>(s, 0.6);
      const Tensor<D> P = sph::neo_hookean_P<D>(m, F);
      const double h = 1e-6;
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) {
          Tensor<D> Fp = F, Fm = F;
          Fp(i, j) += h;
          Fm(i, j) -= h;
          const double fd = (sph::neo_hookean_energy<D>(m, Fp) - sph::neo_hookean_energy<D>(m, Fm)) / (2 * h);
          // Truncation O(h^2 Psi''') and round-off O(eps Psi / h): both ~1e-9 of the stress scale here.
          EXPECT_NEAR(P(i, j), fd, 1e-7 * (P.norm() + m.lambda + m.mu)) << "seed " << s << " (" << i << j << ")";
        }
    }
  }
}

// The three stress measures agree: P = F S (3.38) and T = J^-1 F S F^T (3.36); P_from_cauchy inverts (3.33).
TYPED_TEST(NeoHookeanTest, StressMeasuresConsistent) {
  constexpr int D = TypeParam::value;
  for (unsigned s = 1; s <= 10; ++s) {
    const Tensor<D> F = random_F<D>(s, 0.6);
    const Tensor<D> P = sph::neo_hookean_P<D>(kSteel, F), S = sph::neo_hookean_S<D>(kSteel, F);
    const Tensor<D> T = sph::neo_hookean_cauchy<D>(kSteel, F);
    const double scale = P.norm() + kSteel.mu;
    EXPECT_LE((P - F * S).norm(), 1e-13 * scale);
    EXPECT_LE((T - F * S * F.transpose() / F.determinant()).norm(), 1e-13 * scale);
    EXPECT_LE((sph::P_from_cauchy<D>(T, F) - P).norm(), 1e-13 * scale);
  }
}

// Small strain: for F = I + eps G the neo-Hookean stresses equal Hooke's law (3.54) of the small strain
// sym(eps G) up to O(eps^2) (Ismail 2009 Section 3.3.3: "reduces to a linear elastic one").
TYPED_TEST(NeoHookeanTest, SmallStrainLimitIsHooke) {
  constexpr int D = TypeParam::value;
  for (const Lame& m : {kSteel, kRubbery}) {
    for (unsigned s = 1; s <= 5; ++s) {
      const Tensor<D> G = random_F<D>(s, 1.0) - Tensor<D>::Identity();
      double previous = 0;
      for (double eps : {1e-3, 1e-4}) {
        const Tensor<D> F = Tensor<D>::Identity() + eps * G;
        const Tensor<D> hooke = sph::hooke_stress<D>(m, sph::small_strain<D>(eps * G));
        const double scale = (m.lambda + 2 * m.mu) * eps * G.norm();
        const double errP = (sph::neo_hookean_P<D>(m, F) - hooke).norm() / scale;
        const double errT = (sph::neo_hookean_cauchy<D>(m, F) - hooke).norm() / scale;
        // Relative deviation of first order in eps (second order in absolute terms).
        EXPECT_LT(errP, 10 * eps * G.norm()) << "eps " << eps;
        EXPECT_LT(errT, 10 * eps * G.norm()) << "eps " << eps;
        if (previous > 0) {
          EXPECT_NEAR(previous / errP, 10.0, 1.0) << "relative error not first order in eps";
        }
        previous = errP;
      }
    }
  }
}

// Plane strain: the 2D law is the in-plane block of the 3D law with F33 = 1, and T33 its 33 component.
TEST(NeoHookean, PlaneStrainIsThreeDWithUnitThirdStretch) {
  for (unsigned s = 1; s <= 10; ++s) {
    const sph::Tensor2 F2 = random_F<2>(s, 0.7);
    sph::Tensor3 F3 = sph::Tensor3::Identity();
    F3.topLeftCorner<2, 2>() = F2;
    const sph::Tensor3 T3 = sph::neo_hookean_cauchy<3>(kRubbery, F3);
    const double scale = T3.norm() + kRubbery.mu;
    EXPECT_LE((sph::neo_hookean_cauchy<2>(kRubbery, F2) - T3.topLeftCorner<2, 2>()).norm(), 1e-13 * scale);
    EXPECT_NEAR(sph::neo_hookean_plane_strain_T33(kRubbery, F2), T3(2, 2), 1e-13 * scale);
    EXPECT_NEAR(sph::neo_hookean_energy<2>(kRubbery, F2), sph::neo_hookean_energy<3>(kRubbery, F3), 1e-13 * scale);
    const sph::Tensor2 e2 = sph::small_strain<2>(F2 - sph::Tensor2::Identity());
    sph::Tensor3 e3 = sph::Tensor3::Zero();
    e3.topLeftCorner<2, 2>() = e2;
    const sph::Tensor3 H3 = sph::hooke_stress<3>(kRubbery, e3);
    EXPECT_LE((sph::hooke_stress<2>(kRubbery, e2) - H3.topLeftCorner<2, 2>()).norm(), 1e-12 * H3.norm());
    EXPECT_NEAR(sph::hooke_plane_strain_T33(kRubbery, e2), H3(2, 2), 1e-12 * H3.norm());
  }
}

// One-dimensional strain, F = diag(l, 1, 1): P11 = mu (l - 1/l) + lambda ln l / l, Ismail 2009
// Algorithm 5.1 line 15 and eq (5.4).
TEST(NeoHookean, UniaxialStrainMatchesAlgorithm51) {
  for (double l : {0.3, 0.8, 1.0, 1.7, 3.6, 6.0}) {
    const sph::Tensor3 F = Eigen::Vector3d(l, 1.0, 1.0).asDiagonal();
    const double expected = kSteel.mu * (l - 1.0 / l) + kSteel.lambda * std::log(l) / l;
    EXPECT_NEAR(sph::neo_hookean_P<3>(kSteel, F)(0, 0), expected, 1e-13 * (std::abs(expected) + kSteel.mu)) << l;
  }
}

TEST(Hooke, UniaxialStrainGivesPWaveModulus) {
  // eps = diag(e, 0, 0): T11 = (lambda + 2 mu) e, T22 = T33 = lambda e (Ismail 2009 eq 4.16).
  const double e = 1e-3;
  const sph::Tensor3 T = sph::hooke_stress<3>(kSteel, sph::Tensor3(Eigen::Vector3d(e, 0, 0).asDiagonal()));
  EXPECT_NEAR(T(0, 0), sph::p_wave_modulus(kSteel) * e, 1e-15);
  EXPECT_NEAR(T(1, 1), kSteel.lambda * e, 1e-15);
  // A rigid rotation of the displacement gradient (skew part) gives no small strain and no stress.
  sph::Tensor3 skew;
  skew << 0, 1, 2, -1, 0, 3, -2, -3, 0;
  EXPECT_EQ(sph::hooke_stress<3>(kSteel, sph::small_strain<3>(skew)).norm(), 0.0);
}

// ----- Elastic constants and wave speeds -----

TEST(ElasticConstants, RoundTripThroughEqs420And422) {
  for (double nu : {-0.5, 0.0, 0.25, 0.3, 0.49, 0.4999}) {
    const Lame m = sph::lame_from_young_poisson(7.0, nu);
    EXPECT_NEAR(sph::young_modulus(m), 7.0, 1e-12 * 7.0 / (1 - 2 * nu)) << nu;
    EXPECT_NEAR(sph::poisson_ratio(m), nu, 1e-12) << nu;
    EXPECT_NEAR(sph::bulk_modulus(m), 7.0 / (3 * (1 - 2 * nu)), 1e-11 / (1 - 2 * nu)) << nu;
  }
  EXPECT_THROW(sph::lame_from_young_poisson(1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(sph::lame_from_young_poisson(1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(sph::lame_from_young_poisson(0.0, 0.3), std::invalid_argument);
}

// Ismail 2009 Section 4.6.3.5 (Fig 4.14 table) with nu = 0.3 (Section 5.3.1): c_L = 5801, 4102, 8204 m/s,
// stated to the metre per second.
TEST(WaveSpeeds, IsmailTable414) {
  const struct { double rho, E, c; } rows[] = {{8000, 200e9, 5801}, {8000, 100e9, 4102}, {4000, 200e9, 8204}};
  for (const auto& r : rows) {
    const Lame m = sph::lame_from_young_poisson(r.E, 0.3);
    EXPECT_NEAR(sph::longitudinal_wave_speed(m, r.rho), r.c, 0.5) << r.E << " " << r.rho;
  }
  const Lame steel = sph::lame_from_young_poisson(200e9, 0.3);
  EXPECT_NEAR(sph::bar_wave_speed(200e9, 8000), 5000.0, 1e-9);
  EXPECT_NEAR(sph::transverse_wave_speed(steel, 8000), std::sqrt(200e9 / 2.6 / 8000), 1e-9);
  // c_T < c_b < c_L for 0 < nu < 1/2.
  EXPECT_LT(sph::transverse_wave_speed(steel, 8000), sph::bar_wave_speed(200e9, 8000));
  EXPECT_LT(sph::bar_wave_speed(200e9, 8000), sph::longitudinal_wave_speed(steel, 8000));
  EXPECT_THROW(sph::bar_wave_speed(200e9, 0.0), std::invalid_argument);
  EXPECT_THROW(sph::longitudinal_wave_speed(steel, -1.0), std::invalid_argument);
}

// ----- von Mises radial return (section 6 of materials.hpp) -------------------------------------------

sph::Tensor2 random_deviator(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  sph::Tensor2 S;
  const double sxy = u(rng);
  S << u(rng), sxy, sxy, u(rng);  // S_xx + S_yy need not vanish: S_zz = -(S_xx + S_yy)
  return S;
}

// The shear energy of Gray's Hooke rate (issue 15 a): its rate is the stress power S : eps_dot for any
// velocity gradient, spin included; the in-plane S:S / (4 mu) alone misses tr S tr(eps_dot) / 3.
TEST(Hooke, ShearEnergyRateIsTheStressPower) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double mu = 0.22;
  for (int trial = 0; trial < 100; ++trial) {
    sph::Tensor2 S, L;
    const double sxy = u(rng);
    S << u(rng), sxy, sxy, u(rng);
    L << u(rng), u(rng), u(rng), u(rng);
    const sph::Tensor2 rate = sph::hooke_deviatoric_rate(mu, L, S);
    const sph::Tensor2 eps_dot = 0.5 * (L + L.transpose());
    const double h = 1e-6;  // d/dt by a central difference of the energy along S + t rate
    const double dU = (sph::shear_energy_density(mu, S + h * rate) - sph::shear_energy_density(mu, S - h * rate)) / (2 * h);
    const double power = (S.array() * eps_dot.array()).sum();
    EXPECT_NEAR(dU, power, 1e-8) << "trial " << trial;
    const double in_plane_only = (S.array() * rate.array()).sum() / (2 * mu);
    if (std::abs(S.trace() * eps_dot.trace()) > 0.1) {
      EXPECT_GT(std::abs(in_plane_only - power), 1e-3);
    }
  }
}

TEST(VonMises, InvariantMatchesTheThreeDimensionalDeviator) {
  std::mt19937 rng(21);
  for (int trial = 0; trial < 50; ++trial) {
    const sph::Tensor2 S = random_deviator(rng, 0.1);
    Eigen::Matrix3d S3 = Eigen::Matrix3d::Zero();
    S3.topLeftCorner<2, 2>() = S;
    S3(2, 2) = -S.trace();
    EXPECT_NEAR(sph::plane_strain_J2(S), 0.5 * (S3.array() * S3.array()).sum(), 1e-15);
  }
  // Uniaxial stress sigma_xx = s: deviator (2s/3, -s/3, -s/3), equivalent stress |s|.
  sph::Tensor2 uni;
  uni << 2.0 / 3.0 * 0.05, 0, 0, -0.05 / 3.0;
  EXPECT_NEAR(sph::von_mises_stress(uni), 0.05, 1e-15);
  // Pure shear S_xy = k yields at k = Y / sqrt(3).
  sph::Tensor2 shear;
  shear << 0, 1, 1, 0;
  EXPECT_NEAR(sph::von_mises_stress(shear), std::sqrt(3.0), 1e-15);
}

TEST(VonMises, ReturnLandsOnTheSurfaceAlongTheTrialDirection) {
  std::mt19937 rng(22);
  const double Y = 0.03;
  int outside = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const sph::Tensor2 S = random_deviator(rng, 0.1);
    if (sph::von_mises_stress(S) <= Y) continue;
    ++outside;
    const sph::Tensor2 R = sph::von_mises_return(S, Y);
    EXPECT_NEAR(sph::von_mises_stress(R), Y, 1e-15);
    const double k = R(0, 0) / S(0, 0);  // radial: R = k S with 0 < k < 1
    EXPECT_GT(k, 0.0);
    EXPECT_LT(k, 1.0);
    EXPECT_LT((R - k * S).norm(), 1e-15);
  }
  EXPECT_GT(outside, 100);
}

TEST(VonMises, InsideTheSurfaceNothingChanges) {
  std::mt19937 rng(23);
  const double Y = 0.03;
  for (int trial = 0; trial < 200; ++trial) {
    const sph::Tensor2 S = random_deviator(rng, 0.008);  // sqrt(3 J2) <= sqrt(12) x 0.008 < Y
    ASSERT_LE(sph::von_mises_stress(S), Y);
    EXPECT_EQ(sph::von_mises_return(S, Y), S);  // bit for bit
  }
}

TEST(VonMises, ReturnIsObjectiveAndIdempotent) {
  std::mt19937 rng(24);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI);
  const double Y = 0.03;
  for (int trial = 0; trial < 100; ++trial) {
    const sph::Tensor2 S = random_deviator(rng, 0.1);
    const sph::Tensor2 Q = Eigen::Rotation2Dd(angle(rng)).toRotationMatrix();
    const sph::Tensor2 R = sph::von_mises_return(S, Y);
    EXPECT_LT((sph::von_mises_return(Q * S * Q.transpose(), Y) - Q * R * Q.transpose()).norm(), 1e-15);
    EXPECT_LT((sph::von_mises_return(R, Y) - R).norm(), 1e-16);
  }
}

}  // namespace
