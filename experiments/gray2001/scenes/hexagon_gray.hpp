// The rotating hexagon of Hoover, Hoover & Merritt 2004 (hoover2004/scenes/hexagon.hpp: 217 particles of the unit
// triangular lattice, rho = sqrt(4/3), m = 1, rigid rotation at 0.1 at the vertices) run with Gray, Monaghan &
// Swift's scheme: the scene the SPAM cures are judged on, so that the cures of both formulations meet on it
// (target X). READING of the material: Gray's scheme has a pressure rho0 c0^2 (rho/rho0 - 1) and a shear
// modulus mu; Hoover's lattice has the Lame constants lambda = eta = sqrt(3/16): c0^2 = (lambda + eta)/rho0
// (the 2D bulk modulus) and mu = eta. Gray's cubic spline at h = 1.5 spacings reaches 3 spacings, as Lucy's h = 3.
#pragma once

#include <string>

#include "hoover2004/scenes/hexagon.hpp"
#include "updated_lagrangian/gray_solver.hpp"

namespace scenes {

struct GrayHexagonSpec {
  sph::scenes::HexagonSetup hexagon;  ///< shells and vertex speed (the SPAM parameters give the material)
  sph::GrayOptions options;           ///< the cures under test
  double cfl = sph::GrayParameters{}.cfl;
  double angle = 2.0 * 3.14159265358979323846 / 3.0;  ///< nominal rotation at which L is read (Sec. VI: 120 degrees)
  double sample_dt = 1.0;             ///< interval of the fragment checks
  double fracture_link = 1.5;         ///< link distance / spacing of the connectivity
};

struct GrayHexagonResult {
  double L_loss = NAN;         ///< 1 - L / L0 at the nominal angle (centre-of-mass frame)
  std::size_t max_fragments = 0;
  std::size_t particles = 0;
  long steps = 0;
  double dt = 0, wall_s = 0;
  std::string blow_up;
};

/// Gray's parameters for Hoover's hexagon (the reading above).
sph::GrayParameters gray_hexagon_scheme(const sph::SpamParams& spam, double cfl);

GrayHexagonResult run_gray_hexagon(const GrayHexagonSpec& s, const std::string& progress_label = "hexagon (Gray)");

}  // namespace scenes
