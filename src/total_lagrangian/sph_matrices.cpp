#include "total_lagrangian/sph_matrices.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/kernels.hpp"
#include "core/neighbours.hpp"

namespace sph {

KernelFn make_kernel_fn(const std::string& name, int dim, double h) {
  if (!(h > 0)) throw std::invalid_argument("make_kernel_fn: h must be positive");
  return with_kernel(name, dim, [&](auto kernel) {
    KernelFn k;
    k.name = name;
    k.dim = dim;
    k.h = h;
    k.radius = kernel.support() * h;
    k.W = [kernel, h](double r) { return kernel.W(r, h); };
    k.dWdr = [kernel, h](double r) { return kernel.dWdr(r, h); };
    return k;
  });
}

SphMatrices1D build_sph_matrices_1d(const KernelFn& k, const std::vector<double>& x, const std::vector<double>& dV,
                                    double pattern_factor) {
  if (x.size() != dV.size()) throw std::invalid_argument("build_sph_matrices_1d: one volume per particle");
  if (pattern_factor < 1.0) throw std::invalid_argument("build_sph_matrices_1d: pattern_factor must be >= 1");
  const int n = static_cast<int>(x.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return x[a] < x[b]; });
  const double R = pattern_factor * k.radius;
  std::vector<Eigen::Triplet<double, int>> tw, tx;
  for (int a = 0; a < n; ++a) {
    const int p = order[a];
    for (int dir : {-1, 1}) {
      for (int b = a + (dir < 0 ? 0 : 1); b >= 0 && b < n; b += dir) {
        const int q = order[b];
        const double d = x[p] - x[q];
        if (std::abs(d) >= R) break;
        const double r = std::abs(d);
        const bool in = r < k.radius;
        tw.emplace_back(p, q, in ? k.W(r) * dV[q] : 0.0);
        tx.emplace_back(p, q, in && r > 0 ? k.dWdr(r) * (d > 0 ? 1.0 : -1.0) * dV[q] : 0.0);
      }
    }
  }
  SphMatrices1D m;
  m.W.resize(n, n);
  m.X.resize(n, n);
  m.W.setFromTriplets(tw.begin(), tw.end());
  m.X.setFromTriplets(tx.begin(), tx.end());
  m.W.makeCompressed();
  m.X.makeCompressed();
  return m;
}

void update_sph_matrices_1d(SphMatrices1D& m, const KernelFn& k, const std::vector<double>& x,
                            const std::vector<double>& dV) {
  const int n = static_cast<int>(m.W.rows());
#pragma omp parallel for schedule(static)
  for (int p = 0; p < n; ++p) {
    SparseMatrix::InnerIterator iw(m.W, p);
    SparseMatrix::InnerIterator ix(m.X, p);
    for (; iw; ++iw, ++ix) {
      const int q = iw.col();
      const double d = x[p] - x[q], r = std::abs(d);
      const bool in = r < k.radius;
      iw.valueRef() = in ? k.W(r) * dV[q] : 0.0;
      ix.valueRef() = in && r > 0 ? k.dWdr(r) * (d > 0 ? 1.0 : -1.0) * dV[q] : 0.0;
    }
  }
}

void spmv(const SparseMatrix& A, const Eigen::VectorXd& v, Eigen::VectorXd& y) {
  const int n = static_cast<int>(A.rows());
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const double* val = A.valuePtr();
#pragma omp parallel for schedule(static) if (n > kParallelRows1D)
  for (int p = 0; p < n; ++p) {
    double s = 0.0;
    for (int k = outer[p]; k < outer[p + 1]; ++k) s += val[k] * v[inner[k]];
    y[p] = s;
  }
}

namespace {
// Rows in parallel from this size: a row of the 2D matrices holds ~20-40 entries, so a few thousand rows
// outweigh the fork/join.
constexpr int kParallelRows2D = 2000;

// Calls row(p, begin, end, inner, vx, vy) for every row p of the pattern X and Y share, rows in parallel.
template <class Row>
void for_each_row_2d(const SphMatrices2D& m, Row&& row) {
  if (m.X.nonZeros() != m.Y.nonZeros() || m.X.rows() != m.Y.rows() || !m.X.isCompressed() || !m.Y.isCompressed())
    throw std::invalid_argument("2D SPH matrices: X and Y must share one compressed pattern (build_sph_matrices_2d)");
  const int n = static_cast<int>(m.X.rows());
  const int* outer = m.X.outerIndexPtr();
  const int* inner = m.X.innerIndexPtr();
  const double* vx = m.X.valuePtr();
  const double* vy = m.Y.valuePtr();
#pragma omp parallel for schedule(static) if (n > kParallelRows2D)
  for (int p = 0; p < n; ++p) row(p, outer[p], outer[p + 1], inner, vx, vy);
}
}  // namespace

void gradient_2d(const SphMatrices2D& m, const Eigen::VectorXd& u0, const Eigen::VectorXd& u1, Eigen::VectorXd (&g)[4]) {
  for_each_row_2d(m, [&](int p, int begin, int end, const int* inner, const double* vx, const double* vy) {
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    for (int k = begin; k < end; ++k) {
      const int q = inner[k];
      s0 += vx[k] * u0[q];
      s1 += vy[k] * u0[q];
      s2 += vx[k] * u1[q];
      s3 += vy[k] * u1[q];
    }
    g[0][p] = s0; g[1][p] = s1; g[2][p] = s2; g[3][p] = s3;
  });
}

void divergence_2d(const SphMatrices2D& m, const Eigen::VectorXd (&P)[4], Eigen::VectorXd& a0, Eigen::VectorXd& a1) {
  for_each_row_2d(m, [&](int p, int begin, int end, const int* inner, const double* vx, const double* vy) {
    double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
    for (int k = begin; k < end; ++k) {
      const int q = inner[k];
      x0 += vx[k] * P[0][q];
      y0 += vy[k] * P[1][q];
      x1 += vx[k] * P[2][q];
      y1 += vy[k] * P[3][q];
    }
    a0[p] = x0 + y0;
    a1[p] = x1 + y1;
  });
}

}  // namespace sph
