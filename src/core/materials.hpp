// Material laws as plain functions of their inputs (no state, no particles): unit-testable alone.
//
// One section per law; a new law (equation of state, Hooke deviatoric stress rate, von Mises return, ...)
// gets its own section below the existing ones, with its equations cited in its doc comments.
//   1. Elastic constants        Lame parameters from E and nu (Ismail 2009 eqs 4.20, 4.22)
//   2. Wave speeds              c_L (4.38), c_b (4.39), c_T
//   3. Linear elasticity        small strain and Hooke's law T = lambda tr(eps) I + 2 mu eps (3.54)
//   4. Compressible neo-Hookean strain energy (3.62), P(F) (3.64), Cauchy stress T = J^-1 P F^T (3.33)
//   5. Weakly compressible solid (Gray, Monaghan & Swift 2001): equation of state (2.7), Hooke's
//      deviatoric stress rate with the rotation terms (2.3)-(2.5), Poisson's ratio (2.8)
//   6. Perfect plasticity: von Mises yield with radial return of the deviatoric stress (Gray 2001 Sec 7.3)
//
// Tensors are Eigen fixed-size D x D matrices, D = 2 or 3. In 2D every law is the PLANE-STRAIN law:
// F33 = 1, eps33 = 0 (Ismail 2009 Section 5.1.1 assumes plane strain for its 2D curves and code); the
// out-of-plane stress T33, which 2D codes do not carry, has its own function where it is needed.
// The stress functions are inline templates because they run once per particle per time step.
// They do not throw: for det F <= 0 the neo-Hookean functions return NaN or inf (ln J undefined), which
// the caller must detect (an exception inside an OpenMP loop would abort the process).
#pragma once

#include <Eigen/LU>
#include <cmath>

#include "core/types.hpp"

namespace sph {

// =====================================================================================================
// 1. Elastic constants
// =====================================================================================================

/// The Lame parameters of an isotropic elastic material.
struct Lame {
  double lambda;  ///< first Lame parameter
  double mu;      ///< shear modulus
};

/// lambda = E nu / ((1 + nu)(1 - 2 nu)), mu = E / (2 (1 + nu)): the inverse of Ismail 2009 eqs (4.20)
/// nu = lambda / (2 (lambda + mu)) and (4.22) E = mu (3 lambda + 2 mu) / (lambda + mu).
/// Throws std::invalid_argument unless E > 0 and -1 < nu < 1/2.
Lame lame_from_young_poisson(double E, double nu);
/// Young's modulus, Ismail 2009 eq (4.22).
double young_modulus(const Lame& m);
/// Poisson's ratio, Ismail 2009 eq (4.20).
double poisson_ratio(const Lame& m);
/// Bulk modulus K = lambda + 2 mu / 3 (3D).
double bulk_modulus(const Lame& m);
/// The one-dimensional-strain (P-wave) modulus lambda + 2 mu: the stress per unit strain in uniaxial
/// strain, Ismail 2009 eq (4.16); it is C in c_L^2 = C / rho (4.38).
inline double p_wave_modulus(const Lame& m) { return m.lambda + 2.0 * m.mu; }

// =====================================================================================================
// 2. Wave speeds (small strain). All throw std::invalid_argument unless rho > 0 and the modulus >= 0.
// =====================================================================================================

/// Longitudinal wave speed in one-dimensional strain, c_L^2 = (lambda + 2 mu) / rho, Ismail 2009 eq (4.38).
double longitudinal_wave_speed(const Lame& m, double rho);
/// Bar wave speed in one-dimensional stress, c_b^2 = E / rho, Ismail 2009 eq (4.39).
double bar_wave_speed(double E, double rho);
/// Transverse (shear) wave speed, c_T^2 = mu / rho.
double transverse_wave_speed(const Lame& m, double rho);

// =====================================================================================================
// 3. Linear elasticity: Hooke's law
// =====================================================================================================

/// Infinitesimal strain eps = (grad u + grad u^T) / 2 from the displacement gradient grad_u(i, j) = du_i/dx_j.
template <int D>
inline Tensor<D> small_strain(const Tensor<D>& grad_u) {
  return 0.5 * (grad_u + grad_u.transpose());
}

/// Hooke's law, T = lambda (tr eps) I + 2 mu eps, Ismail 2009 eq (3.54) (eq 4.15 in components).
/// In 2D this is plane strain (eps33 = 0); the out-of-plane stress is hooke_plane_strain_T33.
template <int D>
inline Tensor<D> hooke_stress(const Lame& m, const Tensor<D>& eps) {
  return m.lambda * eps.trace() * Tensor<D>::Identity() + 2.0 * m.mu * eps;
}

/// Out-of-plane stress of 2D plane-strain Hooke: T33 = lambda (eps11 + eps22).
inline double hooke_plane_strain_T33(const Lame& m, const Tensor2& eps) { return m.lambda * eps.trace(); }

// =====================================================================================================
// 4. Compressible neo-Hookean hyperelasticity (Ismail 2009 Section 3.3.3)
// =====================================================================================================
// Strain energy per unit reference volume (3.62):  Psi = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2,
// C = F^T F, J = det F. Second Piola-Kirchhoff stress (3.63): S = mu (I - C^-1) + lambda ln J C^-1;
// first Piola-Kirchhoff stress P = F S (3.38), which is (3.64): P = mu (F - F C^-1) + lambda ln J F C^-1.
// Since F C^-1 = F F^-1 F^-T = F^-T, P = mu (F - F^-T) + lambda ln J F^-T: that is the form coded (one
// inverse, no C^-1 of a possibly ill-conditioned C). P = dPsi/dF (tests/test_materials.cpp checks it).
// Plane strain in 2D: with F33 = 1, tr C = tr C_2D + 1 and J = det F_2D, so Psi = mu/2 (tr C_2D - 2) - ...
// and the in-plane P is the same formula on 2 x 2 matrices.

/// Strain energy Psi(F), Ismail 2009 eq (3.62); D = 2 is plane strain (tr C - 3 -> tr C_2D - 2).
template <int D>
inline double neo_hookean_energy(const Lame& m, const Tensor<D>& F) {
  const double lnJ = std::log(F.determinant());
  return 0.5 * m.mu * ((F.transpose() * F).trace() - D) - m.mu * lnJ + 0.5 * m.lambda * lnJ * lnJ;
}

/// First Piola-Kirchhoff stress P(F) = mu (F - F C^-1) + lambda ln J F C^-1, Ismail 2009 eq (3.64),
/// evaluated as mu (F - F^-T) + lambda ln J F^-T. D = 2: in-plane components under plane strain.
template <int D>
inline Tensor<D> neo_hookean_P(const Lame& m, const Tensor<D>& F) {
  const double J = F.determinant();
  const Tensor<D> F_invT = F.inverse().transpose();
  return m.mu * (F - F_invT) + m.lambda * std::log(J) * F_invT;
}

/// Second Piola-Kirchhoff stress S = mu (I - C^-1) + lambda ln J C^-1, Ismail 2009 eq (3.63).
template <int D>
inline Tensor<D> neo_hookean_S(const Lame& m, const Tensor<D>& F) {
  const Tensor<D> C_inv = (F.transpose() * F).inverse();
  return m.mu * (Tensor<D>::Identity() - C_inv) + m.lambda * std::log(F.determinant()) * C_inv;
}

/// Cauchy stress from the first Piola-Kirchhoff stress, T = J^-1 P F^T, Ismail 2009 eq (3.33).
template <int D>
inline Tensor<D> cauchy_from_P(const Tensor<D>& P, const Tensor<D>& F) {
  return P * F.transpose() / F.determinant();
}

/// First Piola-Kirchhoff stress from the Cauchy stress, P = J T F^-T, Ismail 2009 eq (3.32).
template <int D>
inline Tensor<D> P_from_cauchy(const Tensor<D>& T, const Tensor<D>& F) {
  return F.determinant() * T * F.inverse().transpose();
}

/// Neo-Hookean Cauchy stress T = J^-1 P(F) F^T (3.33 applied to 3.64). D = 2: in-plane, plane strain.
template <int D>
inline Tensor<D> neo_hookean_cauchy(const Lame& m, const Tensor<D>& F) {
  return cauchy_from_P<D>(neo_hookean_P<D>(m, F), F);
}

/// Out-of-plane Cauchy stress of the 2D plane-strain neo-Hookean law: with F33 = 1 the 33 component of
/// (3.64) is P33 = lambda ln J, and T33 = P33 / J (3.33).
inline double neo_hookean_plane_strain_T33(const Lame& m, const Tensor2& F) {
  const double J = F.determinant();
  return m.lambda * std::log(J) / J;
}

// =====================================================================================================
// 5. Weakly compressible elastic solid (Gray, Monaghan & Swift 2001, Section 2)
// =====================================================================================================
// Stress sigma = -P I + S (2.2), P from the density by the equation of state, S integrated in time by
// Hooke's law in rate form. Units of the paper: rho0 = 1, c0 = 1, stress in rho0 c0^2.

/// Equation of state P = c0^2 (rho - rho0), Gray et al. 2001 eq (2.7).
inline double linear_eos_pressure(double rho, double rho0, double c0) { return c0 * c0 * (rho - rho0); }

/// Rate of the deviatoric stress, Gray et al. 2001 eqs (2.3)-(2.5):
///   dS/dt = 2 mu (eps_dot - 1/3 tr(eps_dot) I) + S Omega^T + Omega S,
/// with grad_v(i, j) = dv_i/dx_j, eps_dot its symmetric and Omega its antisymmetric part. The rotation
/// terms make the rate objective (Jaumann). In 2D the 1/3 keeps the 3D deviator of a plane-strain
/// motion; the out-of-plane S_zz it implies is not carried (it does not enter the in-plane forces).
inline Tensor2 hooke_deviatoric_rate(double mu, const Tensor2& grad_v, const Tensor2& S) {
  const Tensor2 eps_dot = 0.5 * (grad_v + grad_v.transpose());
  const Tensor2 omega = 0.5 * (grad_v - grad_v.transpose());
  return 2.0 * mu * (eps_dot - eps_dot.trace() / 3.0 * Tensor2::Identity()) + S * omega.transpose() + omega * S;
}

/// The shear strain energy per unit volume that hooke_deviatoric_rate stores: (S:S + S_zz^2) / (4 mu) with
/// S_zz = -tr S, the out-of-plane deviator its 1/3 implies (from a state whose 3D deviator is traceless, as
/// S = 0). Its rate under hooke_deviatoric_rate is the stress power S : eps_dot (the rotation terms do no work);
/// S:S alone misses tr S tr(eps_dot) / 3.
inline double shear_energy_density(double mu, const Tensor2& S) {
  return (S.squaredNorm() + S.trace() * S.trace()) / (4.0 * mu);
}

/// Poisson's ratio as printed in Gray et al. 2001 eq (2.8): (3K/mu - 2) / (2 (3K/mu + 2)).
/// Note: the standard 3D relation is (3K - 2 mu) / (2 (3K + mu)); (2.8) has 2 mu where mu belongs in
/// the denominator. Both are provided so the plate theory (7.1) can be evaluated under either reading.
inline double gray_poisson_ratio_as_printed(double K, double mu) { return (3 * K / mu - 2) / (2 * (3 * K / mu + 2)); }
/// Poisson's ratio of an isotropic 3D solid with bulk modulus K and shear modulus mu.
inline double poisson_ratio_from_bulk_shear(double K, double mu) { return (3 * K - 2 * mu) / (2 * (3 * K + mu)); }
/// Young's modulus of an isotropic 3D solid with bulk modulus K and shear modulus mu: 9 K mu / (3K + mu).
inline double young_from_bulk_shear(double K, double mu) { return 9 * K * mu / (3 * K + mu); }

// =====================================================================================================
// 6. Perfectly plastic von Mises yield, radial return (Gray, Monaghan & Swift 2001 Section 7.3: "the Von
//    Mises criterion with a yield strength of 0.03"; the paper gives no formula)
// =====================================================================================================
// Convention (CHOSEN, the usual one of SPH solid codes, e.g. Libersky & Petschek 1991):
//  - the invariant is J2 = 1/2 S:S of the full 3D deviator. A 2D plane-strain state carries S_xx, S_xy,
//    S_yy; its out-of-plane component is S_zz = -(S_xx + S_yy), which is exactly what the 1/3 of the rate
//    (2.3) integrates to (section 5: the in-plane trace of dS/dt is 2 mu tr(eps_dot) / 3 = -dS_zz/dt);
//  - the yield strength Y is the UNIAXIAL yield stress ("yield strength" of a metal), so the surface is
//    sqrt(3 J2) = Y (a pure shear yields at S_xy = Y / sqrt(3)).
// Radial return: a trial S outside the surface is scaled back onto it, S <- S Y / sqrt(3 J2); inside, S is
// unchanged. Scaling keeps the direction of S and S_zz = -(S_xx + S_yy), and commutes with rotations.

/// J2 = 1/2 (S_xx^2 + S_yy^2 + S_zz^2 + 2 S_xy^2) with S_zz = -(S_xx + S_yy) (plane strain).
inline double plane_strain_J2(const Tensor2& S) {
  const double sxx = S(0, 0), syy = S(1, 1), szz = -(sxx + syy), sxy = 0.5 * (S(0, 1) + S(1, 0));
  return 0.5 * (sxx * sxx + syy * syy + szz * szz) + sxy * sxy;
}

/// von Mises equivalent stress sqrt(3 J2): equals |sigma| in uniaxial stress.
inline double von_mises_stress(const Tensor2& S) { return std::sqrt(3.0 * plane_strain_J2(S)); }

/// Perfectly plastic radial return onto the von Mises surface sqrt(3 J2) = yield (yield > 0).
inline Tensor2 von_mises_return(const Tensor2& S, double yield) {
  const double J2_3 = 3.0 * plane_strain_J2(S);
  if (J2_3 <= yield * yield) return S;
  return S * (yield / std::sqrt(J2_3));
}

}  // namespace sph
