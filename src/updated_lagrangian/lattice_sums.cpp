#include "updated_lagrangian/lattice_sums.hpp"

#include <cmath>
#include <stdexcept>

namespace sph {

template <class Shape>
DispersionSums dispersion_sums(const Kernel<Shape>& kernel, LatticeKind lattice, double h_over_dp, int n,
                               double kx, double ky) {
  if (kernel.dim() != 2) throw std::invalid_argument("dispersion_sums: needs a 2D kernel");
  if (!(h_over_dp > 0) || n < 0) throw std::invalid_argument("dispersion_sums: need h/dp > 0 and n >= 0");
  const double h = h_over_dp, dp = 1.0;
  const double Wdp = kernel.W(dp, h);
  if (!(Wdp > 0)) throw std::invalid_argument("dispersion_sums: W(dp) = 0, f = W/W(dp) undefined (h/dp too small)");
  const double Z = dp * dp / ((n + 1) * std::pow(Wdp, n));
  const double R = kernel.support() * h;
  const double dy = row_spacing(lattice, dp);
  const int nx = static_cast<int>(std::ceil(R / dp)) + 2, ny = static_cast<int>(std::ceil(R / dy)) + 2;

  DispersionSums s;
  for (int j = -ny; j <= ny; ++j) {
    const double shift = (lattice != LatticeKind::Square && (j % 2 != 0)) ? 0.5 * dp : 0.0;
    for (int i = -nx; i <= nx; ++i) {
      // r_ab = r_a - r_b with a at the origin and b at the lattice point.
      const Vec2 rab(-(i * dp + shift), -(j * dy));
      const double r = rab.norm();
      if (r == 0.0 || r >= R) continue;
      const double phase = kx * rab.x() + ky * rab.y();
      const double one_minus_cos = 1.0 - std::cos(phase), sine = std::sin(phase);
      const double W = kernel.W(r, h), dW = kernel.dWdr(r, h), d2W = kernel.d2Wdr2(r, h);
      const Vec2 e = rab / r;
      // Hessian of a radial function g(|r_a - r_b|) with respect to r_a: g'' e e^T + g'/r (I - e e^T).
      auto hess = [&](double g1, double g2, double& hxx, double& hyy, double& hxy) {
        hxx = g2 * e.x() * e.x() + g1 / r * (1 - e.x() * e.x());
        hyy = g2 * e.y() * e.y() + g1 / r * (1 - e.y() * e.y());
        hxy = (g2 - g1 / r) * e.x() * e.y();
      };
      double hxx, hyy, hxy;
      hess(dW, d2W, hxx, hyy, hxy);
      s.A_x += sine * dW * e.x();
      s.A_y += sine * dW * e.y();
      s.B_x += one_minus_cos * hxx;
      s.B_y += one_minus_cos * hyy;
      s.C += one_minus_cos * hxy;
      s.beta += 0.5 * one_minus_cos * W;
      // g = W^(n+1): g' = (n+1) W^n W', g'' = (n+1) (n W^(n-1) W'^2 + W^n W'').
      const double Wn = std::pow(W, n);
      const double g1 = (n + 1) * Wn * dW;
      const double g2 = (n + 1) * ((n > 0 ? n * std::pow(W, n - 1) * dW * dW : 0.0) + Wn * d2W);
      hess(g1, g2, hxx, hyy, hxy);
      s.f_xx += Z * one_minus_cos * hxx;
      s.f_yy += Z * one_minus_cos * hyy;
      s.f_xy += Z * one_minus_cos * hxy;
    }
  }
  const double area = dp * dp;  // the dp^2 prefactor of (5.5) and (5.14)
  s.A_x *= area; s.A_y *= area; s.B_x *= area; s.B_y *= area; s.C *= area; s.beta *= area;
  return s;
}

template DispersionSums dispersion_sums(const Kernel<CubicSplineShape>&, LatticeKind, double, int, double, double);
template DispersionSums dispersion_sums(const Kernel<LucyShape>&, LatticeKind, double, int, double, double);
template DispersionSums dispersion_sums(const Kernel<GaussianShape>&, LatticeKind, double, int, double, double);
template DispersionSums dispersion_sums(const Kernel<MollifierShape>&, LatticeKind, double, int, double, double);
template DispersionSums dispersion_sums(const Kernel<ModifiedMollifierShape>&, LatticeKind, double, int, double, double);

}  // namespace sph
