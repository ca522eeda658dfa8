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
#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/neighbours.hpp"
#include "core/types.hpp"

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

/// W, X and Y for 2D particles (CellList2D neighbour search: O(N)). K: a bound kernel (KernelFn, or
/// BoundKernel<Kernel> of bound_kernel.hpp) with dim, radius, W(r) and dWdr(r).
template <class K>
SphMatrices2D build_sph_matrices_2d(const K& k, const std::vector<Vec2>& x, const std::vector<double>& dV);

/// Rows from which spmv runs in parallel: a 1D row holds a few entries, so below this the fork and join cost
/// more than the rows (the 1D solver's other per-step loops use it too).
inline constexpr long kParallelRows1D = 50000;
/// y = A v, rows in parallel (OpenMP); y must already have A.rows() entries (no allocation).
void spmv(const SparseMatrix& A, const Eigen::VectorXd& v, Eigen::VectorXd& y);

/// The 2D step's products in one pass over the rows each, reading the pattern X and Y share (built together,
/// build_sph_matrices_2d) once instead of once per product: g = [X u0, Y u0, X u1, Y u1] (eq 5.9) and
/// a0 = X P0 + Y P1, a1 = X P2 + Y P3 (eq 5.6). Every sum runs in the order of spmv, so the results are the
/// same bits as the separate products. Outputs must already have their sizes (no allocation).
void gradient_2d(const SphMatrices2D& m, const Eigen::VectorXd& u0, const Eigen::VectorXd& u1, Eigen::VectorXd (&g)[4]);
void divergence_2d(const SphMatrices2D& m, const Eigen::VectorXd (&P)[4], Eigen::VectorXd& a0, Eigen::VectorXd& a1);

template <class K>
SphMatrices2D build_sph_matrices_2d(const K& k, const std::vector<Vec2>& x, const std::vector<double>& dV) {
  if (x.size() != dV.size()) throw std::invalid_argument("build_sph_matrices_2d: one volume per particle");
  if (k.dim != 2) throw std::invalid_argument("build_sph_matrices_2d: kernel must be 2D");
  const int n = static_cast<int>(x.size());
  Box2 box = bounding_box(x);
  box.xmax += k.radius; box.ymax += k.radius;  // non-empty even for a single row or column
  CellList2D cells(box, k.radius);
  cells.build(x);
  // Row p's entries are found independently of every other row: fill rows in parallel into per-row lists.
  std::vector<std::vector<std::pair<int, Vec2>>> rows(n);  // (q, x_p - x_q)
#pragma omp parallel for schedule(dynamic, 64)
  for (int p = 0; p < n; ++p) {
    rows[p].emplace_back(p, Vec2::Zero());
    cells.for_each_neighbour(x, p, k.radius, [&](std::size_t q, const Vec2& d, double) {
      rows[p].emplace_back(static_cast<int>(q), d);
    });
    std::sort(rows[p].begin(), rows[p].end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  }
  SphMatrices2D m;
  for (SparseMatrix* A : {&m.W, &m.X, &m.Y}) {
    A->resize(n, n);
    Eigen::VectorXi nnz(n);
    for (int p = 0; p < n; ++p) nnz[p] = static_cast<int>(rows[p].size());
    A->reserve(nnz);
  }
  for (int p = 0; p < n; ++p) {
    for (const auto& [q, d] : rows[p]) {
      const double r = d.norm();
      const double g = r > 0 ? k.dWdr(r) / r * dV[q] : 0.0;  // grad_p W = dW/dr (x_p - x_q)/r
      m.W.insert(p, q) = k.W(r) * dV[q];
      m.X.insert(p, q) = g * d.x();
      m.Y.insert(p, q) = g * d.y();
    }
  }
  m.W.makeCompressed();
  m.X.makeCompressed();
  m.Y.makeCompressed();
  return m;
}

}  // namespace sph
