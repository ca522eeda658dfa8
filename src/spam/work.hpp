// Scratch storage of one SPAM evaluation: the neighbour pairs of every particle in the shared pair storage
// (core/pair_list.hpp) with their displacement d = x_i - x_j, weight w_ij and F_ij = w'(r)/r (so
// grad_i w_ij = d F_ij), gathered once per derivative evaluation and reused by every group of terms; plus the
// per-particle and per-pair intermediates. The pair list keeps its candidates within support + skin until a
// particle has moved half the skin (SpamParams::skin_over_h): the sums run over exactly the pairs inside the
// support, in the order of the last search (with skin 0: of a fresh search at every evaluation). Nothing
// allocates in the time loop once the arrays have reached their size.
#pragma once

#include <vector>

#include "core/kernels.hpp"
#include "core/neighbours.hpp"
#include "core/pair_list.hpp"
#include "core/parallel.hpp"
#include "spam/options.hpp"

namespace sph {

struct SpamWork {
  SpamWork(const SpamParams& p, std::size_t n)
      : params(p), kernel(2), cells(p.box, (kernel.support() + p.skin_over_h) * p.h) {
    rho.assign(n, 0); sumw.assign(n, 0); u.assign(n, Vec2::Zero()); q.assign(n, 0);
    txx.assign(n, 0); tyy.assign(n, 0); txy.assign(n, 0); ldot.assign(n, 0); scale.assign(n, 1);
    w0 = kernel.W(0.0, p.h);
  }

  /// Bins the particles (when the skin is used up) and refreshes the pairs and their geometry. OpenMP over
  /// particles.
  void gather(const std::vector<Vec2>& x) {
    const double h = params.h;
    pairs.update(cells, x, kernel.support() * h, params.skin_over_h * h, kernel.at(h));
    if (f.size() < pairs.slots()) {
      f.resize(pairs.slots(), Vec2::Zero());
      tau.resize(pairs.slots(), 0.0);
    }
  }

  SpamParams params;
  Lucy kernel;
  CellList2D cells;
  PairList pairs;            // pairs of particle i: k = pairs.first(i) .. pairs.last(i) - 1
  double w0 = 0;             // w(0), the self term of the sums
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
