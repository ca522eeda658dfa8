// The updated-Lagrangian SPH scheme for elastic solids of Gray, Monaghan & Swift 2001 (Sections 2, 3, 6):
//   acceleration (3.1) with the artificial stress (3.12)-(3.14) in principal axes (6.1)-(6.9),
//   XSPH velocity (3.6) used for positions, density and velocity gradients,
//   continuity (3.8) or summation density, EOS (2.7), Hooke deviatoric stress rate (2.3)-(2.5) with the
//   velocity gradient (3.10), Monaghan's artificial viscosity, and the predictor-corrector leapfrog
//   (6.14)-(6.18) with two force evaluations per step. Optional perfectly plastic von Mises yield
//   (Section 7.3): a radial return of S after each stress update, a separate pass that only runs if enabled.
// Particle kinds (elastic_body.hpp): Free particles move with the forces (and the XSPH velocity), Fixed ones
//   stay, Driven ones follow their prescribed acceleration exactly; all interact through the same SPH sums,
//   so contact between bodies (the colliding rings) is nothing but those sums.
//
// A scene declares the terms it uses in GrayOptions. GraySolver maps them once, at construction, to a
// compile-time instance of the pair loop (GrayTerms<...>) so that a term that is off is not in the loop
// at all; that mapping is the only place that branches on the options.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "updated_lagrangian/elastic_body.hpp"
#include "core/kernels.hpp"
#include "core/neighbours.hpp"
#include "core/pair_list.hpp"

namespace sph {

struct GrayOptions {
  bool artificial_stress = true;   ///< R_ab f^n term (3.12)
  bool xsph = true;                ///< move with and differentiate the XSPH velocity (3.6)
  bool viscosity = true;           ///< Monaghan's Pi_ab
  bool summation_density = false;  ///< rho_a = sum_b m_b W_ab instead of the continuity equation (3.8)
  bool plasticity = false;         ///< perfectly plastic von Mises radial return after every stress update
  std::string describe() const;
};

struct GrayParameters {
  double rho0 = 1.0, c0 = 1.0;     ///< reference density and sound speed (units of the paper)
  double mu = 0.22;                ///< shear modulus in rho0 c0^2
  double dp = 0.1;                 ///< initial particle spacing
  double h = 0.15;                 ///< smoothing length (Gray et al. Section 7: h = 1.5 dp)
  double eps_artificial = 0.3;     ///< epsilon of (5.31)
  int n_artificial = 4;            ///< exponent n of f^n (3.12)
  double eps_xsph = 0.5;           ///< epsilon-tilde of (3.6)
  double alpha = 1.0, beta = 1.0;  ///< artificial viscosity constants (not given in the paper)
  double yield_stress = 0.03;      ///< von Mises (uniaxial) yield strength in rho0 c0^2 (Sec 7.3), if plasticity
  Box2 box;                        ///< domain for the cell list (periodic directions allowed)
  double skin_over_h = 0.2;        ///< Verlet skin of the pair list, in units of h (0: rebuild every step)
  double skin() const { return skin_over_h * h; }
  /// Longitudinal wave speed sqrt(c0^2 + 4 mu / (3 rho0)) (4.11): the signal speed of the time step.
  double longitudinal_speed() const;
};

/// Time step from the CFL-type condition dt = cfl * h / (c_L + max |v|), c_L = sqrt(c0^2 + 4mu/3rho0).
double gray_time_step(const GrayParameters& p, double cfl, double max_speed);

/// Thrown when the state stops being physical (non-finite values, vanishing density): names the step,
/// time and particle.
struct BlowUp : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class GraySolver {
 public:
  GraySolver(ElasticBody& body, const GrayParameters& params, const GrayOptions& options);

  /// One predictor-corrector step (6.14)-(6.18). Throws BlowUp if the state becomes unphysical.
  void step(double dt);

  double time() const { return time_; }
  long steps() const { return steps_; }
  const GrayParameters& params() const { return p_; }
  const GrayOptions& options() const { return o_; }
  const PairList& pairs() const { return pairs_; }

  /// Rates of the current state (evaluates the forces once): for tests and diagnostics.
  struct Rates {
    std::vector<Vec2> dv, vhat;
    std::vector<double> drho;
    std::vector<Tensor2> dS;
  };
  const Rates& evaluate_now();

  /// Cauchy stress sigma = -P I + S of particle a.
  Tensor2 stress(std::size_t a) const;
  double kinetic_energy() const;
  /// Shear part sum (m/rho) S:S/(4 mu) plus volumetric part sum m c0^2 (ln(rho/rho0) + rho0/rho - 1).
  double elastic_energy() const;
  Vec2 linear_momentum() const;
  double angular_momentum() const;

 private:
  template <class Terms>
  void evaluate(Rates& out);
  void rebuild_pairs();
  void check_state() const;
  void return_to_yield_surface();

  ElasticBody& body_;
  GrayParameters p_;
  GrayOptions o_;
  CubicSpline kernel_;
  double W_dp_;
  CellList2D cells_;
  PairList pairs_;
  void (GraySolver::*evaluate_)(Rates&) = nullptr;
  Rates r0_, r1_;
  // Scratch owned by the terms that need it: per-particle sigma/rho^2 and the artificial stress.
  std::vector<Tensor2> sigma_over_rho2_, R_;
  std::vector<double> rho_sum_;
  // Start-of-step copies for the corrector.
  std::vector<Vec2> v0_;
  std::vector<double> rho0_;
  std::vector<Tensor2> S0_;
  double time_ = 0;
  long steps_ = 0;
};

}  // namespace sph
