#include "gray2001/scenes/plate.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>

#include "core/lattices.hpp"
#include "core/materials.hpp"

namespace scenes {

double cantilever_kL() {
  gsl_function f;
  f.function = [](double z, void*) { return std::cos(z) * std::cosh(z) + 1.0; };
  f.params = nullptr;
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> s(gsl_root_fsolver_alloc(gsl_root_fsolver_brent),
                                                                       gsl_root_fsolver_free);
  gsl_root_fsolver_set(s.get(), &f, 1.0, 3.0);  // the fundamental root lies in (pi/2, pi)
  double lo = 1.0, hi = 3.0;
  for (int it = 0; it < 200; ++it) {
    gsl_root_fsolver_iterate(s.get());
    lo = gsl_root_fsolver_x_lower(s.get());
    hi = gsl_root_fsolver_x_upper(s.get());
    if (gsl_root_test_interval(lo, hi, 0.0, 1e-15) == GSL_SUCCESS) break;
  }
  return gsl_root_fsolver_root(s.get());
}

double cantilever_mode_velocity(double x, double L, double Vf) {
  const double kL = cantilever_kL(), k = kL / L;
  const double M = std::sin(kL) + std::sinh(kL), N = std::cos(kL) + std::cosh(kL);
  const double Q = 2.0 * (std::cos(kL) * std::sinh(kL) - std::sin(kL) * std::cosh(kL));
  return Vf * (M * (std::cos(k * x) - std::cosh(k * x)) - N * (std::sin(k * x) - std::sinh(k * x))) / Q;
}

double plate_theory_period(double E, double nu, double H, double L, double rho) {
  const double k = cantilever_kL() / L;
  const double omega2 = E * H * H * k * k * k * k / (12.0 * rho * (1.0 - nu * nu));
  return 2.0 * M_PI / std::sqrt(omega2);
}

double plate_theory_period(double mu, double H, double L) {
  const double K = 1.0;
  return plate_theory_period(sph::young_from_bulk_shear(K, mu), sph::poisson_ratio_from_bulk_shear(K, mu), H, L, 1.0);
}

void check_size(const PlateSpec& s) {
  sph::check_particle_count((s.L + s.clamp_length) / s.dp * (s.H / s.dp), s.dp, "plate");
}

Plate make_plate(const PlateSpec& s, const sph::GrayParameters& scheme) {
  if (!(s.dp > 0) || !(s.L > 0) || !(s.H > 0) || s.clamp_length < 0 || s.clamp_layers < 1)
    throw std::invalid_argument("plate: need dp, L, H > 0, clamp length >= 0, clamp layers >= 1");
  const double nrows = s.H / s.dp;
  if (std::abs(nrows - std::round(nrows)) > 1e-9 || nrows < 2)
    throw std::invalid_argument("plate: H / dp must be an integer >= 2 (particles across the thickness)");
  const double ncols_clamp = s.clamp_length / s.dp;
  if (std::abs(ncols_clamp - std::round(ncols_clamp)) > 1e-9)
    throw std::invalid_argument("plate: clamp length must be a multiple of dp");
  Plate p;
  const double rho0 = scheme.rho0, c0 = scheme.c0, m = rho0 * s.dp * s.dp;
  const double x0 = -s.clamp_length;
  check_size(s);
  const int nx = static_cast<int>(std::lround((s.L + s.clamp_length) / s.dp));
  // Row j's centre at (j + first) dp: half spacings (n rows), or the outer centres on the faces (n + 1 rows); the
  // fixed layers continue the rows' spacing beyond the faces, at (l + gap) dp.
  const int ny = static_cast<int>(std::lround(nrows)) + (s.centres_on_faces ? 1 : 0);
  const double first = s.centres_on_faces ? 0.0 : 0.5, gap = s.centres_on_faces ? 1.0 : 0.5;
  double best = std::numeric_limits<double>::max();
  std::mt19937 rng(s.seed);
  std::uniform_real_distribution<double> jitter(-s.perturbation * s.dp, s.perturbation * s.dp);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const sph::Vec2 x(x0 + (i + 0.5) * s.dp, (j + first) * s.dp);
      const double vy = x.x() > 0 ? c0 * cantilever_mode_velocity(x.x(), s.L, s.Vf) : 0.0;
      const sph::Vec2 shake = s.perturbation > 0 ? sph::Vec2(jitter(rng), jitter(rng)) : sph::Vec2::Zero();
      p.body.add(x + shake, sph::Vec2(0.0, vy), m, rho0);
      // The tip: last column, the row nearest the mid-plane (lower of the two middle rows if ny is even).
      const double score = std::abs(i - (nx - 1)) * 1e6 + std::abs(x.y() - 0.5 * s.H + 0.25 * s.dp);
      if (score < best) { best = score; p.tip = p.body.size() - 1; }
    }
  const int layers = s.clamp_layers;
  for (int l = 0; l < layers; ++l) {
    for (int i = -layers; i < static_cast<int>(std::lround(ncols_clamp)); ++i) {
      const double x = x0 + (i + 0.5) * s.dp;
      p.body.add({x, -(l + gap) * s.dp}, {0, 0}, m, rho0, sph::Motion::Fixed);
      p.body.add({x, s.H + (l + gap) * s.dp}, {0, 0}, m, rho0, sph::Motion::Fixed);
    }
    for (int j = 0; j < ny; ++j) p.body.add({x0 - (l + 0.5) * s.dp, (j + first) * s.dp}, {0, 0}, m, rho0, sph::Motion::Fixed);
  }
  const double margin = 0.6 * s.L;  // the tip swings by ~Vf L / (kL)... well inside this at the paper's Vf
  p.body.dp = s.dp;
  p.body.box = {x0 - (layers + 1) * s.dp, -margin, s.L + s.dp, s.H + margin, false, false};
  return p;
}

}  // namespace scenes
