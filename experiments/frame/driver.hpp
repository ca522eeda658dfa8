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
//     double h_step = 0.01;
//     d.param("h-step", h_step, "step of the h/dp sweep").positive().quick(0.05);  // --quick: 0.05
//     return d.run(argc, argv, [&] { ...; d.value("B_x", bx, "eq 5.21"); });
//   }
//
// --quick (CI-sized runs checking the same claims) is declared with the parameter: `.quick(v)` on the option
// param() returns. Under --quick, and only when --<name> was not given, the variable takes v; Driver::run applies
// it after parsing and before the body, so every output header records it. param() returns a DriverOption<T> of the
// variable's type T, so v converts to T as in `var = v` (`.quick({4, 6, 8})` for a list, `.quick({})` for none).
// A quick value outside a bound of its option (.positive(), .at_most(x), ...) is a driver defect like such a
// default: std::logic_error at once, whichever is declared first. --help shows it after the help ("--quick: v").
// A quick value that depends on other parameters, or that must be set later in the run, stays in the body as
// `if (d.quick() && !d.given("x")) x = ...;`.
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

namespace detail {
struct OptionState;  // driver.cpp: the CLI11 option, its bounds and its quick value, owned by the Driver
}

/// A registered option of a variable of type T, for the settings beyond name, variable and help. A handle: it
/// stays valid as long as its Driver (e.g. a scene registers options and a driver sets their quick values).
/// Defined in driver.cpp for the parameter types listed at Driver::param.
template <class T>
class DriverOption {
 public:
  DriverOption(detail::OptionState& state, T& var) : s_(&state), var_(&var) {}
  /// A list option takes between min and max values.
  DriverOption& expected(int min, int max);
  /// A list option also takes its values as one comma-separated (or `c`-separated) word.
  DriverOption& delimiter(char c);
  /// Every value must be one of `allowed`.
  DriverOption& one_of(const std::vector<std::string>& allowed);
  /// Every value (of a number or a list of numbers) must be > lo, >= lo, < hi, <= hi: a value out of range
  /// stops the driver before it runs, naming the option, the value and the range. A default (or quick value)
  /// outside its own range is a defect of the driver: it throws std::logic_error at once (every run finds it).
  DriverOption& above(double lo);
  DriverOption& at_least(double lo);
  DriverOption& below(double hi);
  DriverOption& at_most(double hi);
  DriverOption& positive() { return above(0.0); }
  DriverOption& non_negative() { return at_least(0.0); }
  /// The value under --quick: the variable takes `v` after parsing, before the body runs, unless --<name> was
  /// given. Checked against the option's bounds (std::logic_error); shown by --help.
  DriverOption& quick(const T& v);

 private:
  detail::OptionState* s_;
  T* var_;
};

class Driver {
 public:
  Driver(std::string name, std::string target, std::string description);

  ~Driver();

  /// Registers --<name> bound to `var` (its current value is the default shown by --help) and records
  /// the value used in every output header. Defined in driver.cpp for T in bool, int, unsigned, long, double,
  /// std::string and std::vector of int, double, std::string.
  template <class T>
  DriverOption<T> param(const std::string& name, T& var, const std::string& help);
  /// Registers a switch --<name>.
  DriverOption<bool> flag(const std::string& name, bool& var, const std::string& help);
  /// Registers --<name> bound to `var`: an option that says where the run reads its inputs (like --out, where it
  /// writes), not what it computes, so it is not recorded in the headers (frame/run_jobs.hpp's --runs-from).
  DriverOption<std::string> location(const std::string& name, std::string& var, const std::string& help);

  /// Parses the command line, under --quick gives the parameters not given their quick values, and runs `body`.
  /// Returns the process exit code.
  int run(int argc, char** argv, const std::function<void()>& body);

  bool quick() const { return quick_; }
  /// Sets the target id for a driver that serves several targets (e.g. Tables 1 and 2); call before
  /// writing anything. The default output directory follows unless --out was given.
  void retarget(const std::string& target);
  /// True when the user set --<name> on the command line (so --quick must not override it: DriverOption::quick).
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
  /// A new option's state (kept here so that its DriverOption handles stay valid).
  detail::OptionState& add_state(CLI::Option* o, const std::string& help);
  std::unique_ptr<CLI::App> app_;
  std::vector<std::unique_ptr<detail::OptionState>> options_;
  bool quick_ = false;
  std::filesystem::path out_;
  std::vector<std::pair<std::string, std::function<std::string()>>> recorders_;
  std::unique_ptr<CsvWriter> values_;
  bool printing_only_ = false;
};

}  // namespace sph
