#include "total_lagrangian/variational_closure.hpp"

namespace sph {

VariationalClosure::VariationalClosure(const TlBody2D& b) {
  const int n = b.nr + b.ng;
  ag_ = Eigen::VectorXd::Zero(b.ng);
  Um_.resize(b.ng, 2);
  Ub_.resize(b.ng, 2);
  if (b.ng == 0) return;
  const TlBoundary2D& bd = b.boundary;
  for (int c = 0; c < 2; ++c) {
    // Row g of E: 2 Ib_g - Im_g (traction component) or -Im_g (Dirichlet: the prescribed part is affine).
    std::vector<Eigen::Triplet<double, int>> tr;
    for (int k = 0; k < b.ng; ++k) {
      const bool dir = bd.condition_of_ghost(k).dirichlet[c];
      if (!dir)
        for (SparseMatrix::InnerIterator it(bd.Ib, k); it; ++it) tr.emplace_back(static_cast<int>(it.col()), k, 2.0 * it.value());
      for (SparseMatrix::InnerIterator it(bd.Im, k); it; ++it) tr.emplace_back(static_cast<int>(it.col()), k, -it.value());
    }
    Et_[c].resize(n, b.ng);
    Et_[c].setFromTriplets(tr.begin(), tr.end());
    Et_[c].makeCompressed();
  }
}

void VariationalClosure::extend(TlBody2D& b, double t) {
  b.boundary.pin_dirichlet(b.u, b.all, t);
  const int nr = b.nr, ng = b.ng;
  if (ng > 0) {
    const TlBoundary2D& bd = b.boundary;
    Um_.col(0).noalias() = bd.Im * b.u[0];
    Um_.col(1).noalias() = bd.Im * b.u[1];
    Ub_.col(0).noalias() = bd.Ib * b.u[0];
    Ub_.col(1).noalias() = bd.Ib * b.u[1];
#pragma omp parallel for schedule(static) if (ng > 5000)
    for (int k = 0; k < ng; ++k) {
      const auto& bp = bd.points[k];
      const auto& bc = bd.conditions[bp.condition];
      for (int c = 0; c < 2; ++c)
        b.u[c][nr + k] = bc.dirichlet[c] ? 2.0 * bc.value[c](bp.Xb, t) - Um_(k, c) : 2.0 * Ub_(k, c) - Um_(k, c);
    }
  }
  b.boundary.correct_dirichlet(b.u);
}

void VariationalClosure::boundary_forces(TlBody2D& b, int c, Eigen::VectorXd& a) {
  if (b.ng > 0) {
    ag_ = a.tail(b.ng);
    b.tmp.noalias() = Et_[c] * ag_;
    a.head(b.nr) += b.tmp.head(b.nr);
  }
  const double dV = b.cfg.ps * b.cfg.ps;
  for (const auto& [i, cond, dA] : b.cfg.real_on_traction)
    if (!b.boundary.conditions[cond].dirichlet[c]) a[i] += b.boundary.conditions[cond].value[c](b.all[i], b.t) * dA / dV;
}

}  // namespace sph
