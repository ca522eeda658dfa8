// Shared scene code for the 1D bar of Ismail 2009 Chapters 4-5 (I-bar, I-het, I-tens, I-nh1d, bench_tl_bar):
// the SPH-smoothed load pulse (Section 4.6.3.2), a run that records gauge histories, and the measurements
// taken from them (arrival times, plateau amplitudes, errors against T11 = -p(t - x/c), eq 4.37).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "total_lagrangian/solver_1d.hpp"

namespace scenes {

/// A square pressure pulse p0 on [0, duration] (shifted by `smoothing` so the smoothed pulse starts at t = 0)
/// smoothed by an SPH interpolation in time with the modified mollifier of smoothing length `smoothing`
/// (Section 4.6.3.2: "an SPH interpolation of the loading pulse"); smoothing = 0 is the bare square pulse.
class SmoothedPulse {
 public:
  SmoothedPulse(double p0, double duration, double smoothing);
  double operator()(double t) const;          ///< p(t) >= 0 (a pressure; the applied T11 is -p)
  double half_time() const { return smoothing_; }  ///< time of the 50% point of the rising edge
  double duration() const { return duration_; }
  double p0() const { return p0_; }

 private:
  double cdf(double z) const;  // integral of the normalised cover function from -1 to z
  double p0_, duration_, smoothing_;
  std::vector<double> table_;
};

struct GaugeRecord {
  std::vector<double> gauge_x;             ///< requested gauge positions
  std::vector<int> gauge_i;                ///< real particle indices
  std::vector<double> t;                   ///< times of the records
  std::vector<std::vector<double>> T, u;   ///< [gauge][record]: T11 and displacement
  double max_abs_T = 0.0;                  ///< over the whole run and all particles
  bool finite = true;
  int steps = 0;
  double wall_s = 0.0;                     ///< time loop only
  double build_s = 0.0;                    ///< SPH matrices and boundary factors
};

/// Runs `bar` with step dt until t_end (or until max|T| exceeds blowup, if > 0), recording the gauges every
/// `every` steps. `on_step` (optional) is called after each step.
GaugeRecord run_bar(sph::TlSolver1D& bar, double dt, double t_end, const std::vector<double>& gauge_x, int every = 1,
                    double blowup = 0.0, const std::function<void(const sph::TlSolver1D&)>& on_step = nullptr);

/// First time >= t_from at which v crosses `level` (from the side of 0), linearly interpolated; NaN if never.
double crossing_time(const std::vector<double>& t, const std::vector<double>& v, double level, double t_from = 0.0);
/// Mean of v over [t0, t1] (NaN if no sample).
double window_mean(const std::vector<double>& t, const std::vector<double>& v, double t0, double t1);
/// Centroid sum t v / sum v over [t0, t1]: the pulse's arrival, insensitive to the dispersion of its edges.
double centroid_time(const std::vector<double>& t, const std::vector<double>& v, double t0, double t1);
/// RMS of (v - exact(t)) over [t0, t1].
double window_rms_error(const std::vector<double>& t, const std::vector<double>& v,
                        const std::function<double(double)>& exact, double t0, double t1);

/// Interior von Neumann analysis of (4.4) with the lattice operator X X, modified mollifier of support radius h
/// on the lattice of spacing ps: dt_crit = 2 / (c max_k |s(k)|), s(k) = 2 ps sum_j |W'(j ps)| sin(k j ps).
/// Returns dt_crit over h/c.
double lattice_dt_crit_over_h_over_c(double ps, double h);

}  // namespace scenes
