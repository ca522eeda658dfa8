// A SPAM run behind a run-time interface: make_spam maps SpamOptions onto the compile-time SpamPolicy (the
// only place that branches on the options) and returns a simulation that advances with RK4
// (Hoover, Hoover & Merritt 2004, Sec. II) and, with closest_approach, reflects the radial relative velocity
// of approaching pairs closer than closest_distance after every step (Sec. IV: "elastically reflecting the
// radial component of velocity for approaching pairs of particles at a fixed closest-approach distance").
#pragma once

#include <memory>
#include <vector>

#include "spam/work.hpp"
#include "spam/options.hpp"
#include "spam/state.hpp"

namespace sph {

class SpamSimulation {
 public:
  virtual ~SpamSimulation() = default;
  /// One RK4 step of length dt (then the closest-approach reflections, if on).
  virtual void step(double dt) = 0;
  virtual double time() const = 0;
  virtual const SpamState& state() const = 0;
  /// The state may be edited between steps (e.g. a kick).
  virtual SpamState& state() = 0;
  /// The right-hand side at the current state (for tests and diagnostics).
  virtual void derivative(SpamState& dy) = 0;
  /// The density in use at the current state.
  virtual void density(std::vector<double>& rho) = 0;
  /// Scratch and diagnostics of the last right-hand-side evaluation.
  virtual const SpamWork& work() const = 0;
  virtual const SpamOptions& options() const = 0;
  /// Number of pair reflections made by the closest-approach rule so far.
  virtual long reflections() const = 0;
};

/// A SPAM run from `initial` (positions, velocities, stresses, e, and rho when densities are integrated).
/// Throws std::invalid_argument for an inconsistent choice (chain rule without continuity densities or
/// without averaged velocities).
std::unique_ptr<SpamSimulation> make_spam(const SpamOptions& options, const SpamParams& params, const SpamState& initial);

/// Sum over particles of sum_j w_ij with the self term, times m: the summed density (Sec. II (i)).
std::vector<double> summed_density(const std::vector<Vec2>& x, const SpamParams& params);

}  // namespace sph
