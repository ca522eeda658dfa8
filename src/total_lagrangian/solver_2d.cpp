#include "total_lagrangian/solver_2d.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/blow_up.hpp"

namespace sph {

template <class K>
void TlSolver2D::build(const K& kernel) {
  const auto t0 = std::chrono::steady_clock::now();
  TlConfig2D& cfg = b_.cfg;
  if (!(cfg.rho > 0) || cfg.real.empty()) throw std::invalid_argument("TlSolver2D: need ps, rho > 0 and particles");
  if (cfg.conditions.empty() && !cfg.ghosts.empty()) throw std::invalid_argument("TlSolver2D: ghosts need boundary conditions");
  if (cfg.hourglass < 0) throw std::invalid_argument("TlSolver2D: hourglass >= 0");
  if (cfg.closure_passes < 1) throw std::invalid_argument("TlSolver2D: closure_passes >= 1 (0 would leave the ghosts and the gradient unset)");
  b_.radius = kernel.radius;
  b_.nr = static_cast<int>(cfg.real.size());
  b_.ng = static_cast<int>(cfg.ghosts.size());
  b_.all = cfg.real;
  b_.all.insert(b_.all.end(), cfg.ghosts.begin(), cfg.ghosts.end());
  const int nr = b_.nr, ng = b_.ng, n = nr + ng;
  b_.m = build_sph_matrices_2d(kernel, b_.all, std::vector<double>(n, cfg.ps * cfg.ps));
  TlBoundary2D& bd = b_.boundary;
  bd.conditions = std::move(cfg.conditions);
  std::vector<Vec2> Yb, Ym;
  for (const auto& g : cfg.ghosts) {
    bd.points.push_back(cfg.ghost_boundary(g));
    if (bd.points.back().condition < 0 || bd.points.back().condition >= static_cast<int>(bd.conditions.size()))
      throw std::invalid_argument("TlSolver2D: ghost boundary condition index out of range");
    Yb.push_back(bd.points.back().Xb);
    Ym.push_back(2.0 * bd.points.back().Xb - g);
  }
  if (ng > 0) {
    bd.Ib = interpolation_rows(b_.all, nr, Yb, kernel, cfg.ps);
    bd.Im = interpolation_rows(b_.all, nr, Ym, kernel, cfg.ps);
  }
  for (int c = 0; c < 2; ++c) {
    std::vector<int> bset, gset;
    std::vector<char> in(nr, 0);
    for (const auto& [i, cond] : cfg.real_on_dirichlet)
      if (bd.conditions.at(cond).dirichlet[c] && !in.at(i)) { bset.push_back(i); in[i] = 1; bd.dirichlet_condition[c].push_back(cond); }
    for (int k = 0; k < ng; ++k)
      if (bd.condition_of_ghost(k).dirichlet[c]) gset.push_back(nr + k);
    if (!bset.empty() && !gset.empty()) {
      bd.dirichlet[c] = std::make_unique<CorrectiveFactorSet>(b_.m.W, kernel, b_.all, bset, gset);
      bd.dirichlet_target[c].resize(static_cast<int>(bset.size()));
    }
  }
  for (int c = 0; c < 2; ++c) {
    b_.u[c] = Eigen::VectorXd::Zero(n);
    b_.up[c] = b_.u[c];
    b_.a[c] = b_.u[c];
  }
  for (auto& v : b_.g) v = Eigen::VectorXd::Zero(n);
  for (auto& v : b_.P) v = Eigen::VectorXd::Zero(n);
  b_.tmp = Eigen::VectorXd::Zero(n);
  stepper_ = make_tl_stepper_2d(b_, cfg.hourglass > 0 ? HourglassControl(b_, kernel, cfg.hourglass) : HourglassControl());
  build_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The kernels a 2D body can be built with.
template void TlSolver2D::build(const BoundKernel<CubicSpline>&);
template void TlSolver2D::build(const BoundKernel<Lucy>&);
template void TlSolver2D::build(const BoundKernel<Gaussian>&);
template void TlSolver2D::build(const BoundKernel<Mollifier>&);
template void TlSolver2D::build(const BoundKernel<ModifiedMollifier>&);

void TlSolver2D::set_initial_displacement(const std::function<Vec2(const Vec2&)>& u0) {
  for (int i = 0; i < b_.nr; ++i) {
    const Vec2 v = u0(b_.all[i]);
    for (int c = 0; c < 2; ++c) b_.u[c][i] = b_.up[c][i] = v[c];
  }
  // The ghost rule uses the gradient of the previous step: converge it for the initial state.
  for (int it = 0; it < 20; ++it) {
    stepper_->ghost_displacements(b_);
    b_.gradient();
  }
}

void TlSolver2D::set_initial_velocity(const std::function<Vec2(const Vec2&)>& v0, double dt) {
  if (!(dt > 0)) throw std::invalid_argument("TlSolver2D::set_initial_velocity: need dt > 0");
  for (int i = 0; i < b_.nr; ++i) {
    const Vec2 v = v0(b_.all[i]);
    for (int c = 0; c < 2; ++c) b_.up[c][i] = b_.u[c][i] - dt * v[c];
  }
}

void TlSolver2D::step(double dt) {
  stepper_->step(b_, dt);
  check_state();
}

void TlSolver2D::check_state() const {
  const std::size_t bad = first_bad_particle(size(), [this](std::size_t i) {
    return !(std::isfinite(b_.u[0][i]) && std::isfinite(b_.u[1][i]) && std::isfinite(b_.P[0][i]) &&
             std::isfinite(b_.P[1][i]) && std::isfinite(b_.P[2][i]) && std::isfinite(b_.P[3][i]));
  });
  if (bad < size()) throw_blow_up(b_.steps, b_.t, bad, b_.all[bad], "non-finite displacement or stress");
}

int TlSolver2D::nearest(const Vec2& Xq) const {
  int best = 0;
  for (int i = 1; i < b_.nr; ++i)
    if ((b_.all[i] - Xq).squaredNorm() < (b_.all[best] - Xq).squaredNorm()) best = i;
  return best;
}

Tensor2 TlSolver2D::P(int i) const {
  Tensor2 P;
  P << b_.P[0][i], b_.P[1][i], b_.P[2][i], b_.P[3][i];
  return P;
}

Vec2 TlSolver2D::velocity(std::size_t i) const {
  if (!(b_.dt_last > 0)) return Vec2::Zero();
  return Vec2(b_.u[0][i] - b_.up[0][i], b_.u[1][i] - b_.up[1][i]) / b_.dt_last;
}

Tensor2 TlSolver2D::smoothed_cauchy(int i) const {
  Tensor2 s = Tensor2::Zero();
  double w = 0;
  for (SparseMatrix::InnerIterator it(b_.m.W, i); it; ++it) {
    if (it.col() >= b_.nr) continue;
    s += it.value() * cauchy(static_cast<int>(it.col()));
    w += it.value();
  }
  return s / w;
}

Tensor2 TlSolver2D::smoothed(int i, const std::vector<Tensor2>& field) const {
  if (static_cast<int>(field.size()) != b_.nr) throw std::invalid_argument("TlSolver2D::smoothed: one tensor per real particle");
  Tensor2 s = Tensor2::Zero();
  double w = 0;
  for (SparseMatrix::InnerIterator it(b_.m.W, i); it; ++it) {
    if (it.col() >= b_.nr) continue;
    s += it.value() * field[static_cast<std::size_t>(it.col())];
    w += it.value();
  }
  return s / w;
}

bool TlSolver2D::finite() const {
  for (int c = 0; c < 2; ++c) if (!b_.u[c].head(b_.nr).allFinite()) return false;
  for (const auto& p : b_.P) if (!p.head(b_.nr).allFinite()) return false;
  return true;
}

}  // namespace sph
