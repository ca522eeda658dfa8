// The boundary of a 2D total-Lagrangian body (Ismail 2009 Sections 2.8-2.9, 5.4): the conditions per boundary
// piece, the boundary point each ghost mirrors through, the interpolation of the real particles' fields at
// those points and at the mirror points, and the Dirichlet corrections. What a closure (ghost_reflection.hpp,
// variational_closure.hpp) does with the ghosts is the closure's; this holds what every closure shares.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "core/types.hpp"
#include "total_lagrangian/boundary_correction.hpp"
#include "total_lagrangian/sph_matrices.hpp"

namespace sph {

/// The boundary condition at a boundary point: per component, Dirichlet (value = displacement) or traction
/// (value = traction component t_c = (P n)_c in the reference configuration).
struct BoundaryCondition2D {
  using Value = std::function<double(const Vec2& X, double t)>;
  bool dirichlet[2] = {false, false};
  Value value[2] = {[](const Vec2&, double) { return 0.0; }, [](const Vec2&, double) { return 0.0; }};
};

/// Component 0 Dirichlet (d0) or traction with value v0, component 1 likewise.
BoundaryCondition2D boundary_condition(bool d0, BoundaryCondition2D::Value v0, bool d1, BoundaryCondition2D::Value v1);

/// Where a ghost (or a real boundary particle) meets the boundary: nearest boundary point, outward normal,
/// index into the conditions.
struct BoundaryPoint2D {
  Vec2 Xb, n;
  int condition = 0;
};

/// The ghosts' boundary: built once by TlSolver2D from its configuration.
struct TlBoundary2D {
  std::vector<BoundaryCondition2D> conditions;
  std::vector<BoundaryPoint2D> points;     ///< per ghost
  SparseMatrix Ib, Im;                     ///< per ghost: interpolation at X_b and at the mirror point X_m
  std::unique_ptr<CorrectiveFactorSet> dirichlet[2];  ///< per component: the Dirichlet boundary particles
  std::vector<int> dirichlet_condition[2];            ///< the condition of each of them
  Eigen::VectorXd dirichlet_target[2];

  const BoundaryCondition2D& condition_of_ghost(int k) const { return conditions[points[k].condition]; }
  /// Boundary particles of a Dirichlet component hold the prescribed value at time t.
  void pin_dirichlet(Eigen::VectorXd (&u)[2], const std::vector<Vec2>& X, double t);
  /// The corrective factors on the ghosts that make the SPH interpolant equal the prescribed values at the
  /// Dirichlet boundary particles (after pin_dirichlet).
  void correct_dirichlet(Eigen::VectorXd (&u)[2]);
};

/// Interpolation rows over the real particles [0, nr) of `all` for query points Y: weight 1 on a real particle
/// that sits at the point (exact mirrors on a lattice), else Shepard weights W(|Y - X_q|) / sum W.
template <class K>
SparseMatrix interpolation_rows(const std::vector<Vec2>& all, int nr, const std::vector<Vec2>& Y, const K& k, double ps) {
  std::vector<Vec2> pts(all.begin(), all.begin() + nr);
  pts.insert(pts.end(), Y.begin(), Y.end());
  Box2 box = bounding_box(pts);
  box.xmax += k.radius; box.ymax += k.radius;
  CellList2D cells(box, k.radius);
  cells.build(pts);
  std::vector<Eigen::Triplet<double, int>> trip;
  for (std::size_t r = 0; r < Y.size(); ++r) {
    const std::size_t qi = nr + r;
    int exact = -1;
    double sw = 0;
    std::vector<std::pair<int, double>> w;
    cells.for_each_neighbour(pts, qi, k.radius, [&](std::size_t j, const Vec2&, double dist) {
      if (static_cast<int>(j) >= nr) return;
      if (dist < 1e-6 * ps) exact = static_cast<int>(j);
      const double wj = k.W(dist);
      w.emplace_back(static_cast<int>(j), wj);
      sw += wj;
    });
    if (exact >= 0) { trip.emplace_back(static_cast<int>(r), exact, 1.0); continue; }
    if (!(sw > 0)) throw std::invalid_argument("TlSolver2D: a ghost's mirror point has no real particle within a cover");
    for (const auto& [j, wj] : w) trip.emplace_back(static_cast<int>(r), j, wj / sw);
  }
  SparseMatrix I(static_cast<int>(Y.size()), static_cast<int>(all.size()));
  I.setFromTriplets(trip.begin(), trip.end());
  I.makeCompressed();
  return I;
}

}  // namespace sph
