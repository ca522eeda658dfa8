// Scratch storage of one SPAM evaluation: the neighbour pairs of every particle with their displacement
// d = x_i - x_j, weight w_ij and F_ij = w'(r)/r (so grad_i w_ij = d F_ij), gathered once per derivative
// evaluation and reused by every group of terms; plus the per-particle and per-pair intermediates.
// Sized once at construction (max_neighbours slots per particle): nothing allocates inside the time loop.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "core/kernels.hpp"
#include "core/neighbours.hpp"
#include "spam/options.hpp"

namespace sph {

/// Loops over fewer particles run serially: on small bodies (the 217-particle hexagon) a parallel region
/// costs more than it saves, and the 72-variant sweep parallelises over runs instead.
inline constexpr long kSpamParallelMin = 1000;

struct SpamWork {
  SpamWork(const SpamParams& p, std::size_t n)
      : params(p), kernel(2), cells(p.box, p.h), slots(static_cast<std::size_t>(p.max_neighbours)) {
    const std::size_t np = n * slots;
    count.assign(n, 0); nb.assign(np, 0); d.assign(np, Vec2::Zero()); w.assign(np, 0); F.assign(np, 0);
    f.assign(np, Vec2::Zero()); tau.assign(np, 0);
    rho.assign(n, 0); sumw.assign(n, 0); u.assign(n, Vec2::Zero()); q.assign(n, 0);
    txx.assign(n, 0); tyy.assign(n, 0); txy.assign(n, 0); ldot.assign(n, 0); scale.assign(n, 1);
    w0 = kernel.W(0.0, p.h);
  }

  /// Bins the particles and fills the pair arrays. OpenMP over particles.
  void gather(const std::vector<Vec2>& x) {
    cells.build(x);
    const long n = static_cast<long>(x.size());
    long overflow = -1;
#pragma omp parallel for schedule(static) if (n >= kSpamParallelMin)
    for (long i = 0; i < n; ++i) {
      std::size_t c = 0, base = static_cast<std::size_t>(i) * slots;
      cells.for_each_neighbour(x, static_cast<std::size_t>(i), params.h, [&](std::size_t j, const Vec2& dij, double r) {
        if (c < slots) {
          nb[base + c] = j; d[base + c] = dij;
          w[base + c] = kernel.W(r, params.h); F[base + c] = kernel.F(r, params.h);
        }
        ++c;
      });
      if (c > slots) {
#pragma omp critical
        overflow = i;
      }
      count[static_cast<std::size_t>(i)] = c > slots ? slots : c;
    }
    if (overflow >= 0)
      throw std::runtime_error("SPAM: particle " + std::to_string(overflow) + " has more than " +
                               std::to_string(slots) + " neighbours (raise max_neighbours)");
  }

  SpamParams params;
  Lucy kernel;
  CellList2D cells;
  std::size_t slots;
  double w0 = 0;  // w(0), the self term of the sums
  // Pairs of particle i occupy [i * slots, i * slots + count[i]).
  std::vector<std::size_t> count, nb;
  std::vector<Vec2> d;
  std::vector<double> w, F;
  std::vector<Vec2> f;       // pair acceleration m (S_ij . grad_i w_ij) before (and after) torque scaling
  std::vector<double> tau;   // pair torque m (d x f): Ldot_ij of Sec. VIII
  // Per particle: density in use, sum_j w_ij (self included), advection velocity dr/dt, viscous pressure,
  // (sigma - q I)/rho^2, particle torque Ldot_i = 1/2 sum_j Ldot_ij and its scale factor.
  std::vector<double> rho, sumw;
  std::vector<Vec2> u;
  std::vector<double> q, txx, tyy, txy, ldot, scale;
  // Diagnostics of the last evaluation.
  double torque_ratio = 1;          // R of Sec. VIII
  double torque_positive = 0, torque_negative = 0;  // sums of positive and (minus) negative torques
  double gauss_alpha = 0, gauss_beta = 0, gauss_denominator = 0, gauss_inertia = 0, spam_torque = 0;
  long gauss_floor_hits = 0;
};

}  // namespace sph
