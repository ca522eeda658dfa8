#include "io/csv.hpp"

#include <exception>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "io/atomic_output.hpp"

namespace sph {

// A header value on one line: a line break inside it would end the comment and turn the rest into a
// table line (read as the column names).
static std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

CsvWriter::CsvWriter(const std::filesystem::path& path, const RunInfo& info, std::vector<std::string> columns)
    : path_(path), ncols_(columns.size()), uncaught_(std::uncaught_exceptions()) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  out_.open(partial_path(path));
  if (!out_) throw std::runtime_error(write_error("cannot write", partial_path(path)));
  open_ = true;
  out_ << "# driver = " << one_line(info.driver) << "\n# target = " << one_line(info.target) << "\n";
  if (!info.description.empty()) out_ << "# description = " << one_line(info.description) << "\n";
  out_ << "# code_version = " << code_version() << "\n# date = " << utc_timestamp() << "\n";
  for (const auto& [k, v] : info.parameters) out_ << "# param." << one_line(k) << " = " << one_line(v) << "\n";
  out_ << "# given = ";  // the names set on the command line, separated by spaces (none: empty)
  for (std::size_t i = 0; i < info.given.size(); ++i) out_ << (i ? " " : "") << one_line(info.given[i]);
  out_ << "\n";
  for (std::size_t i = 0; i < columns.size(); ++i) out_ << (i ? "," : "") << quote(columns[i]);
  out_ << "\n";
  if (!out_) throw std::runtime_error(write_error("write failed:", partial_path(path_)));
}

CsvWriter::CsvWriter(CsvWriter&& o) noexcept
    : path_(std::move(o.path_)), ncols_(o.ncols_), out_(std::move(o.out_)), open_(std::exchange(o.open_, false)),
      uncaught_(o.uncaught_) {}

CsvWriter& CsvWriter::operator=(CsvWriter&& o) noexcept {
  if (this != &o) {
    finish();
    path_ = std::move(o.path_);
    ncols_ = o.ncols_;
    out_ = std::move(o.out_);
    open_ = std::exchange(o.open_, false);
    uncaught_ = o.uncaught_;
  }
  return *this;
}

CsvWriter::~CsvWriter() { finish(); }

void CsvWriter::finish() noexcept {
  if (!open_) return;
  close_or_discard(uncaught_, [this] { close(); }, [this] {
    open_ = false;
    out_.close();
    std::filesystem::remove(partial_path(path_));
  });
}

void CsvWriter::close() {
  if (!open_) throw std::logic_error(path_.string() + ": closed twice");
  open_ = false;
  const auto part = partial_path(path_);
  errno = 0;
  out_.flush();
  if (out_) out_.close();
  if (out_.fail()) {
    const std::string message = write_error("write failed:", part);
    std::error_code ec;
    std::filesystem::remove(part, ec);
    throw std::runtime_error(message);
  }
  commit_partial(part, path_);
}

void CsvWriter::write_cells(const std::vector<std::string>& cells) {
  if (cells.size() != ncols_)
    throw std::logic_error(path_.string() + ": row has " + std::to_string(cells.size()) + " cells, header " +
                           std::to_string(ncols_));
  if (!open_) throw std::logic_error(path_.string() + ": row written after close");
  for (std::size_t i = 0; i < cells.size(); ++i) out_ << (i ? "," : "") << cells[i];
  out_ << "\n";
  if (!out_) throw std::runtime_error(write_error("write failed:", partial_path(path_)));
}

std::string CsvWriter::quote(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

static std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::string cur;
  bool in_quotes = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (in_quotes) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') { cur += '"'; ++i; }
      else if (c == '"') in_quotes = false;
      else cur += c;
    } else if (c == '"') in_quotes = true;
    else if (c == ',') { cells.push_back(cur); cur.clear(); }
    else cur += c;
  }
  cells.push_back(cur);
  return cells;
}

// True when `line` ends inside a quoted cell: an odd number of '"' (an escaped "" counts twice).
static bool inside_quotes(const std::string& line) {
  std::size_t n = 0;
  for (char c : line) n += (c == '"');
  return n % 2 != 0;
}

CsvTable read_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  CsvTable t;
  std::string line;
  std::size_t lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty()) continue;
    if (line[0] == '#') {
      const auto eq = line.find(" = ");
      if (eq != std::string::npos) t.meta.emplace_back(line.substr(2, eq - 2), line.substr(eq + 3));
      continue;
    }
    // A quoted cell may hold line breaks (the writer quotes them): join the physical lines.
    const std::size_t first = lineno;
    std::string more;
    while (inside_quotes(line)) {
      if (!std::getline(in, more))
        throw std::runtime_error(path.string() + ":" + std::to_string(first) + ": unterminated quoted cell");
      ++lineno;
      line += "\n" + more;
    }
    if (t.columns.empty()) {
      t.columns = split_csv_line(line);
    } else {
      t.rows.push_back(split_csv_line(line));
      if (t.rows.back().size() != t.columns.size())
        throw std::runtime_error(path.string() + ":" + std::to_string(first) + ": row has " +
                                 std::to_string(t.rows.back().size()) + " cells, header " +
                                 std::to_string(t.columns.size()));
    }
  }
  return t;
}

std::string CsvTable::meta_value(const std::string& key) const {
  for (const auto& [k, v] : meta)
    if (k == key) return v;
  throw std::out_of_range("no header entry '" + key + "'");
}

std::size_t CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  throw std::out_of_range("no column '" + name + "'");
}

}  // namespace sph
