// Classical fourth-order Runge-Kutta (Hoover, Hoover & Merritt 2004, Sec. II: "fourth-order Runge-Kutta"),
// generic over the state type so that every solver can use it (SPAM, molecular dynamics, test ODEs).
//
// A State must provide
//   void resize_like(const State& y);                          // same shape as y (may allocate)
//   void set_axpy(const State& x, double a, const State& k);   // *this = x + a k (no allocation)
//   void axpy(double a, const State& k);                       // *this += a k     (no allocation)
// and the derivative is a callable f(t, const State& y, State& dydt) that overwrites every component of
// dydt. The stage buffers are members sized on the first step, so a step never allocates afterwards.
// The vector helpers below implement these operations for std::vector members of double or Eigen types.
#pragma once

#include <cstddef>
#include <vector>

namespace sph {

/// out = x + a k, element by element (out must already have x's size).
template <class T>
void vec_set_axpy(std::vector<T>& out, const std::vector<T>& x, double a, const std::vector<T>& k) {
  const std::size_t n = x.size();
  for (std::size_t i = 0; i < n; ++i) out[i] = x[i] + a * k[i];
}
/// y += a k, element by element.
template <class T>
void vec_axpy(std::vector<T>& y, double a, const std::vector<T>& k) {
  const std::size_t n = y.size();
  for (std::size_t i = 0; i < n; ++i) y[i] += a * k[i];
}

template <class State>
class Rk4 {
 public:
  /// Advances y from t to t + dt: k1 = f(y), k2 = f(y + dt/2 k1), k3 = f(y + dt/2 k2), k4 = f(y + dt k3),
  /// y += dt/6 (k1 + 2 k2 + 2 k3 + k4).
  template <class Derivative>
  void step(State& y, double t, double dt, Derivative&& f) {
    if (!sized_) {
      k1_.resize_like(y); k2_.resize_like(y); k3_.resize_like(y); k4_.resize_like(y); tmp_.resize_like(y);
      sized_ = true;
    }
    f(t, y, k1_);
    tmp_.set_axpy(y, 0.5 * dt, k1_);
    f(t + 0.5 * dt, tmp_, k2_);
    tmp_.set_axpy(y, 0.5 * dt, k2_);
    f(t + 0.5 * dt, tmp_, k3_);
    tmp_.set_axpy(y, dt, k3_);
    f(t + dt, tmp_, k4_);
    y.axpy(dt / 6.0, k1_);
    y.axpy(dt / 3.0, k2_);
    y.axpy(dt / 3.0, k3_);
    y.axpy(dt / 6.0, k4_);
  }
  /// Forgets the buffer sizes (call when the number of unknowns changes).
  void reset() { sized_ = false; }

 private:
  State k1_, k2_, k3_, k4_, tmp_;
  bool sized_ = false;
};

}  // namespace sph
