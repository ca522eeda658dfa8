// The oscillating plate of Gray, Monaghan & Swift 2001 Section 7.1: a plate of length L and thickness H
// clamped at x = 0 between layers of fixed particles, set moving with the fundamental cantilever mode
// (7.3)-(7.4), and the thin-plate theory of its period (7.1)-(7.2).
#pragma once

#include <vector>

#include "updated_lagrangian/elastic_body.hpp"
#include "updated_lagrangian/parameters.hpp"

namespace scenes {

struct PlateSpec {
  double L = 20.0;             ///< free length (Gray 2001 Tables 1-2)
  double H = 2.0;              ///< thickness
  double dp = 0.2;             ///< particle spacing
  double clamp_length = 2.0;   ///< length of plate held between the fixed layers (CHOSEN: see driver)
  int clamp_layers = 3;        ///< fixed layers above, below and behind: 3 dp >= the 2h = 3 dp support
  double Vf = 0.01;            ///< tip speed over c0 (7.3)
  double perturbation = 0.0;   ///< random displacement of the free particles, uniform in +-perturbation*dp
  unsigned seed = 1;           ///< of the perturbation
  /// n + 1 rows with the outer centres on the faces y = 0 and y = H (PySPH's plate example), a plate H + dp
  /// thick, instead of n = H / dp rows at half spacings (issue 46's sensitivity study: the paper does not say)
  bool centres_on_faces = false;
};

/// kL of the fundamental cantilever mode: the first root of cos(kL) cosh(kL) = -1 (7.2), by GSL (Brent).
double cantilever_kL();

/// The mode-shape velocity v_y / c0 at distance x from the clamp (7.3)-(7.4): Vf at x = L, 0 at x = 0.
double cantilever_mode_velocity(double x, double L, double Vf);

/// Thin-plate period 2 pi / omega with omega^2 = E H^2 k^4 / (12 rho (1 - nu^2)) (7.1), k = kL/L.
double plate_theory_period(double E, double nu, double H, double L, double rho);
/// (7.1) for the material of Gray et al. (bulk modulus K = rho0 c0^2 = 1, shear modulus mu, rho0 = 1) with the
/// 3D moduli E = 9 K mu / (3K + mu), nu = (3K - 2 mu) / (2 (3K + mu)): the theory column's reading.
double plate_theory_period(double mu, double H, double L);

struct Plate {
  sph::ElasticBody body;       ///< its box contains the plate with room for its motion
  std::size_t tip = 0;         ///< the free-end particle on the mid-plane row whose y(t) is tracked
};

/// Builds the plate: free particles on a square lattice of spacing dp filling [-clamp_length, L] x [0, H]
/// (centres at half-spacings, so the plate is exactly H thick; with centres_on_faces, rows at y = 0, dp, .., H), fixed layers above and below the clamped
/// part and behind its end, and the initial velocity (7.3) on the particles with x > 0; masses rho0 dp^2 and
/// velocities in units of c0 from the scheme's parameters.
/// Refuses (std::invalid_argument, before anything is allocated) a plate whose particles cannot fit in memory
/// (sph::check_particle_count); make_plate calls it, and a driver that runs several scenes calls it for each
/// before its first run, so that a spacing typed wrong stops at once, not after the other scenes.
void check_size(const PlateSpec& s);
Plate make_plate(const PlateSpec& s, const sph::GrayParameters& scheme);

}  // namespace scenes
