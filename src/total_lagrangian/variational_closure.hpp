// The energy-consistent ("variational") boundary closure of the 2D total-Lagrangian body: traction components
// of the ghosts extend u linearly, u_g = 2 u(X_b) - u(X_m) (a linear map E of the real values; Dirichlet
// components 2 ubar - u(X_m)), stresses are zero at the ghosts, the ghost rows of Div P are returned to the
// real particles by E^T and tractions enter as boundary forces tbar dA. Then the semi-discrete force is minus
// the gradient of sum psi(F) dV: no mode can gain energy from the boundary (the reflection closure feeds a
// particle-scale sawtooth at free edges that grows over thousands of steps). It is less accurate near
// boundaries (the boundary forces and the ghost rows land on the first layers of particles: the sheet with a
// hole's stress comes out 30% low at 201 per side), so every scene uses the reflection closure; this one is
// kept for that comparison (--variational of the hole drivers).
#pragma once

#include <Eigen/Core>

#include "total_lagrangian/body_2d.hpp"

namespace sph {

class VariationalClosure {
 public:
  explicit VariationalClosure(const TlBody2D& b);
  template <class Law>
  void ghost_displacements(TlBody2D& b, double t);
  void ghost_stresses(TlBody2D&, double) const {}  // zero at the ghosts
  /// Adds E^T (ghost rows of a) and the boundary tractions tbar dA / dV to the real rows of component c.
  void boundary_forces(TlBody2D& b, int c, Eigen::VectorXd& a);

 private:
  void extend(TlBody2D& b, double t);
  SparseMatrix Et_[2];  // E^T (all x ghost) per component
  Eigen::VectorXd ag_;
  Eigen::Matrix<double, Eigen::Dynamic, 2> Um_, Ub_;  // u interpolated at X_m and X_b, per ghost
};

template <class Law>
void VariationalClosure::ghost_displacements(TlBody2D& b, double t) {
  extend(b, t);  // the extension does not involve the law
}

}  // namespace sph
