// The rotating hexagon of Hoover, Hoover & Merritt 2004 (Secs. VI-VIII, Figs. 4-7): a regular hexagon of the
// unit triangular lattice with n shells (N = 1 + 3n + 3n^2, 217 for n = 8), stress free, rho = sqrt(4/3),
// in rigid rotation with speed vmax = 0.1 at the vertices (omega = vmax/n), followed for the time 20 n pi
// of one nominal revolution (2 pi / omega). Runs of molecular dynamics or any SPAM variant, sampled into
// time series (L, energies, shape error) and position snapshots at given nominal rotation angles.
// The runs are defined in hexagon.cpp; the drivers' side (options, variants, output files and values) in
// hexagon_record.cpp.
#pragma once

#include <string>
#include <vector>

#include "io/csv.hpp"
#include "core/lattices.hpp"
#include "frame/driver.hpp"
#include "spam/options.hpp"

namespace sph::scenes {

struct HexagonSetup {
  int shells = 8;                  // n = 8, N = 217 (Sec. VIII)
  double vmax = 0.1;               // speed at the vertices (Sec. VI)
  double dt = 0.05;                // CHOSEN (paper silent): RK4 error in L below 1e-9 per revolution for MD
  double revolutions = 1.0;        // nominal revolutions (t_end = revolutions * 2 pi / omega)
  int sample_every = 20;           // steps between time-series samples
  std::vector<double> snapshot_angles;  // nominal rotation angles omega t at which positions are kept
  SpamParams params;               // h = 3, m = 1, lambda = eta = sqrt(3/16)
  bool track_advection_torque = false;  // integrate sum m (dr/dt) x v (one extra evaluation per step)
  double omega() const { return vmax / shells; }
  double revolution_time() const { return 2 * 3.14159265358979323846 / omega(); }
  std::vector<Vec2> lattice() const;
  SpamParams spam_params() const;  // params with a cell-list box around the hexagon
};

struct HexagonRun {
  std::string variant;
  std::vector<double> t, L, K, U, shape_rms, angle, gauss_D, gauss_beta;  // time series; gauss_D = D/(m R^2)
  std::vector<double> snapshot_angles;
  std::vector<std::vector<Vec2>> snapshots;
  std::vector<std::vector<double>> snapshot_density;
  std::vector<double> advection_torque_integral;  // at the samples, when tracked
  double L0 = 0, E0 = 0;
  bool failed = false;     // non-finite state or the body flew apart (shape rms > n)
  double failed_at = -1;
  long steps = 0;
  double wall_s = 0;
  long gauss_floor_hits = 0, reflections = 0;
  /// L / L0 at the first sample with nominal angle >= a (NaN when the run failed before).
  double L_ratio_at_angle(double a, double omega) const;
  /// Index of the first sample at nominal angle >= a (size() when the run stopped before).
  std::size_t sample_at_angle(double a, double omega) const;
};

HexagonRun run_hexagon_md(const HexagonSetup& s);
HexagonRun run_hexagon_spam(const HexagonSetup& s, const SpamOptions& o, const std::string& variant);

/// Writes the time series of several runs (variant,t,angle_deg,L,L_over_L0,K,U,E,shape_rms,rotation_deg,
/// D_over_mR2 = 1 - L^2/(2 K m R^2), the normalised denominator of Gauss's multipliers) and the snapshots (variant,angle_deg,i,x,y,rho) into the output files.

void write_series(CsvWriter& out, const HexagonRun& r, double omega);
void write_snapshots(CsvWriter& out, const HexagonRun& r);
std::vector<std::string> series_columns();
std::vector<std::string> snapshot_columns();

}  // namespace sph::scenes

namespace sph::scenes {

/// A named SPAM variant of the hexagon figures.
struct HexagonVariant { std::string name; SpamOptions options; };

/// Parses "cont/monaghan_arith/chain/pair_torque/visc/approach"-style labels (SpamOptions::label()).
SpamOptions spam_options_from_label(const std::string& label);

}  // namespace sph::scenes

namespace sph::scenes {

/// The hexagon options of a driver, for the quick values of each driver (e.g. `o.dt.quick(0.1)`).
struct HexagonOptions {
  DriverOption<int> shells;
  DriverOption<double> dt, vmax, revolutions;
};
/// Registers the hexagon options on a driver (--shells, --dt, --vmax, --revolutions).
HexagonOptions hexagon_params(Driver& d, HexagonSetup& s);
/// --quick for the hexagon figures: 61 particles (4 shells) and dt = 0.2, unless given on the command line.
void quick_hexagon(HexagonOptions o);
/// The SPAM variants of these labels (spam_options_from_label); "md" is the molecular dynamics reference.
std::vector<HexagonVariant> variants(const std::vector<std::string>& labels);
/// The run of a variant: molecular dynamics for "md", else SPAM with its options.
HexagonRun run_hexagon(const HexagonSetup& s, const HexagonVariant& v);
/// Runs every variant, one per OpenMP thread.
std::vector<HexagonRun> run_hexagons(const HexagonSetup& s, const std::vector<HexagonVariant>& variants);
/// Writes the runs of the variants (runs[k] of variants[k]) as series.csv and snapshots.csv, and records per variant
/// L_over_L0_<a>deg, shape_rms_<a>deg at the snapshot angles, max_L_change and failed_at.
void record_hexagons(Driver& d, const HexagonSetup& s, const std::vector<HexagonVariant>& variants,
                     const std::vector<HexagonRun>& runs);
/// run_hexagons, then record_hexagons.
std::vector<HexagonRun> run_and_record(Driver& d, const HexagonSetup& s, const std::vector<HexagonVariant>& variants);
/// Writes the run's snapshots as <out>/snapshots_<value_name>.h5 (+ .xdmf) for ParaView.
void write_hdf5_snapshots(const Driver& d, const HexagonRun& r, double omega, double dt);
/// The value name of a variant: its label with '/' replaced by '_'.
std::string value_name(const std::string& label);

}  // namespace sph::scenes
