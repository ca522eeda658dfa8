// The predictor-corrector leapfrog of Gray, Monaghan & Swift 2001, eqs (6.14)-(6.18): two evaluations of
// the rates per step,
//   predictor  x += dt u0 + dt^2/2 a0,   v += dt a0,   q += dt q0'         (6.14)-(6.16)
//   corrector  v += dt/2 (a1 - a0),      q += dt/2 (q1' - q0')             (6.17)-(6.18)
// with u the velocity that moves the particles (XSPH's, or zero for a particle that is held), a the
// acceleration, q the first-order fields (density, stress) and q' their rates; 0 marks the rates at the start
// of the step, 1 at the predicted state. The positions of the predictor are final (6.15): the corrector does
// not move the particles, so the pair geometry computed after the predictor serves the next step's first
// evaluation too.
//
// A State has x and v (std::vector<Vec2>) and first_order(), a std::tie of its first-order fields; Rates
// have dx (the u above), dv (the a above) and first_order(), the rates of the same fields in the same order.
// Everything is element by element, with OpenMP over particles; nothing allocates.
#pragma once

#include <cstddef>
#include <tuple>

#include "core/fields.hpp"
#include "core/parallel.hpp"

namespace sph {

template <class State, class Rates>
struct PredictorCorrector {
  /// One step: rates(y, r0); predict; after_predict(y); rates(y, r1); correct; after_correct(y).
  /// r0 and r1 are the caller's buffers (sized for y): after the step they hold the two evaluations.
  template <class Evaluate, class AfterPredict, class AfterCorrect>
  static void step(State& y, double dt, Rates& r0, Rates& r1, Evaluate&& rates, AfterPredict&& after_predict,
                   AfterCorrect&& after_correct) {
    rates(y, r0);
    predict(y, dt, r0);
    after_predict(y);
    rates(y, r1);
    correct(y, dt, r0, r1);
    after_correct(y);
  }

  /// (6.14)-(6.16).
  static void predict(State& y, double dt, const Rates& r) {
    const long n = static_cast<long>(y.x.size());
    const double half_dt2 = 0.5 * dt * dt;
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
    for (long a = 0; a < n; ++a) {
      y.x[a] += dt * r.dx[a] + half_dt2 * r.dv[a];
      y.v[a] += dt * r.dv[a];
    }
    each_first_order(y, r, r, [dt](auto& q, const auto& dq, const auto&, long a) { q[a] += dt * dq[a]; });
  }

  /// (6.17)-(6.18).
  static void correct(State& y, double dt, const Rates& r0, const Rates& r1) {
    const long n = static_cast<long>(y.v.size());
    const double half_dt = 0.5 * dt;
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
    for (long a = 0; a < n; ++a) y.v[a] += half_dt * (r1.dv[a] - r0.dv[a]);
    each_first_order(y, r0, r1, [half_dt](auto& q, const auto& d0, const auto& d1, long a) { q[a] += half_dt * (d1[a] - d0[a]); });
  }

 private:
  // f(q, dq0, dq1, a) for every first-order field q and particle a.
  template <class F>
  static void each_first_order(State& y, const Rates& r0, const Rates& r1, F&& f) {
    auto q = y.first_order();
    auto d0 = r0.first_order();
    auto d1 = r1.first_order();
    constexpr std::size_t nf = std::tuple_size_v<decltype(q)>;
    visit(f, q, d0, d1, std::make_index_sequence<nf>{});
  }
  template <class F, class Q, class D0, class D1, std::size_t... I>
  static void visit(F& f, Q& q, D0& d0, D1& d1, std::index_sequence<I...>) {
    (loop(f, std::get<I>(q), std::get<I>(d0), std::get<I>(d1)), ...);
  }
  template <class F, class Field, class R>
  static void loop(F& f, Field& q, const R& d0, const R& d1) {
    const long n = static_cast<long>(q.size());
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
    for (long a = 0; a < n; ++a) f(q, d0, d1, a);
  }
};

}  // namespace sph
