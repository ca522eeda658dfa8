// The oscillating plate of Gray, Monaghan & Swift 2001 Section 7.1 by the total-Lagrangian SPH of Ismail 2009
// (Section 5.4, TlSolver2D): the cures table's total-Lagrangian column (issue 14 item 9). The kernel, its
// support and the gradients live in the reference configuration, so the tensile instability of the updated-
// Lagrangian scheme has no pairs to act on: the question is the period it gives against (7.1).
//
// CHOSEN (the papers say nothing of a total-Lagrangian plate): the cantilever [0, L] x [0, H] on a square
// lattice of spacing ps, its particles at (i ps, j ps) so that the outermost centres span H (the total-
// Lagrangian bodies of I-2d and I-hole); the left edge clamped (u = 0, ghost reflection of the Dirichlet
// condition: no fixed layers), the other edges traction-free; neo-Hookean (the plate turns by ~0.5 rad at
// V_f = 0.05); h/ps = 3.5 and dt = 0.3 h / c_L as I-hole; the initial velocity the mode (7.3)-(7.4), as the
// updated-Lagrangian plate; no damping, no zero-energy-mode control.
#pragma once

#include <string>
#include <vector>

#include "gray2001/scenes/plate_run.hpp"

namespace scenes {

struct TlPlateSpec {
  double L = 20.0, H = 2.0;
  double ps = 0.25;            ///< lattice spacing: H / ps + 1 particles across
  double Vf = 0.05;            ///< tip speed over c0 (7.3)
  double K = 1.0, mu = 0.6;    ///< bulk and shear modulus (Gray's material, rho0 = c0 = 1)
  double h_over_ps = 3.5, dt_factor = 0.3;
  double t_end = 2000;
  int stop_after_crossings = 1;  ///< stop once the tip has crossed its start line this often
  bool variational = false;      ///< the variational closure instead of ghost reflection (TlConfig2D::Closure)
  bool hooke = false;            ///< Hooke (small strain) instead of neo-Hookean
};

struct TlPlateResult {
  std::vector<TipSample> trace;  ///< y: tip displacement (the particle at (L, H/2)); ke, ee; fragments 1
  long steps = 0;
  int particles = 0;
  double dt = 0, wall_s = 0;
  std::string blow_up;           ///< the solver's message if the state became non-finite
};

TlPlateResult run_tl_plate(const TlPlateSpec& s, const std::string& progress_label = "total-Lagrangian plate");

}  // namespace scenes
