#include "frame/run_folder.hpp"

#include <omp.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <map>
#include <stdexcept>

#include "io/hdf5_snapshot.hpp"

namespace sph {

std::size_t RunTable::index(const std::string& column) const {
  for (std::size_t i = 0; i < t_.columns.size(); ++i)
    if (t_.columns[i] == column) return i;
  throw std::runtime_error(path_.string() + ": no column " + column);
}

const std::string& RunTable::text(std::size_t row, const std::string& column) const {
  const std::size_t j = index(column);
  if (row >= t_.rows.size()) throw std::runtime_error(path_.string() + ": no row " + std::to_string(row + 1));
  return t_.rows[row][j];
}

double RunTable::number(std::size_t row, const std::string& column) const {
  const std::string& cell = text(row, column);
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(cell.c_str(), &end);  // nan, inf and subnormals as written (ERANGE is no error here)
  if (cell.empty() || end != cell.c_str() + cell.size())
    throw std::runtime_error(path_.string() + ": row " + std::to_string(row + 1) + ", column " + column + ": '" + cell +
                             "' is not a number");
  return v;
}

double RunTable::whole(std::size_t row, const std::string& column, double lo, double hi) const {
  const double v = number(row, column);
  if (!(v == std::floor(v) && v >= lo && v <= hi))
    throw std::runtime_error(path_.string() + ": row " + std::to_string(row + 1) + ", column " + column + ": " +
                             text(row, column) + " is not a whole number in range");
  return v;
}

namespace {

std::string value_of(const std::vector<std::pair<std::string, std::string>>& header, const std::string& key) {
  for (const auto& [k, v] : header)
    if (k == key) return v;
  return "(none)";
}

bool modified_tree(const std::string& version) {
  return version.find("dirty") != std::string::npos || version.rfind("unknown", 0) == 0;
}

}  // namespace

RunFolder::RunFolder(std::filesystem::path dir, RunInfo expected, std::vector<std::string> job_options)
    : dir_(std::move(dir)), expected_(std::move(expected)), job_options_(std::move(job_options)) {
  const std::string record = "timing_" + expected_.driver + ".csv";
  if (!std::filesystem::exists(dir_ / record))
    throw std::runtime_error((dir_ / record).string() + ": missing: the run job did not run or did not complete "
                             "(it writes this record last): rerun it");
  const RunTable t = table(record);
  const double threads = t.number(0, "threads");
  if (threads != omp_get_max_threads())
    throw std::runtime_error(t.path().string() + ": the run job ran with " + t.text(0, "threads") + " threads, this run has " +
                             std::to_string(omp_get_max_threads()) + " (the order of the sums decides the bits)");
}

std::filesystem::path RunFolder::existing(const std::string& file) const {
  const auto path = dir_ / file;
  if (!std::filesystem::exists(path))
    throw std::runtime_error(path.string() + ": missing from the run job's folder (written by another version of the "
                             "driver, or removed): rerun the job");
  return path;
}

void RunFolder::check(const std::filesystem::path& path,
                      const std::vector<std::pair<std::string, std::string>>& header) const {
  const std::string where = path.string() + ": ";
  const std::string version = value_of(header, "code_version");
  if (version != code_version())
    throw std::runtime_error(where + "written by code version " + version + ", this run is " + code_version() +
                             ": rerun the run job");
  if (value_of(header, "driver") != expected_.driver || value_of(header, "target") != expected_.target)
    throw std::runtime_error(where + "written by " + value_of(header, "driver") + " for " + value_of(header, "target") +
                             ", not by this run's driver " + expected_.driver + " for " + expected_.target);
  if (modified_tree(version)) {
    std::error_code ec;
    const auto built = std::filesystem::last_write_time("/proc/self/exe", ec);
    if (!ec && std::filesystem::last_write_time(path) < built)
      throw std::runtime_error(where + "written before this binary was built, and the code version " + version +
                               " names no one build: rerun the run job");
  }
  // Every parameter line, both ways, but the job's own options.
  auto job_option = [&](const std::string& k) {
    return std::find(job_options_.begin(), job_options_.end(), k) != job_options_.end();
  };
  std::map<std::string, std::string> theirs, ours;
  for (const auto& [k, v] : header)
    if (k.rfind("param.", 0) == 0 && !job_option(k.substr(6))) theirs[k.substr(6)] = v;
  for (const auto& [k, v] : expected_.parameters)
    if (!job_option(k)) ours[k] = v;
  for (const auto& [k, v] : ours) {
    const auto it = theirs.find(k);
    if (it == theirs.end())
      throw std::runtime_error(where + "written without the parameter --" + k + ", which this run has (" + v + ")");
    if (it->second != v)
      throw std::runtime_error(where + "written with --" + k + " " + it->second + ", this run has --" + k + " " + v);
  }
  for (const auto& [k, v] : theirs)
    if (!ours.count(k)) throw std::runtime_error(where + "written with a parameter --" + k + " (" + v + ") this run has not");
}

RunTable RunFolder::table(const std::string& file) const {
  const auto path = existing(file);
  CsvTable t = read_csv(path);
  check(path, t.meta);
  return RunTable(path, std::move(t));
}

std::filesystem::path RunFolder::snapshots(const std::string& file) const {
  const auto path = existing(file);
  check(path, snapshot_header(path));
  return path;
}

void rewrite_table(const RunFolder& folder, const Driver& d, const std::string& file) {
  const RunTable t = folder.table(file);
  auto out = d.csv(file, t.columns());
  std::vector<std::string> cells(t.columns().size());
  for (std::size_t i = 0; i < t.rows(); ++i) {
    for (std::size_t j = 0; j < cells.size(); ++j) cells[j] = CsvWriter::cell(t.number(i, t.columns()[j]));
    out.write_cells(cells);
  }
}

void rewrite_snapshots(const RunFolder& folder, const Driver& d, const std::string& file) {
  const auto path = folder.snapshots(file);
  SnapshotSeries out(d.out_dir() / file, d.info());
  const std::size_t n = count_snapshots(path);
  for (std::size_t i = 0; i < n; ++i) out.write(read_snapshot(path, i));
}

}  // namespace sph
