#include "hoover2004/scenes/hexagon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "frame/driver.hpp"
#include "io/hdf5_snapshot.hpp"

// The driver side of the hexagon figures (the second and third parts of hexagon.hpp): the options, the variants,
// several runs at once, and their output files and values. The runs themselves: hexagon.cpp.

namespace sph::scenes {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

std::vector<std::string> series_columns() {
  return {"variant", "t", "angle_deg", "L", "L_over_L0", "K", "U", "E", "E_minus_E0", "shape_rms", "rotation_deg",
          "D_over_mR2"};
}
std::vector<std::string> snapshot_columns() { return {"variant", "angle_deg", "i", "x", "y", "rho"}; }

void write_series(CsvWriter& out, const HexagonRun& r, double omega) {
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    const double E = r.K[k] + r.U[k];
    out.row(r.variant, r.t[k], omega * r.t[k] * 180 / kPi, r.L[k], r.L[k] / r.L0, r.K[k], r.U[k], E, E - r.E0,
            r.shape_rms[k], r.angle[k] * 180 / kPi, r.gauss_D[k]);
  }
}

void write_snapshots(CsvWriter& out, const HexagonRun& r) {
  for (std::size_t s = 0; s < r.snapshots.size(); ++s)
    for (std::size_t i = 0; i < r.snapshots[s].size(); ++i)
      out.row(r.variant, r.snapshot_angles[s] * 180 / kPi, static_cast<double>(i), r.snapshots[s][i].x(),
              r.snapshots[s][i].y(), r.snapshot_density[s][i]);
}

HexagonOptions hexagon_params(Driver& d, HexagonSetup& s) {
  return {d.param("shells", s.shells, "hexagon shells n (N = 1 + 3n + 3n^2)").positive(),
          d.param("dt", s.dt, "RK4 time step").positive(),
          d.param("vmax", s.vmax, "rotation speed at the vertices").positive(),
          d.param("revolutions", s.revolutions, "nominal revolutions to follow").positive()};
}

void quick_hexagon(HexagonOptions o) {
  o.dt.quick(0.2);
  o.shells.quick(4);  // 61 particles
}

std::vector<HexagonVariant> variants(const std::vector<std::string>& labels) {
  std::vector<HexagonVariant> v;
  for (const auto& label : labels) v.push_back({label, label == "md" ? SpamOptions{} : spam_options_from_label(label)});
  return v;
}

void write_hdf5_snapshots(const Driver& d, const HexagonRun& r, double omega, double dt) {
  SnapshotSeries h5(d.out_dir() / ("snapshots_" + value_name(r.variant) + ".h5"), d.info());
  for (std::size_t k = 0; k < r.snapshots.size(); ++k) {
    Snapshot s;
    s.time = r.snapshot_angles[k] / omega;
    s.step = std::lround(s.time / dt);
    s.position = r.snapshots[k];
    s.density = r.snapshot_density[k];
    h5.write(s);
  }
}

std::string value_name(const std::string& label) {
  std::string s = label;
  for (char& c : s) if (c == '/') c = '_';
  return s;
}

HexagonRun run_hexagon(const HexagonSetup& s, const HexagonVariant& v) {
  return v.name == "md" ? run_hexagon_md(s) : run_hexagon_spam(s, v.options, v.name);
}

std::vector<HexagonRun> run_hexagons(const HexagonSetup& s, const std::vector<HexagonVariant>& variants) {
  // The runs are independent: one per thread (each run is serial below kSpamParallelMin particles).
  std::vector<HexagonRun> runs(variants.size());
  std::string error;
#pragma omp parallel for schedule(dynamic, 1)
  for (long k = 0; k < static_cast<long>(variants.size()); ++k) {
    try {
      runs[k] = run_hexagon(s, variants[k]);
    } catch (const std::exception& e) {
#pragma omp critical
      error = e.what();
    }
  }
  if (!error.empty()) throw std::runtime_error(error);
  return runs;
}

std::vector<HexagonRun> run_and_record(Driver& d, const HexagonSetup& s, const std::vector<HexagonVariant>& variants) {
  auto runs = run_hexagons(s, variants);
  record_hexagons(d, s, variants, runs);
  return runs;
}

void record_hexagons(Driver& d, const HexagonSetup& s, const std::vector<HexagonVariant>& variants,
                     const std::vector<HexagonRun>& runs) {
  auto series = d.csv("series.csv", series_columns());
  auto snaps = d.csv("snapshots.csv", snapshot_columns());
  for (std::size_t k = 0; k < variants.size(); ++k) {
    const auto& v = variants[k];
    const HexagonRun& r = runs[k];
    write_series(series, r, s.omega());
    write_snapshots(snaps, r);
    if (variants.size() <= 8) write_hdf5_snapshots(d, r, s.omega(), s.dt);  // not for the 72-run sweep
    const std::string n = value_name(v.name);
    for (double a : s.snapshot_angles) {
      const int deg = static_cast<int>(std::lround(a * 180 / kPi));
      d.value("L_over_L0_" + std::to_string(deg) + "deg_" + n, r.L_ratio_at_angle(a, s.omega()), "L/L0 at that nominal angle");
      const std::size_t k = r.sample_at_angle(a, s.omega());
      const double rms = k < r.t.size() ? r.shape_rms[k] : std::numeric_limits<double>::quiet_NaN();
      d.value("shape_rms_" + std::to_string(deg) + "deg_" + n, rms, "rms distance from the best-rotated initial hexagon");
    }
    double dl = 0, de = 0;
    for (std::size_t k = 0; k < r.t.size(); ++k) {
      dl = std::max(dl, std::abs(r.L[k] / r.L0 - 1));
      de = std::max(de, std::abs((r.K[k] + r.U[k]) / r.E0 - 1));
    }
    d.value("max_L_change_" + n, dl, "max |L/L0 - 1| over the run");
    d.value("max_E_change_" + n, de, "max |E/E0 - 1| over the run");
    d.value("failed_at_" + n, r.failed ? r.failed_at : -1.0, "time the run blew up (-1: survived)");
    if (s.track_advection_torque) {
      double res = 0;
      for (std::size_t k = 0; k < r.t.size(); ++k) res = std::max(res, std::abs((r.L[k] - r.L0 - r.advection_torque_integral[k]) / r.L0));
      d.value("max_L_change_less_advection_" + n, res, "max |L - L0 - int sum m (dr/dt) x v dt|/L0: the force torques' part");
    }
  }
}

}  // namespace sph::scenes
