// The molecular-dynamics reference of Hoover, Hoover & Merritt 2004 (Sec. VI): particles of mass m joined to
// their nearest neighbours by the pair potential phi(r) = kappa (r0 - r)^2 / 2 (kappa = r0 = m = 1 in the
// paper), integrated with the same fourth-order Runge-Kutta as SPAM. With kappa = 1 on the unit triangular
// lattice the Lame constants are lambda = eta = sqrt(3/16) kappa and the density sqrt(4/3) (Sec. V), the
// continuum SPAM is given.
//
// The springs are the nearest-neighbour BONDS of the initial, undeformed lattice (pairs closer than
// bond_cutoff), kept for the whole run: a cutoff at the rest length would cut every stretched bond of a
// body under tension (the rotating hexagon) and leave it without tensile strength. MdSolver offers the
// solver contract of core/run_loop.hpp.
#pragma once

#include <cstddef>
#include <tuple>
#include <utility>
#include <vector>

#include "core/rk4.hpp"
#include "core/types.hpp"

namespace sph {

struct MdState {
  std::vector<Vec2> x, v;
  auto fields() { return std::tie(x, v); }
  auto fields() const { return std::tie(x, v); }
};

struct MdParams {
  double mass = 1.0, spring = 1.0, rest_length = 1.0;
  /// Pairs of the REFERENCE configuration closer than this are bonded: between the first (1) and second
  /// (sqrt 3) neighbour distances of the unit triangular lattice.
  double bond_cutoff = 1.3;
};

class MdSolver {
 public:
  /// Bonds are found in `reference` (the undeformed lattice); the run starts from `initial` (which may be
  /// elsewhere: sheared).
  MdSolver(const std::vector<Vec2>& reference, const MdState& initial, const MdParams& p);

  /// dx/dt = v, m dv/dt = sum_bonds kappa (r0 - r) (x_i - x_j)/r. OpenMP over particles.
  void derivative(const MdState& y, MdState& dy) const;
  double potential_energy() const;
  /// One RK4 step; throws BlowUp when a position or velocity is no longer finite.
  void step(double dt);
  double time() const { return t_; }
  long steps() const { return steps_; }
  const MdState& state() const { return y_; }

  const std::vector<std::pair<std::size_t, std::size_t>>& bonds() const { return bonds_; }
  const MdParams& params() const { return p_; }

  // The particles, as every solver offers them (diagnostics).
  std::size_t size() const { return y_.x.size(); }
  double mass(std::size_t) const { return p_.mass; }
  const Vec2& position(std::size_t i) const { return y_.x[i]; }
  const Vec2& velocity(std::size_t i) const { return y_.v[i]; }

 private:
  MdParams p_;
  MdState y_;
  std::vector<std::pair<std::size_t, std::size_t>> bonds_;
  std::vector<std::size_t> start_, partner_;  // CSR: the bonded partners of each particle
  Rk4<MdState> rk_;
  double t_ = 0;
  long steps_ = 0;
};

}  // namespace sph
