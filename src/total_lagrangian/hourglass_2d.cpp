#include "total_lagrangian/hourglass_2d.hpp"

namespace sph {

void HourglassControl::add(const TlBody2D& b, int c, Eigen::VectorXd& a) const {
  // Row c of G: g[2c] = du_c/dX, g[2c + 1] = du_c/dY.
  const Eigen::VectorXd &gx = b.g[2 * c], &gy = b.g[2 * c + 1], &u = b.u[c];
  const double k = gamma_ * young_modulus(b.cfg.lame);
  const int* outer = K_.outerIndexPtr();
  const int* inner = K_.innerIndexPtr();
  const double* val = K_.valuePtr();
  const int nr = b.nr;
#pragma omp parallel for schedule(static) if (nr > 2000)
  for (int i = 0; i < nr; ++i) {
    double s = 0;
    for (int e = outer[i]; e < outer[i + 1]; ++e) {
      const int j = inner[e];
      const bool ghost = j >= nr;  // a ghost's own gradient is truncated by the edge of the ghost layer
      const double Gx = 0.5 * (gx[i] + (ghost ? gx[i] : gx[j])), Gy = 0.5 * (gy[i] + (ghost ? gy[i] : gy[j]));
      const Vec2 d = b.all[j] - b.all[i];
      s += val[e] * (u[j] - u[i] - Gx * d.x() - Gy * d.y());
    }
    a[i] += k * s;
  }
}

}  // namespace sph
