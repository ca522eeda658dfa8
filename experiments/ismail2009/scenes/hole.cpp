#include "ismail2009/scenes/hole.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <vector>

#include <Eigen/Eigenvalues>

#include "core/materials.hpp"
#include "core/run_loop.hpp"
#include "frame/progress.hpp"
#include "ismail2009/scenes/domain_2d.hpp"

namespace scenes {

using sph::Vec2;

double max_principal(const sph::Tensor2& T) {
  const double m = 0.5 * (T(0, 0) + T(1, 1)), r = std::hypot(0.5 * (T(0, 0) - T(1, 1)), 0.5 * (T(0, 1) + T(1, 0)));
  return m + r;
}

double heywood_gross_concentration(double q) { return (2.0 + std::pow(1.0 - q, 3)) / (1.0 - q); }

namespace {

/// The body of the sheet p, the loaded edge's traction `load` (x, t); damping in units of omega.
template <class Load>
sph::TlConfig2D hole_body(const HoleParams& p, const Load& load, double omega) {
  auto zero = [](const Vec2&, double) { return 0.0; };
  const auto cond = sph::boundary_condition;
  // Conditions: 0 symmetry x = 0 (u1 = 0, t2 = 0), 1 symmetry y = 0 (u2 = 0, t1 = 0), 2 loaded edge x = a
  // (t1 = traction, t2 = 0), 3 free (top edge and hole).
  std::vector<sph::BoundaryCondition2D> conds{cond(true, zero, false, zero), cond(false, zero, true, zero),
                                              cond(false, load, false, zero), cond(false, zero, false, zero)};
  auto cfg = make_body(quarter_hole_domain(p.a, p.R, 0, 1, 2, 3, 3), conds, p.a / (p.n - 1), p.h_over_ps);
  cfg.rho = p.rho;
  cfg.lame = sph::lame_from_young_poisson(p.E, p.nu);
  cfg.closure = p.variational ? sph::TlConfig2D::Closure::Variational : sph::TlConfig2D::Closure::GhostReflection;
  cfg.damping = p.damping * omega;
  cfg.hourglass = p.hourglass;
  cfg.closure_passes = p.closure_passes;
  cfg.law = p.hooke ? sph::TlConfig2D::Law::Hooke : sph::TlConfig2D::Law::NeoHookean;
  return cfg;
}

}  // namespace

HoleTimes hole_times(const HoleParams& p) {
  const sph::Lame m = sph::lame_from_young_poisson(p.E, p.nu);
  HoleTimes h;
  h.cL = sph::longitudinal_wave_speed(m, p.rho);
  h.cT = sph::transverse_wave_speed(m, p.rho);
  h.t_ramp = p.ramp_transits * p.a / h.cT;
  // The slowest mode of the quarter sheet is shear-dominated (nu = 0.49): omega ~ pi c_T / (4 a). Mass-
  // proportional damping (HoleParams::damping, 6.5 omega) brings it to rest and holds the reflection closure's
  // edge instability (CHOSEN; the thesis's sheet 'comes to rest' without saying how).
  h.omega = M_PI * h.cT / (4.0 * p.a);
  h.t_end = h.t_ramp + p.settle / h.omega;
  return h;
}

double hole_load(const HoleParams& p, const HoleTimes& times, double t) {
  const double s = std::min(t / times.t_ramp, 1.0);
  return p.traction * (s < 1.0 ? std::sin(0.5 * M_PI * s) * std::sin(0.5 * M_PI * s) : 1.0);
}

sph::TlConfig2D hole_config(const HoleParams& p) {
  const HoleTimes h = hole_times(p);
  return hole_body(p, [p, h](const Vec2&, double t) { return hole_load(p, h, t); }, h.omega);
}

HoleStress hole_stress(const HoleParams& p, const sph::TlSolver2D& body, const std::function<sph::Tensor2(int)>& T) {
  const int n = body.n_real();
  std::vector<sph::Tensor2> field(n);
  for (int i = 0; i < n; ++i) field[i] = T(i);
  const int top = body.nearest({0.0, p.R});
  HoleStress s;
  for (int i = 0; i < n; ++i) s.peak_sigma1 = std::max(s.peak_sigma1, max_principal(field[i]));
  s.sigma1_hole_top = max_principal(field[top]);
  for (int i = 0; i < n; ++i) s.smoothed_peak_sigma1 = std::max(s.smoothed_peak_sigma1, max_principal(body.smoothed(i, field)));
  s.smoothed_sigma1_hole_top = max_principal(body.smoothed(top, field));
  return s;
}

namespace {

/// One sample of the run (every 20 steps and the last): the peak particle stress, the fastest particle and the
/// smoothed stress at the particle `top` into r; returns the largest particle speed.
double record_sample(const sph::TlSolver2D& b, int top, HoleResult& r) {
  double pk = 0;
  for (int i = 0; i < b.n_real(); ++i) pk = std::max(pk, max_principal(b.cauchy(i)));
  r.peak_sigma1_dynamic = std::max(r.peak_sigma1_dynamic, pk);
  double vmax = 0;
  for (int i = 0; i < b.n_real(); ++i) {
    const double v = b.velocity(i).norm();
    if (v > vmax) { vmax = v; r.fastest_X = b.X(i); }
  }
  r.history.push_back({b.time(), max_principal(b.smoothed_cauchy(top)), pk, vmax});
  return vmax;
}

/// Least-squares slope of ln vmax over the last 3/omega of the finite samples (at least 3), in units of omega.
void fit_growth_rate(HoleResult& r, double omega) {
  double s0 = 0, st = 0, sy = 0, stt = 0, sty = 0;
  const double t_last = r.history.empty() ? 0.0 : r.history.back().t;
  for (const auto& h : r.history)
    if (h.t >= t_last - 3.0 / omega && h.vmax > 0 && std::isfinite(h.vmax)) {
      const double t = h.t * omega, y = std::log(h.vmax);
      s0 += 1; st += t; sy += y; stt += t * t; sty += t * y;
    }
  if (s0 >= 3) r.growth_rate = (s0 * sty - st * sy) / (s0 * stt - st * st);
}

/// Disorder: distance of each particle's displacement from the mean of its 4 lattice neighbours (+-ps),
/// over the particles that have all four (found through their lattice indices: the sheet's particles sit
/// at (i ps, j ps), i, j in [0, n)), relative to the displacements.
double zigzag(const HoleParams& p, const sph::TlSolver2D& body) {
  const double ps = p.a / (p.n - 1);
  std::vector<int> at(static_cast<std::size_t>(p.n) * p.n, -1);
  auto index = [&](const Vec2& X) { return static_cast<long>(std::lround(X.y() / ps)) * p.n + std::lround(X.x() / ps); };
  for (int i = 0; i < body.n_real(); ++i) at[index(body.X(i))] = i;
  double num = 0, den = 0;
  for (int i = 0; i < body.n_real(); ++i) {
    const long ix = std::lround(body.X(i).x() / ps), iy = std::lround(body.X(i).y() / ps);
    if (ix == 0 || iy == 0 || ix == p.n - 1 || iy == p.n - 1) continue;
    Vec2 mean = Vec2::Zero();
    bool all4 = true;
    for (const long q : {iy * p.n + ix + 1, iy * p.n + ix - 1, (iy + 1) * p.n + ix, (iy - 1) * p.n + ix}) {
      if (at[q] < 0) { all4 = false; break; }
      mean += body.u(at[q]);
    }
    if (all4) { num += (body.u(i) - mean / 4).squaredNorm(); den += body.u(i).squaredNorm(); }
  }
  return std::sqrt(num / std::max(den, 1e-300));
}

/// The finite sheet at the end: its stress readout, the change of the smoothed (0, R) stress since top_before,
/// its speeds against those of the run, and its disorder.
void measure_at_rest(const HoleParams& p, const sph::TlSolver2D& body, double top_before, double vmin_after_ramp,
                     HoleResult& r) {
  const HoleStress st = hole_stress(p, body, [&](int i) { return body.cauchy(i); });
  r.peak_sigma1 = st.peak_sigma1;
  r.sigma1_hole_top = st.sigma1_hole_top;
  r.smoothed_peak_sigma1 = st.smoothed_peak_sigma1;
  r.smoothed_sigma1_hole_top = st.smoothed_sigma1_hole_top;
  r.settle_change = std::abs(r.smoothed_sigma1_hole_top - top_before) / r.smoothed_sigma1_hole_top;
  if (!r.history.empty() && vmin_after_ramp > 0 && std::isfinite(vmin_after_ramp))
    r.speed_rise = r.history.back().vmax / vmin_after_ramp;
  double vpeak = 0;
  for (const auto& h : r.history) vpeak = std::max(vpeak, h.vmax);
  if (vpeak > 0) r.rest_speed_ratio = r.history.back().vmax / vpeak;
  r.zigzag = zigzag(p, body);
}

}  // namespace

HoleResult run_hole(const HoleParams& p, const std::vector<double>& snapshot_fractions,
                    const std::function<void(const sph::TlSolver2D&, double)>& snapshot) {
  if (p.n < 5) throw std::invalid_argument("run_hole: n >= 5");
  const HoleTimes times = hole_times(p);
  const double cL = times.cL, t_ramp = times.t_ramp, omega = times.omega, t_end = times.t_end;
  sph::TlSolver2D body(hole_config(p));
  HoleResult r;
  r.particles = body.n_real();
  r.build_s = body.build_seconds();
  const double dt = p.dt_factor * body.h() / cL;
  const int n = static_cast<int>(std::ceil(t_end / dt));
  std::size_t next_snap = 0;
  const int top = body.nearest({0.0, p.R});
  double top_before = std::numeric_limits<double>::quiet_NaN();  // smoothed (0, R) stress 1/omega before the end
  double vmin_after_ramp = std::numeric_limits<double>::infinity();
  sph::Progress progress("hole sheet " + std::to_string(p.n) + " x " + std::to_string(p.n), t_end);
  auto observe = [&](const sph::TlSolver2D& b) {
    if (b.steps() == 0) return false;
    const long s = b.steps() - 1;  // index of the step just taken
    if (s % 20 == 0 || s == n - 1) {
      const double vmax = record_sample(b, top, r);
      if (b.time() > t_ramp) vmin_after_ramp = std::min(vmin_after_ramp, vmax);
    }
    if (std::isnan(top_before) && b.time() >= t_end - 1.0 / omega) top_before = max_principal(b.smoothed_cauchy(top));
    while (snapshot && next_snap < snapshot_fractions.size() && b.time() >= snapshot_fractions[next_snap] * t_end) {
      snapshot(b, b.time());
      ++next_snap;
    }
    return false;
  };
  const auto outcome = sph::run(body, {dt, n}, observe, [&](const sph::TlSolver2D& b) { progress.update(b.time(), b.steps()); });
  r.steps = static_cast<int>(outcome.steps);
  r.finite = !outcome.blew_up();
  fit_growth_rate(r, omega);
  r.wall_s = outcome.wall_s;
  if (r.finite) {
    measure_at_rest(p, body, top_before, vmin_after_ramp, r);
    if (snapshot) snapshot(body, body.time());
  }
  return r;
}

HoleParams linear_edge_run(HoleParams p) {
  p.hooke = true;
  p.traction = 0.01 * p.traction;
  p.damping = 0;
  p.hourglass = 0;
  p.settle = 12;
  return p;
}

EdgeSpectrum edge_spectrum(const HoleParams& p) {
  const auto start = std::chrono::steady_clock::now();
  const double ps = p.a / (p.n - 1);
  const sph::Lame m = sph::lame_from_young_poisson(p.E, p.nu);
  const double cL = sph::longitudinal_wave_speed(m, p.rho), cT = sph::transverse_wave_speed(m, p.rho);
  const double omega = M_PI * cT / (4.0 * p.a);  // as run_hole
  // run_hole's body, linear, undamped, uncontrolled and unloaded (the operator is linear: a load only shifts the state).
  HoleParams q = p;
  q.hooke = true;
  q.damping = 0;
  q.hourglass = 0;
  sph::TlSolver2D body(hole_body(q, [](const Vec2&, double) { return 0.0; }, omega));
  const int nr = body.n_real(), N = 2 * nr;
  // From u_0 = u_-1 = eps e_j one central-difference step gives u_1 = u_0 + dt^2 J u_0. A component the step
  // pins (Dirichlet) comes back as 0 and is not a degree of freedom.
  const double dt = 0.05 * body.h() / cL, eps = 1e-6 * ps;
  Eigen::MatrixXd J(N, N);
  std::vector<int> free_dof;
  for (int j = 0; j < N; ++j) {
    const int pj = j / 2, cj = j % 2;
    const Vec2 Xj = body.X(pj);
    body.set_initial_displacement([&](const Vec2& X) {
      Vec2 u = Vec2::Zero();
      if ((X - Xj).norm() < 1e-9 * p.a) u[cj] = eps;
      return u;
    });
    body.step(dt);
    for (int i = 0; i < nr; ++i)
      for (int c = 0; c < 2; ++c) J(2 * i + c, j) = (body.u(i)[c] - (i == pj && c == cj ? eps : 0.0)) / (dt * dt * eps);
    if (std::abs(body.u(pj)[cj] - eps) < 0.5 * eps) free_dof.push_back(j);
  }
  const int F = static_cast<int>(free_dof.size());
  Eigen::MatrixXd K(F, F);
  for (int r = 0; r < F; ++r)
    for (int c = 0; c < F; ++c) K(r, c) = J(free_dof[r], free_dof[c]);
  Eigen::EigenSolver<Eigen::MatrixXd> es(K, true);
  EdgeSpectrum out;
  out.dof = F;
  int worst = 0;
  for (int k = 0; k < F; ++k) {
    const double rate = std::abs(std::sqrt(es.eigenvalues()[k]).real()) / omega;
    if (rate > 1e-6) ++out.growing;
    if (rate > out.rate) out.rate = rate, worst = k;
  }
  out.lambda_re = es.eigenvalues()[worst].real() / (omega * omega);
  out.lambda_im = std::abs(es.eigenvalues()[worst].imag()) / (omega * omega);
  const Eigen::VectorXcd v = es.eigenvectors().col(worst);
  std::vector<double> amp(nr, 0.0);
  for (int r = 0; r < F; ++r) amp[free_dof[r] / 2] += std::norm(v[r]);
  out.where = body.X(static_cast<int>(std::max_element(amp.begin(), amp.end()) - amp.begin()));
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace scenes
