// Zero-energy-mode ("hourglass") control of the 2D total-Lagrangian body, dimensionless gamma (after
// Ganzenmueller 2015, linearised). The plain SPH gradient does not see a particle-scale sawtooth
// (sum_q (-1)^q grad W = 0 on a lattice), so nothing resists it and boundary closures can feed it. The
// control adds, on real particle i,
//   a_i += gamma (E / rho) sum_j K_ij [ (u_j - u_i) - (G_i + G_j)/2 (X_j - X_i) ],  K_ij = W_ij dV / |X_ij|^2,
// G = F - I the SPH displacement gradient (G_j := G_i for a ghost j, whose own gradient is truncated): the
// misfit of each pair against the field the two gradients predict. It is zero for any linear field (between
// real particles also quadratic), pairwise antisymmetric between real particles (momentum kept), and
// stiffens exactly the modes the gradient cannot see. It does not cure the reflection closure's weak
// instability at loaded edges and their corners (experiments/ismail2009/ismail2009_fig5_13to5_15_hole_resolution.cpp:
// damping holds it down there). An optional pass of TlSolver2D's step: off, it is not compiled in.
#pragma once

#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "total_lagrangian/body_2d.hpp"

namespace sph {

class HourglassControl {
 public:
  HourglassControl() = default;
  /// The pair weights K_ij over the real rows of the SPH matrix W; K a bound kernel (bound_kernel.hpp).
  template <class K>
  HourglassControl(const TlBody2D& b, const K& kernel, double gamma) : gamma_(gamma) {
    std::vector<Eigen::Triplet<double, int>> tr;
    const double dV = b.cfg.ps * b.cfg.ps;
    for (int i = 0; i < b.nr; ++i)
      for (SparseMatrix::InnerIterator it(b.m.W, i); it; ++it) {
        const int j = static_cast<int>(it.col());
        if (j == i) continue;
        const double r2 = (b.all[j] - b.all[i]).squaredNorm();
        if (r2 > 0 && it.value() > 0) tr.emplace_back(i, j, kernel.W(std::sqrt(r2)) * dV / r2);
      }
    K_.resize(b.nr, b.nr + b.ng);
    K_.setFromTriplets(tr.begin(), tr.end());
    K_.makeCompressed();
    // X_j - X_i of every entry: the reference configuration does not move, so the offsets are computed once
    // instead of gathered from the positions at every step.
    offset_.resize(K_.nonZeros());
    for (int i = 0; i < b.nr; ++i)
      for (int e = K_.outerIndexPtr()[i]; e < K_.outerIndexPtr()[i + 1]; ++e) offset_[e] = b.all[K_.innerIndexPtr()[e]] - b.all[i];
  }
  /// Adds the control force of both components (before the division by rho) to a0 and a1, in one
  /// traversal of the pairs.
  void add(const TlBody2D& b, Eigen::VectorXd& a0, Eigen::VectorXd& a1) const;

 private:
  double gamma_ = 0;
  SparseMatrix K_;              // real rows x all columns
  std::vector<Vec2> offset_;    // X_j - X_i per entry of K_
};

}  // namespace sph
