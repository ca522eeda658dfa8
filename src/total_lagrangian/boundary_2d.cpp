#include "total_lagrangian/boundary_2d.hpp"

namespace sph {

BoundaryCondition2D boundary_condition(bool d0, BoundaryCondition2D::Value v0, bool d1, BoundaryCondition2D::Value v1) {
  BoundaryCondition2D c;
  c.dirichlet[0] = d0;
  c.dirichlet[1] = d1;
  c.value[0] = std::move(v0);
  c.value[1] = std::move(v1);
  return c;
}

void TlBoundary2D::pin_dirichlet(Eigen::VectorXd (&u)[2], const std::vector<Vec2>& X, double t) {
  for (int c = 0; c < 2; ++c) {
    if (!dirichlet[c]) continue;
    const auto& b = dirichlet[c]->boundary();
    for (std::size_t s = 0; s < b.size(); ++s) {
      dirichlet_target[c][s] = conditions[dirichlet_condition[c][s]].value[c](X[b[s]], t);
      u[c][b[s]] = dirichlet_target[c][s];
    }
  }
}

void TlBoundary2D::correct_dirichlet(Eigen::VectorXd (&u)[2]) {
  for (int c = 0; c < 2; ++c)
    if (dirichlet[c]) dirichlet[c]->apply(u[c], dirichlet_target[c]);
}

}  // namespace sph
