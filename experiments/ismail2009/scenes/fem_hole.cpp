#include "ismail2009/scenes/fem_hole.hpp"

#include <Eigen/LU>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace scenes {

namespace {

using V2 = Eigen::Vector2d;

/// Node (i, j): angle theta_i = (pi/2) i / n_theta, blend t_j = (j / n_r)^grading between the hole point
/// R (cos, sin) and the point of the square's edge on the same ray.
V2 node(double a, double R, int n_theta, int n_r, double grading, int i, int j) {
  const double th = 0.5 * M_PI * i / n_theta, t = std::pow(static_cast<double>(j) / n_r, grading);
  const V2 in(R * std::cos(th), R * std::sin(th));
  const V2 out = th <= 0.25 * M_PI + 1e-14 ? V2(a, a * std::tan(th)) : V2(a / std::tan(th), a);
  return (1.0 - t) * in + t * out;
}

/// The 2 x 2 Gauss points and the corners of the reference element, counter-clockwise.
const double g = 1.0 / std::sqrt(3.0);
const double gp[4][2] = {{-g, -g}, {g, -g}, {g, g}, {-g, g}};
const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

/// The structured mesh: nodes (i, j) at X[j nx + i], and the number of each free displacement component
/// (-1: held by a Dirichlet condition).
struct Mesh {
  int n_theta = 0, n_r = 0, nx = 0, ny = 0, nd = 0;
  std::vector<V2> X;
  std::vector<int> dof_of;
  // Element nodes counter-clockwise: (i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j) -- i runs with theta
  // (counter-clockwise about the hole), j outward, so this order has a positive Jacobian.
  std::array<int, 4> elem(int i, int j) const {
    return std::array<int, 4>{j * nx + i, (j + 1) * nx + i, (j + 1) * nx + i + 1, j * nx + i + 1};
  }
  int dof(const std::array<int, 4>& e, int r) const { return dof_of[2 * e[r / 2] + r % 2]; }
};

Mesh make_mesh(double a, double R, int n_theta, int n_r, double grading) {
  Mesh m;
  m.n_theta = n_theta;
  m.n_r = n_r;
  m.nx = n_theta + 1;
  m.ny = n_r + 1;
  const int nx = m.nx, ny = m.ny, nn = nx * ny;
  m.X.resize(nn);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) m.X[j * nx + i] = node(a, R, n_theta, n_r, grading, i, j);
  // Dirichlet: u_y = 0 on y = 0 (theta = 0, i = 0), u_x = 0 on x = 0 (theta = pi/2, i = n_theta).
  m.dof_of.assign(2 * nn, -1);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int n = j * nx + i;
      if (i != n_theta) m.dof_of[2 * n] = m.nd++;
      if (i != 0) m.dof_of[2 * n + 1] = m.nd++;
    }
  return m;
}

/// B matrix (3 x 8) and det J of element e at (xi, eta).
Eigen::Matrix<double, 3, 8> bmat(const Mesh& m, const std::array<int, 4>& e, double xi, double eta, double& detJ) {
  Eigen::Matrix<double, 2, 4> dN;
  for (int k = 0; k < 4; ++k) {
    dN(0, k) = 0.25 * corner[k][0] * (1 + corner[k][1] * eta);
    dN(1, k) = 0.25 * corner[k][1] * (1 + corner[k][0] * xi);
  }
  Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
  for (int k = 0; k < 4; ++k) J += dN.col(k) * m.X[e[k]].transpose();
  detJ = J.determinant();
  if (!(detJ > 0)) throw std::runtime_error("fem_hole: inverted element");
  const Eigen::Matrix<double, 2, 4> dNx = J.inverse() * dN;
  Eigen::Matrix<double, 3, 8> B = Eigen::Matrix<double, 3, 8>::Zero();
  for (int k = 0; k < 4; ++k) {
    B(0, 2 * k) = dNx(0, k);
    B(1, 2 * k + 1) = dNx(1, k);
    B(2, 2 * k) = dNx(1, k);
    B(2, 2 * k + 1) = dNx(0, k);
  }
  return B;
}

Eigen::SparseMatrix<double> stiffness(const Mesh& m, const Eigen::Matrix3d& D) {
  std::vector<Eigen::Triplet<double>> trip;
  for (int j = 0; j < m.n_r; ++j)
    for (int i = 0; i < m.n_theta; ++i) {
      const auto e = m.elem(i, j);
      Eigen::Matrix<double, 8, 8> K = Eigen::Matrix<double, 8, 8>::Zero();
      for (const auto& q : gp) {
        double dJ;
        const auto B = bmat(m, e, q[0], q[1], dJ);
        K += B.transpose() * D * B * dJ;
      }
      for (int r = 0; r < 8; ++r)
        for (int c = 0; c < 8; ++c) {
          const int dr = m.dof(e, r), dc = m.dof(e, c);
          if (dr >= 0 && dc >= 0) trip.emplace_back(dr, dc, K(r, c));
        }
    }
  Eigen::SparseMatrix<double> K(m.nd, m.nd);
  K.setFromTriplets(trip.begin(), trip.end());
  return K;
}

/// Traction s0 in x on the edge x = a: nodes j = n_r, theta <= pi/4 (i <= n_theta / 2); consistent loads.
Eigen::VectorXd edge_load(const Mesh& m, double s0) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.nd);
  for (int i = 0; i < m.n_theta / 2; ++i) {
    const int n0 = m.n_r * m.nx + i, n1 = n0 + 1;
    const double L = (m.X[n1] - m.X[n0]).norm();
    f[m.dof_of[2 * n0]] += 0.5 * s0 * L;
    f[m.dof_of[2 * n1]] += 0.5 * s0 * L;
  }
  return f;
}

/// sigma_xx at node (0, R) = node (i = n_theta, j = 0), local node 3 of element (n_theta - 1, 0): the
/// Gauss-point sigma_xx extrapolated bilinearly (Gauss point k sits at corner k / sqrt(3)).
double hole_top_sxx(const Mesh& m, const Eigen::Matrix3d& D, const Eigen::VectorXd& u) {
  const auto e = m.elem(m.n_theta - 1, 0);
  Eigen::Matrix<double, 8, 1> ue;
  for (int r = 0; r < 8; ++r) {
    const int d = m.dof(e, r);
    ue[r] = d >= 0 ? u[d] : 0.0;
  }
  double sg[4];
  for (int k = 0; k < 4; ++k) {
    double dJ;
    sg[k] = (D * bmat(m, e, gp[k][0], gp[k][1], dJ) * ue)[0];
  }
  const double xi = std::sqrt(3.0) * corner[3][0], eta = std::sqrt(3.0) * corner[3][1];
  double sxx = 0;
  for (int k = 0; k < 4; ++k) sxx += 0.25 * (1 + gp[k][0] * std::sqrt(3.0) * xi) * (1 + gp[k][1] * std::sqrt(3.0) * eta) * sg[k];
  return sxx;
}

}  // namespace

FemHoleResult fem_hole_concentration(double a, double R, int n_theta, int n_r, double grading) {
  if (n_theta < 2 || n_theta % 2 || n_r < 1 || !(R > 0) || !(a > R)) throw std::invalid_argument("fem_hole: bad mesh or geometry");
  const Mesh mesh = make_mesh(a, R, n_theta, n_r, grading);
  const double E = 1.0, nu = 0.3, s0 = 1.0;
  Eigen::Matrix3d D;
  D << 1, nu, 0, nu, 1, 0, 0, 0, 0.5 * (1 - nu);
  D *= E / (1 - nu * nu);
  const Eigen::SparseMatrix<double> K = stiffness(mesh, D);
  const Eigen::VectorXd f = edge_load(mesh, s0);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(K);
  if (solver.info() != Eigen::Success) throw std::runtime_error("fem_hole: factorisation failed");
  const Eigen::VectorXd u = solver.solve(f);
  FemHoleResult r;
  r.elements = n_theta * n_r;
  r.dofs = mesh.nd;
  r.concentration = hole_top_sxx(mesh, D, u) / s0;
  return r;
}

}  // namespace scenes
