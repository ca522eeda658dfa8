// The strain and stress waves of Ismail 2009 Section 5.4.2 (Figs 5.7-5.9) in the 2D strip, shared by I-2d's driver
// (experiments/ismail2009/ismail2009_fig5_7to5_12_neohookean_2d.cpp) and the peers' tool (experiments/peers/
// peer_tl.cpp): the strip as our driver builds it, its run with the gauge records, and the measurements taken from
// the records (wave speed by pulse centroids, plateau and its spread across the thickness), so that a peer's
// gauge records are measured by the same function as ours.
#pragma once

#include <string>
#include <vector>

#include "ismail2009/scenes/bar.hpp"
#include "total_lagrangian/body_2d.hpp"

namespace scenes {

/// The strip of Figs 5.7-5.9: [0, L] x [0, (rows - 1) ps] on the square lattice, pulled at x = 0 by the smoothed
/// tensile traction T11 = p(t), held at x = L, its sides held transversely (kind "strain": u2 = 0, free to
/// slide) or free (kind "stress").
struct Wave2DSpec {
  std::string kind = "stress";  ///< "strain" or "stress"
  double rho = 8000, E = 200e9, nu = 0.3, L = 0.15, ps = 0.5e-3, h_over_ps = 3.5;
  double p0 = 1e5, pulse = 5e-6, smooth = 0.5e-6;
  int rows = 6;
  double height() const { return (rows - 1) * ps; }
  /// The gauges: x = L/3 and 2L/3, every row.
  std::vector<double> gauge_x() const { return {L / 3, 2 * L / 3}; }
};

/// Our body of the strip (real particles, ghosts, the boundary conditions; the material of spec).
sph::TlConfig2D wave_body(const Wave2DSpec& spec);
/// Our step, dt = 0.3 h / c_L (h the kernel's support radius), and the run's end, 0.13 m / c_L + pulse + 2 us.
double wave_dt(const Wave2DSpec& spec, double support_radius);
double wave_t_end(const Wave2DSpec& spec);

/// The gauge records: T[g][r][k] = Cauchy T11 at gauge g, row r, at t[k].
struct WaveRecord {
  std::vector<double> t;
  std::vector<std::vector<std::vector<double>>> T;
  std::vector<std::vector<int>> gauge_i;  ///< real particle of gauge g, row r
  long steps = 0;
  double wall_s = 0;
  int particles = 0;                      ///< real particles
};

/// Runs our strip and records every gauge at every step (the time of a record is the time before the step: the
/// stress refers to it). Throws if the run becomes non-finite.
WaveRecord run_wave_2d(const Wave2DSpec& spec);

struct WaveMeasures {
  double speed = 0;             ///< (x2 - x1) / (centroid2 - centroid1), mid-thickness row rows / 2
  double plateau_over_p0 = 0;   ///< mean T11 over the middle 20% of the pulse at gauge 1, mid row, / p0
  double spread_over_p0 = 0;    ///< max over rows of |plateau(row) - plateau(mid row)| / p0
};
/// The measurements of our driver: centroid of T11 over [t50 - pulse/2, t50 + 3 pulse/2], t50 the 50% crossing.
WaveMeasures measure_wave(const Wave2DSpec& spec, const std::vector<double>& t,
                          const std::vector<std::vector<std::vector<double>>>& T);

}  // namespace scenes
