// Lattice sums of the SPH dispersion relation, Gray, Monaghan & Swift 2001, Section 5.
//
// For a particle a on an infinite lattice of spacing dp, with k the wave vector:
//   A     = dp^2 sum_b sin(k.r_ab) grad_a W_ab                                   (5.5)
//   B_x   = dp^2 sum_b (1 - cos k.r_ab) d2W_ab/dx_a^2, B_y likewise, C = mixed     (5.5)
//   beta  = 1/2 dp^2 sum_b (1 - cos k.r_ab) W_ab                                  (5.5)
//   f_ij  = Z sum_b (1 - cos k.r_ab) d2(W_ab^(n+1))/dx_a^i dx_a^j,
//   Z     = dp^2 / ((n + 1) W(dp)^n)                                             (5.14), (5.15)
// The sums run over every lattice point within the kernel support (no truncation beyond it).
#pragma once

#include "core/kernels.hpp"
#include "core/lattices.hpp"

namespace sph {

struct DispersionSums {
  double A_x = 0, A_y = 0;          // units 1/dp
  double B_x = 0, B_y = 0, C = 0;   // units 1/dp^2
  double beta = 0;                  // dimensionless
  double f_xx = 0, f_yy = 0, f_xy = 0;  // units 1/dp^2
};

/// The sums for a square or face-centred lattice (LatticeKind), h = h_over_dp * dp, artificial-stress
/// exponent n, wave vector k = (kx, ky) in units of 1/dp; all results in units of dp = 1.
template <class Shape>
DispersionSums dispersion_sums(const Kernel<Shape>& kernel, LatticeKind lattice, double h_over_dp, int n,
                               double kx, double ky);

}  // namespace sph
