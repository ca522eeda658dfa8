// Boundary conditions of Ismail 2009 Sections 2.8.3 and 2.9.
//
// 1D corrective factor (eqs 2.39-2.45): the ghost particles q within the cover of boundary particle b get
// f_q += eta W(x_b - x_q, h), with eta chosen so that the SPH value <f>_b (Dirichlet, eq 2.42, denominator
// D = sum_q W_bq W(x_b - x_q) ) or the SPH gradient <f'>_b (Neumann, eq 2.45, denominator N = sum_q X_bq
// W(x_b - x_q)) equals the boundary value exactly. The thesis applies the change to every particle in the
// cover except b; we restrict it to the ghosts (Algorithm 4.1 line 10 is commented "set G"), so real
// particles move only by the equation of motion. One boundary, one unknown: exact in 1D.
//
// Modified SPH matrix (eqs 2.46-2.47): for a set S of boundary and ghost particles with prescribed values,
// solve  W_SS f_S = fbar_S - W_S,rest f_rest  so that the SPH interpolant <f> = W f equals fbar at every
// particle of S. Eq (2.46) as printed drops the W_S,rest f_rest term (the "simplified" step of Section 2.9
// loses it), which leaves <f>_S != fbar_S wherever interior particles lie in the cover; we keep it, which
// is what "applied exactly" requires. W_SS is factorised once (sparse LU) and never inverted densely.
#pragma once

#include <Eigen/SparseLU>
#include <functional>
#include <vector>

#include "total_lagrangian/sph_matrices.hpp"

namespace sph {

/// Eq (2.41)-(2.45) in 1D for one boundary particle b and the ghosts that receive the correction.
class CorrectiveFactor1D {
 public:
  enum class Kind { Dirichlet, Neumann };
  CorrectiveFactor1D(const SphMatrices1D& m, const KernelFn& k, const std::vector<double>& x, int b,
                     std::vector<int> targets, Kind kind);
  /// Adds eta W(x_b - x_q) to f_q for the target particles so that (W f)_b (Dirichlet) or (X f)_b (Neumann)
  /// equals `value`; returns eta.
  double apply(Eigen::VectorXd& f, double value) const;
  double denominator() const { return denom_; }

 private:
  const SparseMatrix* A_;  // W (Dirichlet) or X (Neumann)
  int b_;
  std::vector<int> targets_;
  std::vector<double> w_;  // W(x_b - x_q, h) for each target
  double denom_;
};

/// Eqs (2.46)-(2.47) with the interior term kept: Dirichlet values on a set S, exact for <f> = W f.
class ModifiedSphMatrix {
 public:
  ModifiedSphMatrix(const SparseMatrix& W, std::vector<int> set);
  /// Overwrites f on S so that (W f)_p = fbar[k] for p = set[k]. fbar has one entry per member of S.
  void apply(Eigen::VectorXd& f, const Eigen::VectorXd& fbar);
  const std::vector<int>& set() const { return set_; }

 private:
  std::vector<int> set_;
  SparseMatrix W_S_rest_;  // rows S, all columns, with the S columns zeroed
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu_;
  Eigen::VectorXd rhs_, sol_, tmp_;
};

/// The corrective factor of eqs (2.39)-(2.42) for MANY boundary particles at once (Section 2.9's objection to
/// 2.8.3 in higher dimensions is that a ghost lies in the covers of several boundary particles: solving for
/// all factors together accounts for it). Ghost q gets f_q += sum_b eta_b W(x_b - x_q); the etas solve
///   A eta = fbar_B - (W f)_B,   A_bb' = sum_q W_bq W(x_b' - x_q)  (q over the ghosts),
/// so that the SPH interpolant equals fbar at every boundary particle. A is the modified SPH matrix (2.46)
/// restricted to the boundary rows with the ghost values spanned by the cover functions of the boundary
/// particles; it is symmetric positive semi-definite (a Gram matrix of the boundary particles' covers over the
/// ghosts) and is factorised once (sparse LU). The full square form of (2.46) also asks for <f> = fbar at the
/// ghosts, whose covers are truncated at the outer edge of the ghost layer: for a body that over-constrains
/// the outer ghosts (ModifiedSphMatrix is kept for interpolation, where that is wanted).
class CorrectiveFactorSet {
 public:
  /// `boundary`: particle indices b; `ghosts`: particle indices q that receive corrections. K: a bound kernel
  /// (bound_kernel.hpp) with W(r).
  template <class K>
  CorrectiveFactorSet(const SparseMatrix& W, const K& k, const std::vector<Vec2>& x, std::vector<int> boundary,
                      std::vector<int> ghosts)
      : W_(&W), boundary_(std::move(boundary)) {
    init(x, ghosts, [&k](double r) { return k.W(r); });
  }
  /// Adds the corrections to f so that (W f)_b = fbar[k] for b = boundary[k].
  void apply(Eigen::VectorXd& f, const Eigen::VectorXd& fbar);
  const std::vector<int>& boundary() const { return boundary_; }

 private:
  void init(const std::vector<Vec2>& x, const std::vector<int>& ghosts, const std::function<double(double)>& cover);
  const SparseMatrix* W_;
  std::vector<int> boundary_;
  SparseMatrix shape_;  // rows: ghosts (all particles), columns: boundary k; W(x_b - x_q)
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu_;
  Eigen::VectorXd rhs_, eta_, corr_;
};

}  // namespace sph
