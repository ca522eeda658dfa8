#include "total_lagrangian/boundary_correction.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sph {

CorrectiveFactor1D::CorrectiveFactor1D(const SphMatrices1D& m, const KernelFn& k, const std::vector<double>& x,
                                       int b, std::vector<int> targets, Kind kind)
    : A_(kind == Kind::Dirichlet ? &m.W : &m.X), b_(b), targets_(std::move(targets)), denom_(0.0) {
  for (int q : targets_) {
    const double r = std::abs(x[b] - x[q]);
    if (q == b || !(r < k.radius)) throw std::invalid_argument("CorrectiveFactor1D: target outside the cover of b");
    w_.push_back(k.W(r));
    denom_ += A_->coeff(b, q) * w_.back();  // the denominator D (2.42) or N (2.45) over the targets
  }
  if (std::abs(denom_) < 1e-300) throw std::invalid_argument("CorrectiveFactor1D: zero denominator");
}

double CorrectiveFactor1D::apply(Eigen::VectorXd& f, double value) const {
  const double current = A_->row(b_).dot(f);
  const double eta = (value - current) / denom_;
  for (std::size_t k = 0; k < targets_.size(); ++k) f[targets_[k]] += eta * w_[k];
  return eta;
}

ModifiedSphMatrix::ModifiedSphMatrix(const SparseMatrix& W, std::vector<int> set) : set_(std::move(set)) {
  const int n = static_cast<int>(W.rows()), m = static_cast<int>(set_.size());
  if (m == 0) throw std::invalid_argument("ModifiedSphMatrix: empty set");
  std::vector<int> pos(n, -1);
  for (int k = 0; k < m; ++k) {
    if (set_[k] < 0 || set_[k] >= n || pos[set_[k]] >= 0) throw std::invalid_argument("ModifiedSphMatrix: bad set");
    pos[set_[k]] = k;
  }
  std::vector<Eigen::Triplet<double, int>> tss, trest;
  for (int k = 0; k < m; ++k)
    for (SparseMatrix::InnerIterator it(W, set_[k]); it; ++it) {
      if (pos[it.col()] >= 0) tss.emplace_back(k, pos[it.col()], it.value());
      else trest.emplace_back(k, it.col(), it.value());
    }
  Eigen::SparseMatrix<double> Wss(m, m);
  Wss.setFromTriplets(tss.begin(), tss.end());
  Wss.makeCompressed();
  W_S_rest_.resize(m, n);
  W_S_rest_.setFromTriplets(trest.begin(), trest.end());
  lu_.analyzePattern(Wss);
  lu_.factorize(Wss);
  if (lu_.info() != Eigen::Success)
    throw std::runtime_error("ModifiedSphMatrix: W_SS is singular (" + std::to_string(m) + " particles)");
  rhs_.resize(m);
  sol_.resize(m);
  tmp_.resize(m);
}

void ModifiedSphMatrix::apply(Eigen::VectorXd& f, const Eigen::VectorXd& fbar) {
  tmp_.noalias() = W_S_rest_ * f;
  rhs_ = fbar - tmp_;
  sol_ = lu_.solve(rhs_);
  for (std::size_t k = 0; k < set_.size(); ++k) f[set_[k]] = sol_[k];
}

void CorrectiveFactorSet::init(const std::vector<Vec2>& x, const std::vector<int>& ghosts,
                               const std::function<double(double)>& cover) {
  const SparseMatrix& W = *W_;
  const int n = static_cast<int>(W.rows()), m = static_cast<int>(boundary_.size());
  if (m == 0) throw std::invalid_argument("CorrectiveFactorSet: no boundary particles");
  std::vector<char> is_ghost(n, 0);
  for (int q : ghosts) is_ghost.at(q) = 1;
  std::vector<int> col(n, -1);
  for (int kk = 0; kk < m; ++kk) col.at(boundary_[kk]) = kk;
  // shape(q, k) = W(x_b_k - x_q) for ghosts q in the cover of b_k (W is symmetric in pattern).
  std::vector<Eigen::Triplet<double, int>> ts;
  for (int kk = 0; kk < m; ++kk)
    for (SparseMatrix::InnerIterator it(W, boundary_[kk]); it; ++it)
      if (is_ghost[it.col()]) ts.emplace_back(it.col(), kk, cover((x[boundary_[kk]] - x[it.col()]).norm()));
  shape_.resize(n, m);
  shape_.setFromTriplets(ts.begin(), ts.end());
  // A = (W restricted to boundary rows, ghost columns) * shape.
  std::vector<Eigen::Triplet<double, int>> ta;
  for (int kk = 0; kk < m; ++kk) {
    Eigen::VectorXd row = Eigen::VectorXd::Zero(m);
    for (SparseMatrix::InnerIterator it(W, boundary_[kk]); it; ++it) {
      if (!is_ghost[it.col()]) continue;
      for (SparseMatrix::InnerIterator js(shape_, it.col()); js; ++js) row[js.col()] += it.value() * js.value();
    }
    for (int j = 0; j < m; ++j)
      if (row[j] != 0.0) ta.emplace_back(kk, j, row[j]);
  }
  Eigen::SparseMatrix<double> A(m, m);
  A.setFromTriplets(ta.begin(), ta.end());
  A.makeCompressed();
  lu_.analyzePattern(A);
  lu_.factorize(A);
  if (lu_.info() != Eigen::Success)
    throw std::runtime_error("CorrectiveFactorSet: singular system (a boundary particle without ghosts in its cover?)");
  rhs_.resize(m);
  eta_.resize(m);
  corr_.resize(n);
}

void CorrectiveFactorSet::apply(Eigen::VectorXd& f, const Eigen::VectorXd& fbar) {
  for (std::size_t kk = 0; kk < boundary_.size(); ++kk) rhs_[kk] = fbar[kk] - W_->row(boundary_[kk]).dot(f);
  eta_ = lu_.solve(rhs_);
  corr_.noalias() = shape_ * eta_;
  f += corr_;
}

}  // namespace sph
