// A SPAM run behind a run-time interface (Hoover, Hoover & Merritt 2004): make_spam maps SpamOptions onto the
// compile-time SpamPolicy (the only place that branches on the options) and returns a solver that advances
// with RK4 (Sec. II) and, with closest_approach, reflects the radial relative velocity of approaching pairs
// closer than closest_distance after every step (Sec. IV: "elastically reflecting the radial component of
// velocity for approaching pairs of particles at a fixed closest-approach distance"). It offers the solver
// contract of core/run_loop.hpp.
#pragma once

#include <memory>
#include <vector>

#include "spam/options.hpp"
#include "spam/state.hpp"
#include "spam/work.hpp"

namespace sph {

class SpamSolver {
 public:
  virtual ~SpamSolver() = default;
  /// One RK4 step of length dt (then the closest-approach reflections, if on). Throws BlowUp when a
  /// position or velocity is no longer finite.
  virtual void step(double dt) = 0;
  virtual double time() const = 0;
  virtual long steps() const = 0;
  virtual const SpamState& state() const = 0;
  /// The state may be edited between steps (e.g. a kick).
  virtual SpamState& state() = 0;
  /// The right-hand side at the current state (for tests and diagnostics).
  virtual void derivative(SpamState& dy) = 0;
  /// The density in use at the current state (summed, or the state's own).
  virtual void density(std::vector<double>& rho) = 0;
  /// Scratch and diagnostics of the last right-hand-side evaluation.
  virtual const SpamWork& work() const = 0;
  virtual const SpamOptions& options() const = 0;
  virtual const SpamParams& params() const = 0;
  /// Number of pair reflections made by the closest-approach rule so far.
  virtual long reflections() const = 0;

  // The particles, as every solver offers them (diagnostics). Equal masses m.
  std::size_t size() const { return state().size(); }
  double mass(std::size_t) const { return params().mass; }
  const Vec2& position(std::size_t i) const { return state().x[i]; }
  const Vec2& velocity(std::size_t i) const { return state().v[i]; }
  Tensor2 stress(std::size_t i) const;
};

/// A SPAM run from `initial` (positions, velocities, stresses, e, and rho when densities are integrated).
/// Throws std::invalid_argument for an inconsistent choice (chain rule without continuity densities or
/// without averaged velocities).
std::unique_ptr<SpamSolver> make_spam(const SpamOptions& options, const SpamParams& params, const SpamState& initial);

/// Sum over particles of sum_j w_ij with the self term, times m: the summed density (Sec. II (i)).
std::vector<double> summed_density(const std::vector<Vec2>& x, const SpamParams& params);

}  // namespace sph
