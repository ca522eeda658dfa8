// HDF5 particle snapshots with an XDMF sidecar, so ParaView (or h5py) opens them.
//
// One .h5 file per series: /snapshot_NNNNNN/{position (N x 2), velocity (N x 2), density (N),
// stress (N x 3: xx, yy, xy)} with attributes time and step; root attributes record the run (driver,
// code version, date, parameters). The .xdmf file next to it is a temporal collection of polyvertex
// grids over those datasets. While the series is written, both are <name>.part (io/atomic_output.hpp; the .part
// sidecar, rewritten after every snapshot, points at the .part file, so a running or killed series is readable);
// closing renames the .h5 and writes the final sidecar. A series left by an exception is discarded.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "io/run_info.hpp"

namespace sph {

struct Snapshot {
  double time = 0;
  long step = 0;
  std::vector<Vec2> position, velocity;
  std::vector<double> density;
  std::vector<double> sxx, syy, sxy;  // Cauchy stress components; empty means "not recorded"
};

class SnapshotSeries {
 public:
  /// Creates (truncates) `h5_path` and writes the run's metadata.
  SnapshotSeries(const std::filesystem::path& h5_path, const RunInfo& info);
  /// Closes as close() does, or discards the series while an exception unwinds; a failure is recorded.
  ~SnapshotSeries();
  /// Closes the file and gives it and its sidecar their final names; throws naming the file on failure.
  void close();
  SnapshotSeries(const SnapshotSeries&) = delete;
  SnapshotSeries& operator=(const SnapshotSeries&) = delete;

  void write(const Snapshot& s);
  std::size_t count() const { return entries_.size(); }

 private:
  void write_xdmf(const std::filesystem::path& to, const std::string& h5_name) const;
  std::filesystem::path h5_, xdmf_;
  long file_ = -1;  // hid_t
  int uncaught_ = 0;  // std::uncaught_exceptions() at construction
  struct Entry { std::string group; double time; std::size_t n; bool vel, rho, stress; };
  std::vector<Entry> entries_;
};

/// Reads snapshot `index` (0-based, in write order) back: for tests and post-processing.
Snapshot read_snapshot(const std::filesystem::path& h5_path, std::size_t index);
/// Number of snapshots in a series file.
std::size_t count_snapshots(const std::filesystem::path& h5_path);
/// The run's record in a series file's root attributes (driver, target, code_version, date, param.<name>, given),
/// as the '#' header lines of a CSV hold it: (key, value) in the order of their names.
std::vector<std::pair<std::string, std::string>> snapshot_header(const std::filesystem::path& h5_path);

}  // namespace sph
