// The molecular-dynamics reference of Hoover, Hoover & Merritt 2004 (Sec. VI): particles of mass m joined to
// their nearest neighbours by the pair potential phi(r) = kappa (r0 - r)^2 / 2 (kappa = r0 = m = 1 in the
// paper), integrated with the same fourth-order Runge-Kutta as SPAM. With kappa = 1 on the unit triangular
// lattice the Lame constants are lambda = eta = sqrt(3/16) kappa and the density sqrt(4/3) (Sec. V), the
// continuum SPAM is given.
//
// The springs are the nearest-neighbour BONDS of the initial, undeformed lattice (pairs closer than
// bond_cutoff), kept for the whole run: a cutoff at the rest length would cut every stretched bond of a
// body under tension (the rotating hexagon) and leave it without tensile strength.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "core/lattices.hpp"
#include "core/rk4.hpp"

namespace sph {

struct MdState {
  std::vector<Vec2> x, v;
  void resize_like(const MdState& o) { x.resize(o.x.size()); v.resize(o.v.size()); }
  void set_axpy(const MdState& a, double s, const MdState& k) { vec_set_axpy(x, a.x, s, k.x); vec_set_axpy(v, a.v, s, k.v); }
  void axpy(double s, const MdState& k) { vec_axpy(x, s, k.x); vec_axpy(v, s, k.v); }
};

struct MdParams {
  double mass = 1.0, spring = 1.0, rest_length = 1.0;
  /// Pairs of the REFERENCE configuration closer than this are bonded: between the first (1) and second
  /// (sqrt 3) neighbour distances of the unit triangular lattice.
  double bond_cutoff = 1.3;
};

class MolecularDynamics {
 public:
  /// Bonds are found in `reference` (the undeformed lattice); the state may start elsewhere (sheared).
  MolecularDynamics(const std::vector<Vec2>& reference, const MdParams& p);

  /// dx/dt = v, m dv/dt = sum_bonds kappa (r0 - r) (x_i - x_j)/r. OpenMP over particles.
  void derivative(const MdState& y, MdState& dy) const;
  double potential_energy(const MdState& y) const;
  void step(MdState& y, double t, double dt);

  const std::vector<std::pair<std::size_t, std::size_t>>& bonds() const { return bonds_; }
  const MdParams& params() const { return p_; }

 private:
  MdParams p_;
  std::vector<std::pair<std::size_t, std::size_t>> bonds_;
  std::vector<std::size_t> start_, partner_;  // CSR: the bonded partners of each particle
  Rk4<MdState> rk_;
};

}  // namespace sph
