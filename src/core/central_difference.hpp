// Central differences in time, Ismail 2009 eq (4.4):  u_{n+1} = dt^2 a_n + 2 u_n - u_{n-1}.
// (Algorithms 4.1, 5.1 and 5.2 print "- u_{n+1}" in the last term: a typo for u_{n-1}, as (4.3)-(4.4) show.)
// Second order in dt; for u'' = -w^2 u stable iff dt w <= 2 (the amplification roots leave the unit circle).
#pragma once

#include <Eigen/Core>

namespace sph {

/// One step on the entries [begin, end): u_prev <- u_{n+1}, then swap so that on return u holds u_{n+1}
/// and u_prev holds u_n. No allocation.
inline void central_difference_step(Eigen::VectorXd& u, Eigen::VectorXd& u_prev, const Eigen::VectorXd& a, double dt,
                                    int begin, int end) {
  const double dt2 = dt * dt;
#pragma omp parallel for schedule(static) if (end - begin > 50000)
  for (int i = begin; i < end; ++i) u_prev[i] = dt2 * a[i] + 2.0 * u[i] - u_prev[i];
  u.swap(u_prev);
}

/// The largest stable step for a mode of angular frequency omega: dt = 2 / omega.
inline double central_difference_max_step(double omega) { return 2.0 / omega; }

}  // namespace sph
