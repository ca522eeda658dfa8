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
// Everything is element by element (every first-order field has one entry per particle), with OpenMP over
// particles; nothing allocates.
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
    auto q = y.first_order();
    const auto dq = r.first_order();
    // One loop for every field (one fork and join instead of one per field: on two threads the joins of these
    // cheap loops were a measurable part of a step); each element gets the same operations as before.
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
    for (long a = 0; a < n; ++a) {
      y.x[a] += dt * r.dx[a] + half_dt2 * r.dv[a];
      y.v[a] += dt * r.dv[a];
      each_field([&](auto& qf, const auto& d0, const auto&) { qf[a] += dt * d0[a]; }, q, dq, dq);
    }
  }

  /// (6.17)-(6.18).
  static void correct(State& y, double dt, const Rates& r0, const Rates& r1) {
    const long n = static_cast<long>(y.v.size());
    const double half_dt = 0.5 * dt;
    auto q = y.first_order();
    const auto d0 = r0.first_order();
    const auto d1 = r1.first_order();
#pragma omp parallel for schedule(static) if (n >= kParallelMin)
    for (long a = 0; a < n; ++a) {
      y.v[a] += half_dt * (r1.dv[a] - r0.dv[a]);
      each_field([&](auto& qf, const auto& e0, const auto& e1) { qf[a] += half_dt * (e1[a] - e0[a]); }, q, d0, d1);
    }
  }

 private:
  // f(q_i, d0_i, d1_i) for the i-th first-order field and its two rates, for every i.
  template <class F, class Q, class D0, class D1>
  static void each_field(F&& f, Q& q, const D0& d0, const D1& d1) {
    constexpr std::size_t nf = std::tuple_size_v<Q>;
    static_assert(nf == std::tuple_size_v<D0> && nf == std::tuple_size_v<D1>, "rates must match the first-order fields");
    visit(f, q, d0, d1, std::make_index_sequence<nf>{});
  }
  template <class F, class Q, class D0, class D1, std::size_t... I>
  static void visit(F& f, Q& q, const D0& d0, const D1& d1, std::index_sequence<I...>) {
    (f(std::get<I>(q), std::get<I>(d0), std::get<I>(d1)), ...);
  }
};

}  // namespace sph
