// The updated-Lagrangian SPH scheme for elastic solids of Gray, Monaghan & Swift 2001 (Sections 2, 3, 6):
//   acceleration (3.1) with the artificial stress (3.12)-(3.14) in principal axes (6.1)-(6.9),
//   XSPH velocity (3.6) used for positions, density and velocity gradients,
//   continuity (3.8) or summation density, EOS (2.7), Hooke deviatoric stress rate (2.3)-(2.5) with the
//   velocity gradient (3.10), Monaghan's artificial viscosity (the terms: pair_terms.hpp; their loop:
//   pair_loop.hpp), and the predictor-corrector leapfrog (6.14)-(6.18) with two force evaluations per step
//   (core/predictor_corrector.hpp). Optional
//   perfectly plastic von Mises yield (Section 7.3): a radial return of S after each stress update, a
//   separate pass that only runs if enabled.
// Particle kinds (elastic_body.hpp): Free particles move with the forces (and the XSPH velocity), Fixed ones
//   stay, Driven ones follow their prescribed acceleration exactly; all interact through the same SPH sums,
//   so contact between bodies (the colliding rings) is nothing but those sums.
// The solver works on the scene's body (held by reference) and offers the solver contract of
// core/run_loop.hpp.
#pragma once

#include <cstddef>
#include <vector>

#include "core/blow_up.hpp"
#include "core/kernels.hpp"
#include "core/neighbours.hpp"
#include "core/pair_list.hpp"
#include "updated_lagrangian/elastic_body.hpp"
#include "updated_lagrangian/pair_loop.hpp"
#include "updated_lagrangian/parameters.hpp"

namespace sph {

class GraySolver {
 public:
  using Rates = GrayRates;
  GraySolver(ElasticBody& body, const GrayParameters& params, const GrayOptions& options);

  /// One predictor-corrector step (6.14)-(6.18). Throws BlowUp if the state becomes unphysical.
  void step(double dt);
  double time() const { return time_; }
  long steps() const { return steps_; }

  const GrayParameters& params() const { return p_; }
  const GrayOptions& options() const { return o_; }
  const PairList& pairs() const { return pairs_; }
  double h() const { return h_; }
  /// dt = cfl h / (c_L + max_speed) for this body (parameters.hpp).
  double time_step(double max_speed) const { return gray_time_step(p_, body_.dp, max_speed); }

  /// Rates of the current state (evaluates the forces once): for tests and diagnostics.
  const Rates& evaluate_now();

  // The particles, as every solver offers them (diagnostics, snapshots).
  std::size_t size() const { return body_.size(); }
  double mass(std::size_t a) const { return body_.m[a]; }
  const Vec2& position(std::size_t a) const { return body_.x[a]; }
  const Vec2& velocity(std::size_t a) const { return body_.v[a]; }
  double density(std::size_t a) const { return body_.rho[a]; }
  /// Cauchy stress sigma = -P I + S of particle a.
  Tensor2 stress(std::size_t a) const;
  /// Shear part sum (m/rho) (S:S + S_zz^2)/(4 mu), S_zz = -tr S, plus volumetric part
  /// sum m c0^2 (ln(rho/rho0) + rho0/rho - 1).
  double elastic_energy() const;
  /// What makes d(kinetic + elastic)/dt differ from zero at the current state (zero for a term that is off):
  /// - artificial_stress, viscosity: sum_a m_a v_a . (the term's acceleration of a), for R_ab f^n (3.12) and
  ///   Monaghan's viscosity, which have no counterpart in elastic_energy();
  /// - xsph: sum_a m_a (v_a - vhat_a) . (the stress term's acceleration of a): the density and stress rates
  ///   are those of the XSPH velocity vhat (3.6), so the elastic energy gains the stress power of vhat, and
  ///   the kinetic energy loses that of v.
  /// What is left is the stress power's own mismatch (the pair weights m_b / rho_a^2 against V_b / rho_a of
  /// the velocity gradient, the volume change of the shear energy): of the order of the density changes.
  /// A diagnostic pass over the pairs (allocates), outside the step; continuity density assumed.
  struct PowerBudget { double artificial_stress = 0, viscosity = 0, xsph = 0; };
  PowerBudget power_budget() const;

 private:
  using Evaluate = void (*)(ElasticBody&, const GrayParameters&, const CubicSpline&, double, double, const PairList&,
                            GrayScratch&, GrayRates&);
  void rebuild_pairs();
  void check_state() const;
  void return_to_yield_surface();

  ElasticBody& body_;
  GrayParameters p_;
  GrayOptions o_;
  CubicSpline kernel_;
  double h_, W_dp_;
  CellList2D cells_;
  PairList pairs_;
  Evaluate evaluate_ = nullptr;
  Rates r0_, r1_;
  GrayScratch scratch_;
  double time_ = 0;
  long steps_ = 0;
};

}  // namespace sph
