#include "ismail2009/scenes/bar.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/kernels.hpp"
#include "core/run_loop.hpp"
#include "total_lagrangian/sph_matrices.hpp"

namespace scenes {

namespace {
constexpr int kTable = 4000;
}

SmoothedPulse::SmoothedPulse(double p0, double duration, double smoothing)
    : p0_(p0), duration_(duration), smoothing_(smoothing) {
  if (!(duration > 0) || smoothing < 0) throw std::invalid_argument("SmoothedPulse: duration > 0, smoothing >= 0");
  if (smoothing > 0.5 * duration) throw std::invalid_argument("SmoothedPulse: smoothing must be <= duration / 2");
  // Cumulative integral of the 1D modified mollifier W(r, 1) on [-1, 1] (trapezoid, 4000 panels; the
  // function is C-infinity so the error is far below 1e-10), normalised to end at exactly 1.
  sph::ModifiedMollifier k(1);
  table_.assign(kTable + 1, 0.0);
  const double dz = 2.0 / kTable;
  for (int i = 1; i <= kTable; ++i) {
    const double z0 = -1.0 + (i - 1) * dz, z1 = z0 + dz;
    table_[i] = table_[i - 1] + 0.5 * dz * (k.W(std::abs(z0), 1.0) + k.W(std::abs(z1), 1.0));
  }
  for (double& v : table_) v /= table_.back();
}

double SmoothedPulse::cdf(double z) const {
  if (z <= -1.0) return 0.0;
  if (z >= 1.0) return 1.0;
  const double s = (z + 1.0) / 2.0 * kTable;
  const int i = std::min(static_cast<int>(s), kTable - 1);
  return table_[i] + (s - i) * (table_[i + 1] - table_[i]);
}

double SmoothedPulse::operator()(double t) const {
  if (smoothing_ == 0.0) return (t >= 0.0 && t < duration_) ? p0_ : 0.0;
  const double a = smoothing_, b = smoothing_ + duration_;  // square pulse on [a, b], smoothed
  return p0_ * (cdf((t - a) / smoothing_) - cdf((t - b) / smoothing_));
}

GaugeRecord run_bar(sph::TlSolver1D& bar, double dt, double t_end, const std::vector<double>& gauge_x, int every,
                    double blowup, const std::function<void(const sph::TlSolver1D&)>& on_step) {
  GaugeRecord r;
  r.gauge_x = gauge_x;
  for (double x : gauge_x) r.gauge_i.push_back(bar.nearest(x));
  r.T.assign(gauge_x.size(), {});
  r.u.assign(gauge_x.size(), {});
  const int n = static_cast<int>(std::ceil(t_end / dt - 1e-9));
  const std::size_t nrec = static_cast<std::size_t>(n / std::max(every, 1) + 1);
  r.t.reserve(nrec);
  for (auto& v : r.T) v.reserve(nrec);
  for (auto& v : r.u) v.reserve(nrec);
  r.build_s = bar.build_seconds();
  double t_stress = bar.time();  // the stress computed in a step refers to the time before it
  long calls = 0;
  auto observe = [&](const sph::TlSolver1D& b) {
    const long s = calls++ - 1;  // index of the step just taken in this run (-1: the start)
    if (s < 0) return false;
    const double m = b.max_abs_stress();
    r.max_abs_T = std::max(r.max_abs_T, m);
    if (on_step) on_step(b);
    if (s % std::max(every, 1) == 0) {
      r.t.push_back(t_stress);
      for (std::size_t g = 0; g < gauge_x.size(); ++g) {
        r.T[g].push_back(b.stress(r.gauge_i[g]));
        r.u[g].push_back(b.u_prev(r.gauge_i[g]));  // u_n, the displacement the stress was computed from
      }
    }
    t_stress = b.time();
    return blowup > 0 && m > blowup;
  };
  const auto outcome = sph::run(bar, {dt, n}, observe);
  r.steps = static_cast<int>(outcome.steps);
  if (outcome.blew_up()) { r.finite = false; r.max_abs_T = std::numeric_limits<double>::infinity(); }
  r.wall_s = outcome.wall_s;
  return r;
}

double crossing_time(const std::vector<double>& t, const std::vector<double>& v, double level, double t_from) {
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i] < t_from) continue;
    const bool crossed = level < 0 ? (v[i] <= level && v[i - 1] > level) : (v[i] >= level && v[i - 1] < level);
    if (crossed) return t[i - 1] + (level - v[i - 1]) / (v[i] - v[i - 1]) * (t[i] - t[i - 1]);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double window_mean(const std::vector<double>& t, const std::vector<double>& v, double t0, double t1) {
  double s = 0;
  int n = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t0 && t[i] <= t1) { s += v[i]; ++n; }
  return n ? s / n : std::numeric_limits<double>::quiet_NaN();
}

double centroid_time(const std::vector<double>& t, const std::vector<double>& v, double t0, double t1) {
  double sv = 0, stv = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t0 && t[i] <= t1) { sv += v[i]; stv += t[i] * v[i]; }
  return sv != 0 ? stv / sv : std::numeric_limits<double>::quiet_NaN();
}

double window_rms_error(const std::vector<double>& t, const std::vector<double>& v,
                        const std::function<double(double)>& exact, double t0, double t1) {
  double s = 0;
  int n = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t0 && t[i] <= t1) { const double e = v[i] - exact(t[i]); s += e * e; ++n; }
  return n ? std::sqrt(s / n) : std::numeric_limits<double>::quiet_NaN();
}

double lattice_dt_crit_over_h_over_c(double ps, double h) {
  const sph::KernelFn k = sph::make_kernel_fn("modified_mollifier", 1, h);
  double smax = 0;
  for (int i = 1; i <= 20000; ++i) {
    const double kk = M_PI / ps * i / 20000.0;
    double s = 0;
    for (int j = 1; j * ps < k.radius; ++j) s += 2 * ps * std::abs(k.dWdr(j * ps)) * std::sin(kk * j * ps);
    smax = std::max(smax, std::abs(s));
  }
  return 2.0 / (smax * h);
}

}  // namespace scenes
