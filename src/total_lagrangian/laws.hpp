// The material laws of the total-Lagrangian bodies as types (a compile-time choice of TlSolver2D's step):
// the first Piola-Kirchhoff stress P(F) in plane strain (core/materials.hpp).
#pragma once

#include "core/materials.hpp"

namespace sph {

/// Compressible neo-Hookean, Ismail 2009 eq (3.64).
struct NeoHookeanLaw {
  static Tensor2 P(const Lame& m, const Tensor2& F) { return neo_hookean_P<2>(m, F); }
};

/// Hooke's law of the small strain of F, eq (3.54): the linear reference.
struct HookeLaw {
  static Tensor2 P(const Lame& m, const Tensor2& F) {
    return hooke_stress<2>(m, small_strain<2>(Tensor2(F - Tensor2::Identity())));
  }
};

}  // namespace sph
