// Total Lagrangian SPH for a 1D bar (Ismail 2009 Algorithms 4.1 and 5.1), with the updated Lagrangian
// variant of Section 4.7.2 (SPH matrices recomputed from current positions every step).
//
// Per step, at time t_n (Algorithm 4.1/5.1):
//   1. boundary values: Dirichlet end particle u_b = ubar(t); ghosts by the mirror extension of the field
//      (odd about ubar at a Dirichlet end; u_mirror + epsbar (x_g - x_m) at a traction end), then the
//      corrective factor eta (eqs 2.42/2.45) on the ghosts makes <u>_b = ubar or <u'>_b = epsbar exactly;
//   2. F = 1 + X u (eq 4.6 / 5.7);
//   3. stress at the real particles: Hooke T11 = C eps (4.23: C = lambda + 2 mu for 1D strain, or E as in
//      Algorithm 4.1) or neo-Hookean P11 = mu (F - 1/F) + lambda ln F / F (Algorithm 5.1 line 15 = eq 3.64,
//      src/core/materials.hpp); ghost stresses by mirror: even at a fixed end (T_,x = rho a = 0 there), odd about
//      the applied stress at a traction end (the image construction of the wave solution (4.27));
//   4. a = (X P) / rho_0 (4.11 / 5.6); 5. central differences (4.4) on the real particles.
// In 1D the Cauchy stress equals P11 (T = J^-1 P F^T with J = F). TlSolver1D offers the solver contract of
// core/run_loop.hpp (positions and velocities as 2D vectors along x).
// CHOSEN where the thesis is silent: the ghost base values (the thesis integrates the ghosts with the rest;
// their covers then reach past the ghost layer and their values drift, so ours are slaved to the field).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "total_lagrangian/boundary_correction.hpp"
#include "core/central_difference.hpp"
#include "core/materials.hpp"
#include "total_lagrangian/sph_matrices.hpp"

namespace sph {

struct EndCondition1D {
  enum class Kind { Traction, Displacement };
  Kind kind = Kind::Traction;
  /// Applied stress T11 (= P11 in 1D) at a traction end, or the displacement at a Displacement end.
  std::function<double(double)> value = [](double) { return 0.0; };
};

struct TlConfig1D {
  double length = 0.15;        ///< m
  double ps = 0.15e-3;         ///< particle spacing, m
  double h_over_ps = 5.5;      ///< cover (support radius) in spacings
  std::string kernel = "modified_mollifier";
  std::function<double(double)> density = [](double) { return 8000.0; };  ///< rho_0(X), kg/m^3
  enum class Law { Hooke, NeoHookean } law = Law::Hooke;
  double modulus = 0.0;        ///< Hooke: C in T11 = C eps11 (4.23)
  Lame lame{0.0, 0.0};         ///< neo-Hookean constants
  EndCondition1D left, right;
  bool updated_lagrangian = false;
  double ul_pattern_factor = 1.5;  ///< UL: neighbour pattern radius / support (particles may separate)
};

class TlSolver1D {
 public:
  explicit TlSolver1D(const TlConfig1D& cfg);
  TlSolver1D(const TlSolver1D&) = delete;  // the corrective factors point into m_
  TlSolver1D& operator=(const TlSolver1D&) = delete;

  /// Sets u_0 = u_{-1} = u0(X) on the real particles (a body at rest in that state).
  void set_initial_displacement(const std::function<double(double)>& u0);
  /// Multiplies the displacement of real particle i (index into the real particles) at both time levels.
  void scale_displacement(int i, double factor);
  /// One step of Algorithm 4.1/5.1 from t to t + dt. Stress/strain afterwards refer to time t. Throws
  /// BlowUp when a displacement or stress (ghosts included) is no longer finite.
  void step(double dt);

  double time() const { return t_; }
  long steps() const { return steps_; }
  int n_real() const { return n_real_; }
  int first_real() const { return first_; }
  int n_all() const { return static_cast<int>(x_.size()); }
  double h() const { return kern_.radius; }
  double X(int i) const { return x_[first_ + i]; }  ///< reference position of real particle i
  int nearest(double X) const;                       ///< real particle index nearest to X
  double u(int i) const { return u_[first_ + i]; }
  double u_prev(int i) const { return u_prev_[first_ + i]; }
  double velocity(int i, double dt) const { return (u_[first_ + i] - u_prev_[first_ + i]) / dt; }
  // The particles, as every solver offers them (diagnostics): the real ones, along x.
  std::size_t size() const { return static_cast<std::size_t>(n_real_); }
  double mass(std::size_t i) const { return rho_[first_ + i] * dV_[first_ + i]; }
  Vec2 position(std::size_t i) const { return {X(static_cast<int>(i)) + u(static_cast<int>(i)), 0.0}; }
  /// (u_n - u_{n-1}) / dt of the last step (zero before the first).
  Vec2 velocity(std::size_t i) const { return {dt_last_ > 0 ? velocity(static_cast<int>(i), dt_last_) : 0.0, 0.0}; }
  double density(std::size_t i) const { return rho_[first_ + i] / F_[first_ + i]; }
  /// T11 as the (1, 1) entry of a 2 x 2 tensor.
  Tensor2 stress(std::size_t i) const { return (Tensor2() << P_[first_ + i], 0.0, 0.0, 0.0).finished(); }
  double stress(int i) const { return P_[first_ + i]; }  ///< T11 = P11 at time t - dt (after step)
  double stretch(int i) const { return F_[first_ + i]; }
  double max_abs_stress() const;
  bool finite() const;
  double build_seconds() const { return build_s_; }
  const SphMatrices1D& matrices() const { return m_; }
  /// Stress law of the bar at stretch F (T11 = P11 in 1D).
  double law(double F) const;
  /// The stretch F with law(F) = T (Newton; throws if none below the peak of the law).
  double inverse_law(double T) const;

 private:
  void apply_boundary(double t);
  TlConfig1D cfg_;
  KernelFn kern_;
  std::vector<double> x_, dV_, xcur_;
  int first_ = 0, n_real_ = 0;
  SphMatrices1D m_;
  std::vector<CorrectiveFactor1D> corr_;  // [0] left, [1] right
  Eigen::VectorXd u_, u_prev_, F_, P_, a_, rho_;
  double t_ = 0.0, build_s_ = 0.0, dt_last_ = 0.0;
  long steps_ = 0;
};

}  // namespace sph
