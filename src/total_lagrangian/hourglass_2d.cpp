#include "total_lagrangian/hourglass_2d.hpp"

namespace sph {

void HourglassControl::add(const TlBody2D& b, Eigen::VectorXd& a0_, Eigen::VectorXd& a1_) const {
  // Row c of G: g[2c] = du_c/dX, g[2c + 1] = du_c/dY. Both components in one pass: they share the pattern,
  // the weights and the offsets (the pass was a third of a sheet-with-a-hole step when run per component).
  const double* __restrict g0x = b.g[0].data();
  const double* __restrict g0y = b.g[1].data();
  const double* __restrict g1x = b.g[2].data();
  const double* __restrict g1y = b.g[3].data();
  const double* __restrict u0 = b.u[0].data();
  const double* __restrict u1 = b.u[1].data();
  const double k = gamma_ * young_modulus(b.cfg.lame);
  const int* __restrict outer = K_.outerIndexPtr();
  const int* __restrict inner = K_.innerIndexPtr();
  const double* __restrict val = K_.valuePtr();
  const Vec2* __restrict d = offset_.data();
  const int nr = b.nr;
  double* __restrict a0 = a0_.data();
  double* __restrict a1 = a1_.data();
#pragma omp parallel for schedule(static) if (nr > 2000)
  for (int i = 0; i < nr; ++i) {
    double s0 = 0, s1 = 0;
    for (int e = outer[i]; e < outer[i + 1]; ++e) {
      const int j = inner[e];
      const int jg = j >= nr ? i : j;  // a ghost's own gradient is truncated by the edge of the ghost layer: G_j := G_i
      const double dx = d[e].x(), dy = d[e].y();
      const double G0x = 0.5 * (g0x[i] + g0x[jg]), G0y = 0.5 * (g0y[i] + g0y[jg]);
      const double G1x = 0.5 * (g1x[i] + g1x[jg]), G1y = 0.5 * (g1y[i] + g1y[jg]);
      s0 += val[e] * (u0[j] - u0[i] - G0x * dx - G0y * dy);
      s1 += val[e] * (u1[j] - u1[i] - G1x * dx - G1y * dy);
    }
    // a_i += k s_i as the per-component pass had it (one fused multiply-add: bit-identical to it).
    a0[i] += k * s0;
    a1[i] += k * s1;
  }
}

}  // namespace sph
