// One step of the 2D total-Lagrangian body, Ismail 2009 Section 5.4 and Algorithm 5.2, for a compile-time
// choice of the material law, the boundary closure and the optional passes (a pass that is off is not in
// the step):
//   1. ghost displacements (the closure), the Dirichlet boundary particles pinned;
//   2. F = I + [X u, Y u] (eq 5.9); P = P(F) on the real particles (the law, laws.hpp);
//   3. ghost stresses (the closure);
//   4. a = Div P / rho_0 = (X P_.1 + Y P_.2) / rho_0 (5.6), the closure's boundary forces, the hourglass
//      control and the mass-proportional damping if on;
//   5. central differences (4.4) on the real particles; the Dirichlet components pinned at the new time.
// TlSolver2D (solver_2d.hpp) holds the body and the stepper its configuration selects (stepper_2d.cpp).
#pragma once

#include <memory>

#include "core/central_difference.hpp"
#include "total_lagrangian/body_2d.hpp"
#include "total_lagrangian/hourglass_2d.hpp"

namespace sph {

struct TlStepper2D {
  virtual ~TlStepper2D() = default;
  /// Step 1 alone at the body's time (to settle the lagged gradient of an initial state).
  virtual void ghost_displacements(TlBody2D& b) = 0;
  virtual void step(TlBody2D& b, double dt) = 0;
};

/// The stepper of b's configuration: law, closure, hourglass control if cfg.hourglass > 0, damping if
/// cfg.damping > 0. The one place where the configuration becomes a compile-time instance of the step.
std::unique_ptr<TlStepper2D> make_tl_stepper_2d(const TlBody2D& b, HourglassControl hourglass);

template <class Law, class Closure, bool Hourglass, bool Damping>
class TlStepperOf final : public TlStepper2D {
 public:
  TlStepperOf(const TlBody2D& b, HourglassControl hourglass) : closure_(b), hourglass_(std::move(hourglass)) {}

  void ghost_displacements(TlBody2D& b) override { closure_.template ghost_displacements<Law>(b, b.t); }

  void step(TlBody2D& b, double dt) override {
    for (int pass = 0; pass < b.cfg.closure_passes; ++pass) {
      closure_.template ghost_displacements<Law>(b, b.t);
      b.gradient();
    }
    const int nr = b.nr;
#pragma omp parallel for schedule(static) if (nr > 2000)
    for (int i = 0; i < nr; ++i) {
      const Tensor2 P = Law::P(b.cfg.lame, b.F(i));
      b.P[0][i] = P(0, 0); b.P[1][i] = P(0, 1); b.P[2][i] = P(1, 0); b.P[3][i] = P(1, 1);
    }
    closure_.ghost_stresses(b, b.t);
    divergence_2d(b.m, b.P, b.a[0], b.a[1]);  // both components first: the passes below read only their own
    for (int c = 0; c < 2; ++c) closure_.boundary_forces(b, c, b.a[c]);
    if constexpr (Hourglass) hourglass_.add(b, b.a[0], b.a[1]);
    for (int c = 0; c < 2; ++c) {
      b.a[c] /= b.cfg.rho;
      if constexpr (Damping) b.a[c].head(nr) -= b.cfg.damping / dt * (b.u[c].head(nr) - b.up[c].head(nr));
      central_difference_step(b.u[c], b.up[c], b.a[c], dt, 0, nr);
    }
    b.t += dt;
    b.dt_last = dt;
    ++b.steps;
    // The integrator also moved the Dirichlet components of the boundary particles; pin them at the new time
    // already, so that u() and velocity() between steps report the prescribed motion, not a dt^2 a of the
    // reaction force.
    b.boundary.pin_dirichlet(b.u, b.all, b.t);
  }

 private:
  Closure closure_;
  HourglassControl hourglass_;
};

}  // namespace sph
