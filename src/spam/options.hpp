// The algorithm choices of smooth-particle applied mechanics (SPAM) as listed by Hoover, Hoover & Merritt
// 2004, Sec. IX, plus the chain-rule continuity equation of Sec. VI:
//   density      summed, rho_i = m sum_j w_ij, or integrated from the continuity equation (Sec. II);
//   advection    dr/dt = v, the Shepard average <v> or Monaghan's <v>_M with arithmetic or geometric
//                rho_ij (Sec. IV);
//   chain_rule   continuity with the averaged velocities, drho_i/dt = m sum <v_i - v_j> . grad_i w_ij (Sec. VI);
//   torque       none, scaling of the pair torques Ldot_ij or the particle torques Ldot_i (Sec. VIII), or
//                Gauss's principle with the multipliers alpha, beta (Sec. VII);
//   viscosity    a von Neumann-Richtmyer viscous pressure (Sec. IX (ii)), off in all the paper's figures;
//   closest_approach  elastic reflection of the radial relative velocity of approaching pairs closer than a
//                fixed distance (Sec. IV; Sec. IX (i)).
// SpamPolicy carries the choices as compile-time constants so a term that is off is not compiled in;
// SpamOptions is the run-time description that make_spam (spam_simulation.cpp) maps onto a policy.
#pragma once

#include <cmath>
#include <string>

#include "core/neighbours.hpp"

namespace sph {

enum class SpamDensity { Summation, Continuity };
enum class SpamAdvection { Velocity, Shepard, MonaghanArithmetic, MonaghanGeometric };
enum class SpamTorque { None, PairScaling, ParticleScaling, Gauss };

template <SpamDensity D, SpamAdvection A, bool ChainRule, SpamTorque T, bool Viscosity, bool ClosestApproach>
struct SpamPolicy {
  static constexpr SpamDensity density = D;
  static constexpr SpamAdvection advection = A;
  static constexpr bool chain_rule = ChainRule;
  static constexpr SpamTorque torque = T;
  static constexpr bool viscosity = Viscosity;
  static constexpr bool closest_approach = ClosestApproach;
  static constexpr bool averaged = A != SpamAdvection::Velocity;
  static constexpr bool monaghan = A == SpamAdvection::MonaghanArithmetic || A == SpamAdvection::MonaghanGeometric;
  static constexpr bool torque_scaling = T == SpamTorque::PairScaling || T == SpamTorque::ParticleScaling;
  static_assert(!ChainRule || (D == SpamDensity::Continuity && A != SpamAdvection::Velocity),
                "the chain-rule continuity equation needs continuity densities and averaged velocities");
};

struct SpamOptions {
  SpamDensity density = SpamDensity::Continuity;
  SpamAdvection advection = SpamAdvection::Velocity;
  bool chain_rule = false;
  SpamTorque torque = SpamTorque::None;
  bool viscosity = false;
  bool closest_approach = false;
  /// e.g. "cont/monaghan_arith/chain/pair_torque/visc/approach" (only the parts that are on after the first two).
  std::string label() const;
};

std::string to_string(SpamDensity d);      // sum, cont
std::string to_string(SpamAdvection a);    // v, shepard, monaghan_arith, monaghan_geom
std::string to_string(SpamTorque t);       // none, pair_torque, particle_torque, gauss
SpamDensity spam_density_from_string(const std::string& s);
SpamAdvection spam_advection_from_string(const std::string& s);
SpamTorque spam_torque_from_string(const std::string& s);

/// Physical and numerical parameters (Hoover et al. 2004, Secs. V, VI, VIII).
struct SpamParams {
  double mass = 1.0;                       // m = 1
  double h = 3.0;                          // Lucy's range, three lattice spacings (Sec. VIII)
  double lambda = std::sqrt(3.0 / 16.0);   // Lame constants of the nearest-neighbour spring lattice (Sec. V)
  double eta = std::sqrt(3.0 / 16.0);
  double viscosity_coefficient = 2.0;      // CHOSEN: von Neumann-Richtmyer q = rho (c dx)^2 (div v)^2, c = 2
  double viscosity_length = 1.0;           // dx = the lattice spacing
  double closest_distance = 0.7;           // CHOSEN: 70% of the lattice spacing
  double gauss_floor = 1e-12;              // Gauss multipliers off while D < floor * m R^2 (rigid rotation)
  double skin_over_h = 0.2;                // Verlet skin of the pair list / h (as Gray's scheme; 0: search every evaluation)
  Box2 box;                                // cell-list box; periodic flags make a periodic crystal
};

}  // namespace sph
