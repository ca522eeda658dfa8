// The "SPH matrices" of Ismail 2009 (Section 2.6; appended paper eqs 8-10), built SPARSE in the reference
// configuration: row p holds the neighbours q of particle p (|x_p - x_q| < support h), so N x (neighbours)
// entries instead of the thesis's dense N x N (which limited it to 21 x 21 particles, Section 5.4.4).
//
//   W_pq = W(x_p - x_q, h) dV_q                 <f>_p   = (W f)_p      eq (2.24) / (4)
//   X_pq = dW(x_p - x_q, h)/dx_p,1 dV_q         <f_,1>_p = (X f)_p     eq (2.25) / (5), (10)
//   Y_pq = dW(x_p - x_q, h)/dx_p,2 dV_q         <f_,2>_p = (Y f)_p     eq (5.9)
//
// As printed (no f_p subtracted), so the row sums of X are zero only on a symmetric lattice; ghost particles
// supply the missing half of the cover at a boundary (Section 2.8.1). Rows are stored row-major so that a
// mat-vec is one parallel pass over rows (OpenMP). The updated Lagrangian variant (Section 4.7.2) keeps the
// pattern built with a margin and recomputes the values in place from current positions: no allocation.
#pragma once

#include <Eigen/Sparse>
#include <functional>
#include <string>
#include <vector>

#include "core/lattices.hpp"

namespace sph {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

/// A cover function of run-time name bound to a smoothing length: W(r) and dW/dr(r), support radius.
/// Built once (the normalisation quadrature runs once), then cheap to call.
struct KernelFn {
  std::string name;
  int dim = 1;
  double h = 1.0;
  double radius = 1.0;  ///< support radius = support() * h
  std::function<double(double)> W, dWdr;
};
KernelFn make_kernel_fn(const std::string& name, int dim, double h);

struct SphMatrices1D {
  SparseMatrix W, X;
};
struct SphMatrices2D {
  SparseMatrix W, X, Y;
};

/// W and X for particles at x with volumes dV. The pattern holds every pair with |x_p - x_q| <
/// pattern_factor * radius (>= 1; > 1 only for the updated Lagrangian variant, whose neighbours may move
/// apart); entries beyond the support are stored as zeros. O(N log N) (sorted sweep).
SphMatrices1D build_sph_matrices_1d(const KernelFn& k, const std::vector<double>& x, const std::vector<double>& dV,
                                    double pattern_factor = 1.0);
/// Recomputes the values of m (pattern fixed) for current positions x: updated Lagrangian, Section 4.7.2.
void update_sph_matrices_1d(SphMatrices1D& m, const KernelFn& k, const std::vector<double>& x,
                            const std::vector<double>& dV);

/// W, X and Y for 2D particles (CellList2D neighbour search: O(N)).
SphMatrices2D build_sph_matrices_2d(const KernelFn& k, const std::vector<Vec2>& x, const std::vector<double>& dV);

/// y = A v, rows in parallel (OpenMP); y must already have A.rows() entries (no allocation).
void spmv(const SparseMatrix& A, const Eigen::VectorXd& v, Eigen::VectorXd& y);

}  // namespace sph
