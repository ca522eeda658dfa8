#include "total_lagrangian/ghost_reflection.hpp"

namespace sph {

GhostReflection::GhostReflection(const TlBody2D& b) {
  tb_ = Eigen::VectorXd::Zero(b.ng);
  tm_ = Eigen::VectorXd::Zero(b.ng);
  Pb_.resize(b.ng, 4);
  Pm_.resize(b.ng, 4);
  Um_.resize(b.ng, 2);
}

void GhostReflection::ghost_stresses(TlBody2D& b, double t) {
  if (b.ng == 0) return;
  const TlBoundary2D& bd = b.boundary;
  for (int k = 0; k < 4; ++k) {
    tb_.noalias() = bd.Ib * b.P[k];
    tm_.noalias() = bd.Im * b.P[k];
    Pb_.col(k) = tb_;
    Pm_.col(k) = tm_;
  }
  for (int g = 0; g < b.ng; ++g) {
    const auto& bp = bd.points[g];
    const auto& bc = bd.conditions[bp.condition];
    for (int c = 0; c < 2; ++c) {  // row c of P: (P_c1, P_c2) = columns 2c, 2c + 1
      Vec2 rb(Pb_(g, 2 * c), Pb_(g, 2 * c + 1)), rm(Pm_(g, 2 * c), Pm_(g, 2 * c + 1)), rg;
      if (bc.dirichlet[c]) {
        rg = rm;
      } else {
        const double tbar = bc.value[c](bp.Xb, t);
        const Vec2 rbar = rb - (rb.dot(bp.n) - tbar) * bp.n;
        rg = 2.0 * rbar - rm;
      }
      b.P[2 * c][b.nr + g] = rg.x();
      b.P[2 * c + 1][b.nr + g] = rg.y();
    }
  }
}

}  // namespace sph
