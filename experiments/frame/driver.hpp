// The common frame of every experiment driver: command line (CLI11), --help, --quick, --out, parameter
// overrides recorded into every output file, the values file read by `make check`, and error handling
// (a bad parameter or a failed run prints one clear line and exits non-zero, never a silent result).
//
// Usage in a driver:
//   int main(int argc, char** argv) {
//     sph::Driver d("gray2001_sec5_dispersion", "G-disp", "Section 5 lattice sums");
//     double h_over_dp = 1.0;  // Gray et al. 2001, Section 5.3
//     d.param("h-over-dp", h_over_dp, "smoothing length over particle spacing");
//     return d.run(argc, argv, [&] { ...; d.value("B_x", bx, "eq 5.21"); });
//   }
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "io/csv.hpp"
#include "io/run_info.hpp"

namespace sph {

class Driver {
 public:
  Driver(std::string name, std::string target, std::string description);

  /// Registers --<name> bound to `var` (its current value is the default shown by --help) and records
  /// the value used in every output header.
  template <class T>
  CLI::Option* param(const std::string& name, T& var, const std::string& help) {
    auto* opt = app_.add_option("--" + name, var, help)->capture_default_str();
    recorders_.emplace_back(name, [&var] { return to_text(var); });
    return opt;
  }
  /// Registers a switch --<name>.
  CLI::Option* flag(const std::string& name, bool& var, const std::string& help);

  /// Parses the command line and runs `body`. Returns the process exit code.
  int run(int argc, char** argv, const std::function<void()>& body);

  bool quick() const { return quick_; }
  /// Sets the target id for a driver that serves several targets (e.g. Tables 1 and 2); call before
  /// writing anything. The default output directory follows unless --out was given.
  void retarget(const std::string& target) {
    target_ = target;
    if (!given("out")) out_ = "results/" + target_;
  }
  /// True when the user set --<name> on the command line (so --quick must not override it).
  bool given(const std::string& name) const { return app_.count("--" + name) > 0; }
  const std::filesystem::path& out_dir() const { return out_; }
  RunInfo info() const;

  /// A CSV in the output directory with the run's header.
  CsvWriter csv(const std::string& filename, std::vector<std::string> columns) const;
  /// Records a reproduced quantity for `make check` (values_<driver>.csv: quantity,value,note).
  void value(const std::string& quantity, double v, const std::string& note = "");

 private:
  template <class T>
  static std::string to_text(const T& v) {
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) return format_number(static_cast<double>(v));
    else if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
    else if constexpr (std::is_same_v<T, std::string>) return v;
    else {
      std::ostringstream s;
      bool first = true;
      for (const auto& x : v) { s << (first ? "" : " ") << to_text(x); first = false; }
      return s.str();
    }
  }

  /// timing_<driver>.csv in the output directory: the wall time of the run and the particle-steps its time
  /// loops took (core/run_loop.hpp), for results/timings.csv.
  void write_timing(double wall_s, long long particle_steps) const;
  std::string name_, target_, description_;
  CLI::App app_;
  bool quick_ = false;
  std::filesystem::path out_;
  std::vector<std::pair<std::string, std::function<std::string()>>> recorders_;
  std::unique_ptr<CsvWriter> values_;
};

}  // namespace sph
