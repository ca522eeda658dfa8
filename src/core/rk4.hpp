// Classical fourth-order Runge-Kutta (Hoover, Hoover & Merritt 2004, Sec. II: "fourth-order Runge-Kutta"),
// generic over the state type: SPAM, the molecular dynamics reference and the test ODEs use it.
//
// A State is a structure of arrays that lists its fields (fields.hpp); every field is an unknown. The
// derivative is a callable f(t, const State& y, State& dydt) that overwrites every component of dydt. The
// stage buffers are members sized on the first step (and when the number of particles changes), so a step
// never allocates otherwise.
#pragma once

#include <cstddef>

#include "core/fields.hpp"

namespace sph {

template <class State>
class Rk4 {
 public:
  /// Advances y from t to t + dt: k1 = f(y), k2 = f(y + dt/2 k1), k3 = f(y + dt/2 k2), k4 = f(y + dt k3),
  /// y += dt/6 (k1 + 2 k2 + 2 k3 + k4).
  template <class Derivative>
  void step(State& y, double t, double dt, Derivative&& f) {
    const std::size_t n = field_size(y);
    if (n != size_) {
      for (State* s : {&k1_, &k2_, &k3_, &k4_, &tmp_}) resize_fields(*s, n);
      size_ = n;
    }
    using A = FieldAlgebra;
    f(t, y, k1_);
    A::set_axpy(tmp_, y, 0.5 * dt, k1_);
    f(t + 0.5 * dt, tmp_, k2_);
    A::set_axpy(tmp_, y, 0.5 * dt, k2_);
    f(t + 0.5 * dt, tmp_, k3_);
    A::set_axpy(tmp_, y, dt, k3_);
    f(t + dt, tmp_, k4_);
    A::axpy(y, dt / 6.0, k1_);
    A::axpy(y, dt / 3.0, k2_);
    A::axpy(y, dt / 3.0, k3_);
    A::axpy(y, dt / 6.0, k4_);
  }

 private:
  State k1_, k2_, k3_, k4_, tmp_;
  std::size_t size_ = static_cast<std::size_t>(-1);
};

}  // namespace sph
