// A run job's folder, as the run that collects it reads it (issue 45; Makefile run_rules).
//
// A run job is a target's driver given one of its simulation runs (--step-runs <run>, frame/run_jobs.hpp) and its
// own folder, results/.runs/<target>/<run>/: it steps that run and writes its results there as ordinary files with
// the usual '#' headers (a table per result, listed once by name: write_rows below and the scenes' *_files.hpp),
// then, last, the driver frame's completion record timing_<driver>.csv. The collecting run (--runs-from) reads the
// files back and refuses, with one line naming the file, a folder
//   - without its completion record (the job did not run, failed or was interrupted: rerun it),
//   - without a file it needs,
//   - whose files were written by another driver or target, another code version, or with other parameters than
//     the collecting run's own (every '# param.' line, but the job's own --step-runs),
//   - whose job ran with another thread count (the order of the sums decides the bits),
//   - written before this binary was built, when the code version is a modified tree's ('-dirty' names no one
//     build: Make reruns the jobs of a rebuilt driver, and this refuses what a hand run would find stale).
// Numbers are read back from the text CsvWriter wrote (their shortest round-trip text), so a run read from its
// folder has every bit of the run stepped.
#pragma once

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "frame/driver.hpp"
#include "io/csv.hpp"
#include "io/run_info.hpp"

namespace sph {

/// A table of a run folder: cells by row and column name, as numbers or texts; a cell that is not what is asked
/// for is refused naming the file, the row and the column.
class RunTable {
 public:
  RunTable(std::filesystem::path path, CsvTable table) : path_(std::move(path)), t_(std::move(table)) {}
  const std::filesystem::path& path() const { return path_; }
  std::size_t rows() const { return t_.rows.size(); }
  const std::vector<std::string>& columns() const { return t_.columns; }
  const std::string& text(std::size_t row, const std::string& column) const;
  double number(std::size_t row, const std::string& column) const;
  /// The cell as a T: a text, a bool (0 or 1), an integer (refused unless a whole number in T's range) or a floating
  /// point number.
  template <class T>
  void get(std::size_t row, const std::string& column, T& v) const {
    if constexpr (std::is_same_v<T, std::string>) v = text(row, column);
    else if constexpr (std::is_floating_point_v<T>) v = static_cast<T>(number(row, column));
    else v = static_cast<T>(whole(row, column, static_cast<double>(std::numeric_limits<T>::lowest()),
                                  static_cast<double>(std::numeric_limits<T>::max())));
  }

 private:
  double whole(std::size_t row, const std::string& column, double lo, double hi) const;
  std::size_t index(const std::string& column) const;
  std::filesystem::path path_;
  CsvTable t_;
};

class RunFolder {
 public:
  /// The folder `dir` of a run job of the run `expected` describes (the collecting run's Driver::info(), taken when
  /// the folder is opened); `job_options`: the parameters a run job sets and the collecting run does not
  /// (--step-runs). Checks the completion record, else throws std::runtime_error naming it.
  RunFolder(std::filesystem::path dir, RunInfo expected, std::vector<std::string> job_options);
  const std::filesystem::path& dir() const { return dir_; }
  /// The table `file` of the folder, its header checked.
  RunTable table(const std::string& file) const;
  /// The path of the HDF5 snapshot series `file` of the folder, its header (root attributes) checked.
  std::filesystem::path snapshots(const std::string& file) const;

 private:
  std::filesystem::path existing(const std::string& file) const;
  void check(const std::filesystem::path& path, const std::vector<std::pair<std::string, std::string>>& header) const;
  std::filesystem::path dir_;
  RunInfo expected_;
  std::vector<std::string> job_options_;
};

// ---------------------------------------------------------------------------------------------------------------
// A result's fields listed once, by name: `fields(r, f)` is `f("t", r.t) && f("y", r.y) && ...` (a generic lambda,
// r const when writing), and the same list writes a table's columns and reads them back. A field is a number, a
// bool or a text (a vector is rows of their own: a table of its own).

namespace run_fields {
struct Names {
  std::vector<std::string>& out;
  template <class T>
  bool operator()(const char* name, const T&) { out.emplace_back(name); return true; }
};
struct Cells {
  std::vector<std::string>& out;
  template <class T>
  bool operator()(const char*, const T& v) { out.push_back(CsvWriter::cell(v)); return true; }
};
struct Reader {
  const RunTable& table;
  std::size_t row;
  template <class T>
  bool operator()(const char* name, T& v) { table.get(row, name, v); return true; }
};
}  // namespace run_fields

/// Writes `rows` as the table `file` of d's output folder, one column per field.
template <class Row, class Fields>
void write_rows(const Driver& d, const std::string& file, const std::vector<Row>& rows, Fields&& fields) {
  std::vector<std::string> columns;
  Row probe{};
  fields(static_cast<const Row&>(probe), run_fields::Names{columns});
  auto out = d.csv(file, columns);
  for (const Row& r : rows) {
    std::vector<std::string> cells;
    fields(r, run_fields::Cells{cells});
    out.write_cells(cells);
  }
}

/// The rows of the table `file` of a run folder, read back by the list that wrote them.
template <class Row, class Fields>
std::vector<Row> read_rows(const RunFolder& folder, const std::string& file, Fields&& fields) {
  const RunTable table = folder.table(file);
  std::vector<Row> rows(table.rows());
  for (std::size_t i = 0; i < rows.size(); ++i) fields(rows[i], run_fields::Reader{table, i});
  return rows;
}

/// The one row of the table `file` (a run's scalars), refused unless it has exactly one.
template <class Row, class Fields>
Row read_row(const RunFolder& folder, const std::string& file, Fields&& fields) {
  auto rows = read_rows<Row>(folder, file, fields);
  if (rows.size() != 1)
    throw std::runtime_error((folder.dir() / file).string() + ": " + std::to_string(rows.size()) + " rows, one expected");
  return std::move(rows.front());
}

// ---------------------------------------------------------------------------------------------------------------
// Files a run job writes as the collecting run's own outputs (the slab's snapshots and frames, G-fig8): read from the
// folder and written again into d's output folder under d's header, as stepping there would have written them.

/// The numeric table `file`, every cell read as a number and written again.
void rewrite_table(const RunFolder& folder, const Driver& d, const std::string& file);
/// The snapshot series `file` (.h5 and its .xdmf), every snapshot read and written again.
void rewrite_snapshots(const RunFolder& folder, const Driver& d, const std::string& file);

}  // namespace sph
