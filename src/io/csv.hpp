// CSV output with a self-describing header:
//   # driver = ..., # target = ..., # code_version = ..., # date = ..., # param.<name> = <value> ...
//   col1,col2,...
//   rows
// Lines starting with '#' are comments to pandas (comment='#') and to the plotting scripts.
// The file is written as <path>.part and renamed to <path> when closed (io/atomic_output.hpp): by close(), or by the
// destructor when no exception is on its way out (a writer left by an exception is discarded: its .part removed).
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <type_traits>
#include <vector>

#include "io/run_info.hpp"

namespace sph {

class CsvWriter {
 public:
  CsvWriter(const std::filesystem::path& path, const RunInfo& info, std::vector<std::string> columns);
  CsvWriter(CsvWriter&& other) noexcept;
  CsvWriter& operator=(CsvWriter&& other) noexcept;
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;
  /// Closes as close() does, or discards the file while an exception unwinds; a failure to close is recorded
  /// (record_output_failure), as a destructor cannot throw it.
  ~CsvWriter();
  /// Flushes, closes and renames the file to its final name; throws naming the file and errno if any write
  /// failed. Nothing may be written after it.
  void close();

  template <class... T>
  void row(const T&... values) {
    static_assert(sizeof...(T) > 0, "empty row");
    std::vector<std::string> cells{cell(values)...};
    write_cells(cells);
  }
  void write_cells(const std::vector<std::string>& cells);
  const std::filesystem::path& path() const { return path_; }

  /// The text of one cell as row() writes it: a number as its shortest round-trip text, a text quoted if needed.
  template <class T>
  static std::string cell(const T& v) {
    if constexpr (std::is_arithmetic_v<T>) return format_number(static_cast<double>(v));
    else return quote(std::string(v));
  }

 private:
  static std::string quote(const std::string& s);

  void finish() noexcept;  // the destructor's and move assignment's close or discard

  std::filesystem::path path_;
  std::size_t ncols_ = 0;
  std::ofstream out_;
  bool open_ = false;      // false once closed, discarded or moved from
  int uncaught_ = 0;       // std::uncaught_exceptions() at construction: more at destruction = unwinding
};

/// A parsed CSV: the header comments as key/value pairs, column names and string cells.
struct CsvTable {
  std::vector<std::pair<std::string, std::string>> meta;
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  std::string meta_value(const std::string& key) const;
  std::size_t column(const std::string& name) const;  // throws if absent
};
CsvTable read_csv(const std::filesystem::path& path);

}  // namespace sph
