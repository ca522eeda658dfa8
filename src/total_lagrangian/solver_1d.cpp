#include "total_lagrangian/solver_1d.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/blow_up.hpp"
#include "total_lagrangian/interpolation_1d.hpp"

namespace sph {

TlSolver1D::TlSolver1D(const TlConfig1D& cfg) : cfg_(cfg) {
  if (!(cfg.ps > 0) || !(cfg.length > 0) || !(cfg.h_over_ps > 1.0))
    throw std::invalid_argument("TlSolver1D: need length > 0, ps > 0 and h_over_ps > 1");
  if (cfg.law == TlConfig1D::Law::Hooke && !(cfg.modulus > 0)) throw std::invalid_argument("TlSolver1D: modulus must be > 0");
  if (cfg.law == TlConfig1D::Law::NeoHookean && !(cfg.lame.mu > 0)) throw std::invalid_argument("TlSolver1D: mu must be > 0");
  const auto t0 = std::chrono::steady_clock::now();
  kern_ = make_kernel_fn(cfg.kernel, 1, cfg.h_over_ps * cfg.ps);
  // Particles on the ends (Fig 2.25 boundary particles), ghosts out to one cover radius: every real
  // particle's cover is then full. The ghost layer must be mirrored inside the bar, hence length > cover.
  const ParticleLine line = uniform_line(0.0, cfg.length, cfg.ps, kern_.radius);
  x_ = line.x;
  dV_ = line.volume;
  first_ = static_cast<int>(line.first_real);
  n_real_ = static_cast<int>(line.n_real);
  if (first_ >= n_real_) throw std::invalid_argument("TlSolver1D: the bar must be longer than the cover radius");
  m_ = build_sph_matrices_1d(kern_, x_, dV_, cfg.updated_lagrangian ? cfg.ul_pattern_factor : 1.0);
  const int n = static_cast<int>(x_.size()), last = first_ + n_real_ - 1;
  std::vector<int> left, right;
  for (int g = 0; g < first_; ++g) left.push_back(g);
  for (int g = last + 1; g < n; ++g) right.push_back(g);
  using K = CorrectiveFactor1D::Kind;
  auto kind = [](const EndCondition1D& e) { return e.kind == EndCondition1D::Kind::Traction ? K::Neumann : K::Dirichlet; };
  corr_.emplace_back(m_, kern_, x_, first_, left, kind(cfg.left));
  corr_.emplace_back(m_, kern_, x_, last, right, kind(cfg.right));
  u_ = Eigen::VectorXd::Zero(n);
  u_prev_ = u_;
  F_ = Eigen::VectorXd::Ones(n);
  P_ = Eigen::VectorXd::Zero(n);
  a_ = Eigen::VectorXd::Zero(n);
  rho_.resize(n);
  for (int i = 0; i < n; ++i) rho_[i] = cfg.density(std::min(std::max(x_[i], 0.0), cfg.length));
  xcur_ = x_;
  build_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int TlSolver1D::nearest(double X) const {
  const long i = std::lround(X / cfg_.ps);
  return static_cast<int>(std::min<long>(std::max<long>(i, 0), n_real_ - 1));
}

void TlSolver1D::set_initial_displacement(const std::function<double(double)>& u0) {
  for (int i = 0; i < n_real_; ++i) u_[first_ + i] = u_prev_[first_ + i] = u0(x_[first_ + i]);
}

void TlSolver1D::scale_displacement(int i, double factor) {
  u_[first_ + i] *= factor;
  u_prev_[first_ + i] *= factor;
}

double TlSolver1D::law(double F) const {
  if (cfg_.law == TlConfig1D::Law::Hooke) return cfg_.modulus * (F - 1.0);
  return neo_hookean_P<1>(cfg_.lame, Tensor<1>::Constant(F))(0, 0);  // mu (F - 1/F) + lambda ln F / F
}

double TlSolver1D::inverse_law(double T) const {
  if (cfg_.law == TlConfig1D::Law::Hooke) return 1.0 + T / cfg_.modulus;
  double F = 1.0 + T / (cfg_.lame.lambda + 2.0 * cfg_.lame.mu);
  for (int it = 0; it < 60; ++it) {
    const double e = 1e-7 * F, slope = (law(F + e) - law(F - e)) / (2 * e);
    if (!(slope > 0)) break;
    const double dF = (law(F) - T) / slope;
    F = std::max(0.5 * F, F - dF);
    if (std::abs(dF) < 1e-14 * F) return F;
  }
  throw std::runtime_error("TlSolver1D::inverse_law: no stretch gives stress " + std::to_string(T));
}

void TlSolver1D::apply_boundary(double t) {
  const int n = static_cast<int>(x_.size()), last = first_ + n_real_ - 1;
  const EndCondition1D* ends[2] = {&cfg_.left, &cfg_.right};
  const int b[2] = {first_, last};
  for (int e = 0; e < 2; ++e) {
    const bool traction = ends[e]->kind == EndCondition1D::Kind::Traction;
    const double v = ends[e]->value(t);
    const double eps = traction ? inverse_law(v) - 1.0 : 0.0;
    if (!traction) u_[b[e]] = v;
    const int ng = e == 0 ? first_ : n - 1 - last;
    for (int k = 1; k <= ng; ++k) {
      const int g = e == 0 ? b[e] - k : b[e] + k, mirror = e == 0 ? b[e] + k : b[e] - k;
      u_[g] = traction ? u_[mirror] + eps * (x_[g] - x_[mirror]) : 2.0 * v - u_[mirror];
    }
    corr_[e].apply(u_, traction ? eps : v);
  }
}

void TlSolver1D::step(double dt) {
  const int n = static_cast<int>(x_.size()), last = first_ + n_real_ - 1;
  apply_boundary(t_);
  if (cfg_.updated_lagrangian) {
    for (int i = 0; i < n; ++i) xcur_[i] = x_[i] + u_[i];
    update_sph_matrices_1d(m_, kern_, xcur_, dV_);
  }
  spmv(m_.X, u_, F_);
  F_.array() += 1.0;
  for (int i = first_; i <= last; ++i) P_[i] = law(F_[i]);
  // Ghost stresses: odd about the applied stress at a traction end, even at a displacement end.
  const EndCondition1D* ends[2] = {&cfg_.left, &cfg_.right};
  const int b[2] = {first_, last};
  for (int e = 0; e < 2; ++e) {
    const bool traction = ends[e]->kind == EndCondition1D::Kind::Traction;
    const double Pbar = traction ? ends[e]->value(t_) : 0.0;
    const int ng = e == 0 ? first_ : n - 1 - last;
    for (int k = 1; k <= ng; ++k) {
      const int g = e == 0 ? b[e] - k : b[e] + k, mirror = e == 0 ? b[e] + k : b[e] - k;
      P_[g] = traction ? 2.0 * Pbar - P_[mirror] : P_[mirror];
    }
  }
  spmv(m_.X, P_, a_);
  a_.array() /= rho_.array();
  central_difference_step(u_, u_prev_, a_, dt, first_, last + 1);
  t_ += dt;
  dt_last_ = dt;
  ++steps_;
  // A displacement end holds its value at every time level (the particle is on the boundary, Fig 2.25).
  if (cfg_.left.kind == EndCondition1D::Kind::Displacement) u_[first_] = cfg_.left.value(t_);
  if (cfg_.right.kind == EndCondition1D::Kind::Displacement) u_[last] = cfg_.right.value(t_);
  // Serial below spmv's threshold like the rest of the step: in parallel from 1 000 particles this check took
  // the 1D bar's step ~10-15% slower (fork and join of a region around a few microseconds of work).
  const std::size_t bad = first_bad_particle(static_cast<std::size_t>(n), [this](std::size_t i) {
    return !(std::isfinite(u_[i]) && std::isfinite(P_[i]));
  }, kParallelRows1D);
  if (bad < static_cast<std::size_t>(n))
    throw_blow_up(steps_, t_, bad, Vec2(x_[bad], 0.0), "non-finite displacement or stress (particle index counts the ghosts)");
}

double TlSolver1D::max_abs_stress() const {
  return P_.segment(first_, n_real_).cwiseAbs().maxCoeff();
}

bool TlSolver1D::finite() const { return u_.allFinite() && P_.allFinite(); }

}  // namespace sph
