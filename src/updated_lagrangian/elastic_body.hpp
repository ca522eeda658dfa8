// The state of an updated-Lagrangian elastic body in 2D (Gray, Monaghan & Swift 2001): one array per field
// (fields.hpp), and the lattice spacing and domain the body was built on.
#pragma once

#include <cstddef>
#include <tuple>
#include <vector>

#include "core/neighbours.hpp"
#include "core/types.hpp"

namespace sph {

/// What the integrator does with a particle. Every kind carries density and stress and takes part in
/// the interactions; only Free particles are moved by the forces.
enum class Motion : unsigned char {
  Free = 0,
  Fixed = 1,   ///< does not move (clamp layers of Gray et al. 2001 Section 7.1)
  Driven = 2,  ///< moves at its prescribed constant acceleration `drive`, whatever the forces
               ///< (the end bands of the slab of Gray et al. 2001 Section 7.3): x = x0 + v0 t + drive t^2/2
};

struct ElasticBody {
  std::vector<Vec2> x, v;
  std::vector<double> m, rho;
  std::vector<Tensor2> S;        ///< deviatoric stress
  std::vector<Motion> motion;
  std::vector<Vec2> drive;       ///< prescribed acceleration of a Driven particle (zero for the others)
  double dp = 0;                 ///< spacing of the lattice the body was cut from (h = h_over_dp dp)
  Box2 box;                      ///< the domain of the neighbour search (periodic directions allowed)

  std::size_t size() const { return x.size(); }
  void add(const Vec2& pos, const Vec2& vel, double mass, double density, Motion kind = Motion::Free,
           const Vec2& acceleration = Vec2::Zero()) {
    x.push_back(pos);
    v.push_back(vel);
    m.push_back(mass);
    rho.push_back(density);
    S.push_back(Tensor2::Zero());
    motion.push_back(kind);
    drive.push_back(kind == Motion::Driven ? acceleration : Vec2::Zero());
  }
  auto fields() { return std::tie(x, v, m, rho, S, motion, drive); }
  auto fields() const { return std::tie(x, v, m, rho, S, motion, drive); }
  /// The fields the predictor-corrector integrates to first order (predictor_corrector.hpp).
  auto first_order() { return std::tie(rho, S); }
};

}  // namespace sph
