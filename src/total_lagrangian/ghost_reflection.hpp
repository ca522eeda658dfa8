// The ghost-reflection boundary closure of the 2D total-Lagrangian body (every scene's; Ismail 2009 Sections
// 2.8, 5.4 with the choices below). Per step, at time t:
//   ghost displacements: at the boundary point X_b of a ghost X_g (outward normal n), each component is
//     Dirichlet or traction. Traction components: the Taylor extension u_g = u(X_m) + (F_b - I)(X_g - X_m),
//     X_m = 2 X_b - X_g the mirror point, where the normal column of F_b solves P(F_b) n = tbar (the 2D
//     analogue of the 1D ghost with the prescribed strain) and its tangential column is the last step's
//     (values at X_b, X_m interpolated over the real particles, exact at lattice points). Dirichlet
//     components: the boundary particles take ubar, the ghosts 2 ubar(X_b) - u(X_m), then the corrective
//     factors of all boundary particles, solved together (CorrectiveFactorSet: eqs 2.39-2.42 with the coupling
//     of Section 2.9), make W u = ubar exactly there;
//   ghost stresses: rows of P of a traction component reflected oddly about the prescribed traction,
//     P_g = 2 Pbar(X_b) - P(X_m) with Pbar = P - (P n - tbar) n^T; rows of a Dirichlet component evenly,
//     P_g = P(X_m) (no acceleration normal to a held boundary).
// CHOSEN where the thesis differs or is silent: Algorithm 5.2 replaces u by its interpolant W u every step
// (lines 8-9) and sets displacement GRADIENTS equal to the traction (lines 14-17, a strain set to a stress);
// we keep u and impose the traction on P itself. Neumann conditions on P by reflection rather than by the
// secondary SPH approximation of Section 2.9.
#pragma once

#include <algorithm>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/LU>

#include "total_lagrangian/body_2d.hpp"

namespace sph {

class GhostReflection {
 public:
  explicit GhostReflection(const TlBody2D& b);
  template <class Law>
  void ghost_displacements(TlBody2D& b, double t);
  void ghost_stresses(TlBody2D& b, double t);
  void boundary_forces(TlBody2D&, int, Eigen::VectorXd&) const {}

 private:
  // The normal column a = F n of the deformation gradient at a boundary point for which P(F) n = tbar holds
  // in the traction components: Newton on (P(F(a)) n - tbar)_c = 0, F(a) = Fb + (a - Fb n) n^T.
  template <class Law>
  Vec2 traction_normal_column(const TlBody2D& b, const Tensor2& Fb, const Vec2& n, const BoundaryCondition2D& bc,
                              const Vec2& Xb, double t) const;
  Eigen::VectorXd tb_, tm_;
  Eigen::Matrix<double, Eigen::Dynamic, 4> Pb_, Pm_;  // P (or the gradient) interpolated at X_b and X_m, per ghost
  Eigen::Matrix<double, Eigen::Dynamic, 2> Um_;       // u interpolated at X_m, per ghost
};

template <class Law>
Vec2 GhostReflection::traction_normal_column(const TlBody2D& b, const Tensor2& Fb, const Vec2& n,
                                             const BoundaryCondition2D& bc, const Vec2& Xb, double t) const {
  // Unknown: a = F n (the derivative along the normal), for the traction components only; the others keep
  // the value of the last step.
  Vec2 a = Fb * n;
  int free_c[2], nf = 0;
  for (int c = 0; c < 2; ++c) if (!bc.dirichlet[c]) free_c[nf++] = c;
  if (nf == 0) return a;
  const Vec2 tbar(bc.dirichlet[0] ? 0.0 : bc.value[0](Xb, t), bc.dirichlet[1] ? 0.0 : bc.value[1](Xb, t));
  const double scale = std::abs(tbar.x()) + std::abs(tbar.y()) + b.cfg.lame.mu;
  auto residual = [&](const Vec2& aa) {
    const Tensor2 F = Fb + (aa - Fb * n) * n.transpose();
    return Vec2(Law::P(b.cfg.lame, F) * n - tbar);
  };
  for (int it = 0; it < 12; ++it) {
    const Vec2 r = residual(a);
    double rn = 0;
    for (int i = 0; i < nf; ++i) rn = std::max(rn, std::abs(r[free_c[i]]));
    if (!std::isfinite(rn)) return Fb * n;
    if (rn < 1e-12 * scale) break;
    Tensor2 J = Tensor2::Identity();
    for (int j = 0; j < nf; ++j) {
      Vec2 ap = a;
      const double e = 1e-7 * (1.0 + std::abs(a[free_c[j]]));
      ap[free_c[j]] += e;
      const Vec2 rp = residual(ap);
      for (int i = 0; i < nf; ++i) J(i, j) = (rp[free_c[i]] - r[free_c[i]]) / e;
    }
    Vec2 rr(r[free_c[0]], nf > 1 ? r[free_c[1]] : 0.0);
    if (nf == 1) { J(0, 1) = J(1, 0) = 0; J(1, 1) = 1; }
    const Vec2 da = J.fullPivLu().solve(rr);
    for (int i = 0; i < nf; ++i) a[free_c[i]] -= da[i];
  }
  return a;
}

template <class Law>
void GhostReflection::ghost_displacements(TlBody2D& b, double t) {
  b.boundary.pin_dirichlet(b.u, b.all, t);
  const int nr = b.nr, ng = b.ng;
  if (ng > 0) {
    // An extension with the lagged gradient alone feeds the boundary gradient back to itself with gain ~1
    // (a neutral mode that grows at loaded edges): hence the traction solve for the normal column.
    const TlBoundary2D& bd = b.boundary;
    Um_.col(0).noalias() = bd.Im * b.u[0];
    Um_.col(1).noalias() = bd.Im * b.u[1];
    for (int k = 0; k < 4; ++k) {
      tb_.noalias() = bd.Ib * b.g[k];
      Pb_.col(k) = tb_;
    }
#pragma omp parallel for schedule(static) if (ng > 5000)
    for (int k = 0; k < ng; ++k) {
      const auto& bp = bd.points[k];
      const auto& bc = bd.conditions[bp.condition];
      const Vec2 Xg = b.all[nr + k], d = Xg - (2.0 * bp.Xb - Xg);
      Tensor2 Fb;
      Fb << 1.0 + Pb_(k, 0), Pb_(k, 1), Pb_(k, 2), 1.0 + Pb_(k, 3);
      Vec2 ext = Vec2::Zero();
      if (!bc.dirichlet[0] || !bc.dirichlet[1]) {
        const Vec2 a = traction_normal_column<Law>(b, Fb, bp.n, bc, bp.Xb, t);
        const Tensor2 F = Fb + (a - Fb * bp.n) * bp.n.transpose();
        ext = (F - Tensor2::Identity()) * d;
      }
      for (int c = 0; c < 2; ++c)
        b.u[c][nr + k] = bc.dirichlet[c] ? 2.0 * bc.value[c](bp.Xb, t) - Um_(k, c) : Um_(k, c) + ext[c];
    }
  }
  b.boundary.correct_dirichlet(b.u);
}

}  // namespace sph
