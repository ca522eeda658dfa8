// The common frame of every experiment driver: command line (CLI11), --help, --quick, --out, parameter
// overrides recorded into every output file, the values file read by `make check`, and error handling
// (a bad parameter or a failed run prints one clear line and exits non-zero, never a silent result).
// CLI11 is included by driver.cpp only: parsing its header took ~10 s of every driver's ~18 s compile (half of
// a fresh build), so param() is defined there for the parameter types drivers use (listed at param below).
//
// Usage in a driver:
//   int main(int argc, char** argv) {
//     sph::Driver d("gray2001_sec5_dispersion", "G-disp", "Section 5 lattice sums");
//     double h_over_dp = 1.0;  // Gray et al. 2001, Section 5.3
//     d.param("h-over-dp", h_over_dp, "smoothing length over particle spacing");
//     return d.run(argc, argv, [&] { ...; d.value("B_x", bx, "eq 5.21"); });
//   }
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "io/csv.hpp"
#include "io/run_info.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace sph {

/// A registered option, for the few settings beyond name, variable and help.
class DriverOption {
 public:
  /// `current` gives the bound variable's numbers (its default when a bound is declared; none for text).
  DriverOption(CLI::Option* o, std::function<std::vector<double>()> current) : o_(o), current_(std::move(current)) {}
  /// A list option takes between min and max values.
  DriverOption& expected(int min, int max);
  /// A list option also takes its values as one comma-separated (or `c`-separated) word.
  DriverOption& delimiter(char c);
  /// Every value must be one of `allowed`.
  DriverOption& one_of(const std::vector<std::string>& allowed);
  /// Every value (of a number or a list of numbers) must be > lo, >= lo, < hi, <= hi: a value out of range
  /// stops the driver before it runs, naming the option, the value and the range. A default outside its
  /// own range is a defect of the driver: it throws std::logic_error at once (every run finds it).
  DriverOption& above(double lo);
  DriverOption& at_least(double lo);
  DriverOption& below(double hi);
  DriverOption& at_most(double hi);
  DriverOption& positive() { return above(0.0); }
  DriverOption& non_negative() { return at_least(0.0); }

 private:
  DriverOption& bound(const char* relation, double limit, bool (*holds)(double, double));
  CLI::Option* o_;
  std::function<std::vector<double>()> current_;
};

class Driver {
 public:
  Driver(std::string name, std::string target, std::string description);

  ~Driver();

  /// Registers --<name> bound to `var` (its current value is the default shown by --help) and records
  /// the value used in every output header. Defined in driver.cpp for T in bool, int, unsigned, long, double,
  /// std::string and std::vector of int, double, std::string.
  template <class T>
  DriverOption param(const std::string& name, T& var, const std::string& help);
  /// Registers a switch --<name>.
  DriverOption flag(const std::string& name, bool& var, const std::string& help);
  /// Registers --<name> bound to `var`: an option that says where the run reads its inputs (like --out, where it
  /// writes), not what it computes, so it is not recorded in the headers (frame/run_jobs.hpp's --runs-from).
  DriverOption location(const std::string& name, std::string& var, const std::string& help);

  /// Parses the command line and runs `body`. Returns the process exit code.
  int run(int argc, char** argv, const std::function<void()>& body);

  bool quick() const { return quick_; }
  /// Sets the target id for a driver that serves several targets (e.g. Tables 1 and 2); call before
  /// writing anything. The default output directory follows unless --out was given.
  void retarget(const std::string& target);
  /// True when the user set --<name> on the command line (so --quick must not override it).
  bool given(const std::string& name) const;
  const std::filesystem::path& out_dir() const { return out_; }
  RunInfo info() const;

  /// A CSV in the output directory with the run's header.
  CsvWriter csv(const std::string& filename, std::vector<std::string> columns) const;
  /// Records a reproduced quantity for `make check` (values_<driver>.csv: quantity,value,note).
  void value(const std::string& quantity, double v, const std::string& note = "");
  /// This run only prints (e.g. --list-runs): no completion record is written, as nothing ran.
  void printing_only() { printing_only_ = true; }

 private:
  /// timing_<driver>.csv in the output directory: the wall time of the run and the particle-steps its time
  /// loops took (core/run_loop.hpp), for results/timings.csv. It is also the run's completion record:
  /// removed before the body starts and written only after it has returned, so that a run that fails, blows
  /// up unhandled or is interrupted leaves its other files without it, and reference/check.py refuses them (as
  /// the run that collects a run job's folder does: frame/run_folder.hpp).
  void write_timing(double wall_s, long long particle_steps) const;
  std::filesystem::path completion_record() const;
  /// Before a run: the output folder exists and is writable (else an error naming --out), and the run's
  /// completion record is removed.
  void prepare_output() const;
  std::string name_, target_, description_;
  std::unique_ptr<CLI::App> app_;
  bool quick_ = false;
  std::filesystem::path out_;
  std::vector<std::pair<std::string, std::function<std::string()>>> recorders_;
  std::unique_ptr<CsvWriter> values_;
  bool printing_only_ = false;
};

}  // namespace sph
