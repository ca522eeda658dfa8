// A 2D total-Lagrangian body (Ismail 2009 Section 5.4): its configuration as a scene declares it, and the
// fields the step and the boundary closures share. TlSolver2D (solver_2d.hpp) builds and advances it.
#pragma once

#include <functional>
#include <tuple>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/materials.hpp"
#include "total_lagrangian/boundary_2d.hpp"
#include "total_lagrangian/sph_matrices.hpp"

namespace sph {

struct TlConfig2D {
  std::vector<Vec2> real;                 ///< real particles (reference positions)
  std::vector<Vec2> ghosts;               ///< ghost particles (within a cover of the real ones)
  double ps = 1.0;                        ///< lattice spacing; dV = ps^2
  double h_over_ps = 2.5;
  double rho = 1.0;
  enum class Law { Hooke, NeoHookean } law = Law::NeoHookean;
  Lame lame{1.0, 1.0};
  std::vector<BoundaryCondition2D> conditions;
  std::function<BoundaryPoint2D(const Vec2& Xg)> ghost_boundary;  ///< for every ghost
  /// Real particles that carry Dirichlet components: (index into real, condition index).
  std::vector<std::pair<int, int>> real_on_dirichlet;
  /// Real particles on a piece with a traction component: (index into real, condition, boundary length).
  std::vector<std::tuple<int, int, double>> real_on_traction;
  /// Optional mass-proportional damping a -= damping v (1/s); 0 = off (the pass is then not compiled in).
  double damping = 0.0;
  /// Zero-energy-mode control gamma (hourglass_2d.hpp); 0 = off, the thesis's scheme.
  double hourglass = 0.0;
  /// The boundary closure: ghost reflection (ghost_reflection.hpp, every scene's) or the energy-consistent
  /// variational closure (variational_closure.hpp, kept for the comparison).
  enum class Closure { GhostReflection, Variational } closure = Closure::GhostReflection;
  /// Ghost displacements and gradient evaluated this many times in each step, each ghost pass reading the
  /// gradient of the one before (1: the closure's one-step-lagged tangential gradient; more: towards their fixed
  /// point within the step; issue 15 b's experiment).
  int closure_passes = 1;
};

/// The fields of the body: real particles [0, nr), ghosts [nr, nr + ng) in every vector.
struct TlBody2D {
  TlConfig2D cfg;
  int nr = 0, ng = 0;
  std::vector<Vec2> all;                  ///< reference positions, real then ghosts
  SphMatrices2D m;
  TlBoundary2D boundary;
  double radius = 0;                      ///< support radius of the kernel
  Eigen::VectorXd u[2], up[2];            ///< displacement components at t_n and t_{n-1}
  Eigen::VectorXd g[4];                   ///< displacement gradient: du1/dX, du1/dY, du2/dX, du2/dY
  Eigen::VectorXd P[4];                   ///< first Piola-Kirchhoff stress P11, P12, P21, P22
  Eigen::VectorXd a[2], tmp;              ///< acceleration components, scratch
  double t = 0.0, dt_last = 0.0;
  long steps = 0;

  /// The gradient g = [X u1, Y u1, X u2, Y u2] (eq 5.9).
  void gradient() {
    gradient_2d(m, u[0], u[1], g);
  }
  Tensor2 F(int i) const {
    Tensor2 F;
    F << 1.0 + g[0][i], g[1][i], g[2][i], 1.0 + g[3][i];
    return F;
  }
};

}  // namespace sph
