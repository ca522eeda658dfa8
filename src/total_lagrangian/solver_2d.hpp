// Total Lagrangian SPH in 2D (plane strain), Ismail 2009 Section 5.4 and Algorithm 5.2: the solver of a body
// declared by a TlConfig2D (body_2d.hpp). Its kernel is a template parameter of the construction (the modified
// mollifier of the thesis by default), which builds the sparse SPH matrices (sph_matrices.hpp), the ghosts'
// boundary (boundary_2d.hpp) and the optional hourglass weights; the law, the boundary closure and the optional
// passes are mapped once onto a compile-time instance of the step (stepper_2d.hpp). TlSolver2D offers the
// solver contract of core/run_loop.hpp.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>

#include "core/kernels.hpp"
#include "total_lagrangian/body_2d.hpp"
#include "total_lagrangian/bound_kernel.hpp"
#include "total_lagrangian/stepper_2d.hpp"

namespace sph {

/// Selects the kernel of a TlSolver2D: TlSolver2D body(cfg, KernelTag<Lucy>{}).
template <class Kernel>
struct KernelTag {};

class TlSolver2D {
 public:
  template <class Kernel = ModifiedMollifier>
  explicit TlSolver2D(TlConfig2D cfg, KernelTag<Kernel> = {}) {
    b_.cfg = std::move(cfg);
    if (!(b_.cfg.ps > 0) || !(b_.cfg.h_over_ps > 0)) throw std::invalid_argument("TlSolver2D: need ps, h_over_ps > 0");
    build(BoundKernel<Kernel>(2, b_.cfg.h_over_ps * b_.cfg.ps));
  }
  TlSolver2D(const TlSolver2D&) = delete;
  TlSolver2D& operator=(const TlSolver2D&) = delete;

  /// u_0 = u_{-1} = u0(X) on the real particles.
  void set_initial_displacement(const std::function<Vec2(const Vec2&)>& u0);
  /// u_{-1} = u_0 - dt v0(X) on the real particles, so that the central difference starts at velocity v0: exact
  /// to O(dt^3) where the initial acceleration is zero (an unstressed body). dt must be the first step's.
  void set_initial_velocity(const std::function<Vec2(const Vec2&)>& v0, double dt);
  /// One step; throws BlowUp when a displacement or stress of a real particle is no longer finite.
  void step(double dt);
  double time() const { return b_.t; }
  long steps() const { return b_.steps; }

  int n_real() const { return b_.nr; }
  const Vec2& X(int i) const { return b_.all[i]; }
  Vec2 u(int i) const { return {b_.u[0][i], b_.u[1][i]}; }
  /// (u_n - u_{n-1}) / dt of the last step (zero before the first); Dirichlet components as prescribed.
  Vec2 velocity(std::size_t i) const;
  double rho0() const { return b_.cfg.rho; }
  /// F and P at real particle i, from the last step (time t - dt).
  Tensor2 F(int i) const { return b_.F(i); }
  Tensor2 P(int i) const;
  /// Cauchy stress T = J^-1 P F^T (3.33), in-plane.
  Tensor2 cauchy(int i) const { return cauchy_from_P<2>(P(i), F(i)); }
  /// The Shepard-normalised SPH interpolant of the Cauchy stress over the real particles at real particle i,
  /// sum_q W_iq T_q / sum_q W_iq: the 'secondary SPH approximation' of Section 2.9, which filters the
  /// particle-scale (zero-energy) modes that the plain SPH gradient cannot see.
  Tensor2 smoothed_cauchy(int i) const;
  /// The same interpolant of any tensor field on the real particles (field[q] at real particle q): for a field
  /// that is not this body's own, e.g. an independent code's stress on this body's particles.
  Tensor2 smoothed(int i, const std::vector<Tensor2>& field) const;
  double h() const { return b_.radius; }
  bool finite() const;
  double build_seconds() const { return build_s_; }  ///< SPH matrices, interpolation rows, LU factorisations
  int nearest(const Vec2& Xq) const;

  // The particles, as every solver offers them (diagnostics, snapshots): the real ones, in the current
  // configuration X + u, with the current density rho_0 / J.
  std::size_t size() const { return static_cast<std::size_t>(b_.nr); }
  double mass(std::size_t) const { return b_.cfg.rho * b_.cfg.ps * b_.cfg.ps; }
  Vec2 position(std::size_t i) const { return X(static_cast<int>(i)) + u(static_cast<int>(i)); }
  double density(std::size_t i) const { return b_.cfg.rho / F(static_cast<int>(i)).determinant(); }
  Tensor2 stress(std::size_t i) const { return cauchy(static_cast<int>(i)); }

 private:
  template <class K>
  void build(const K& kernel);
  void check_state() const;
  TlBody2D b_;
  std::unique_ptr<TlStepper2D> stepper_;
  double build_s_ = 0.0;
};

}  // namespace sph
