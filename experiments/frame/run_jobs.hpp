// A driver whose simulation runs are jobs of their own (Makefile run_rules; issue 17, issue 45). Its options:
//   --list-runs true      prints the names of the runs it plans (with the other options given) and exits: the Makefile
//                         generates its run jobs from it, ctest run_names_declared checks it;
//   --step-runs <run>     a run job: steps that run only and writes its results into --out (the run's folder,
//                         results/.runs/<target>/<run>/) as ordinary files, nothing else;
//   --runs-from <dir>     the collecting run: reads every run from <dir>/<run>/ (frame/run_folder.hpp, which refuses a
//                         folder that is incomplete or of another version or other parameters), steps none;
//   none of them          steps every run itself.
// --runs-from says where the inputs are, as --out where the outputs go: not recorded in the headers, so that the
// collecting run's files are those of the run that steps everything. One declaration and handling for every driver.
#pragma once

#include <cstdio>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "frame/driver.hpp"
#include "frame/run_folder.hpp"

namespace sph {

class RunJobs {
 public:
  /// `writes`: what a run job writes into its folder (for --help).
  explicit RunJobs(Driver& d, const std::string& writes = "its results") : d_(d) {
    d.param("step-runs", step_, "step only this run (a name --list-runs prints) and write " + writes +
            " into --out, for the run that collects it (Makefile run_rules)");
    d.param("list-runs", list_, "print the names of the runs and exit");
    d.location("runs-from", from_, "read every run from <this folder>/<run>/, as its run job (--step-runs) wrote it, "
               "instead of stepping it");
  }

  /// With --list-runs, prints `names`; with --step-runs <run>, calls step(i) for the run that is names[i] (a name
  /// not among them is refused). True if either was asked: the driver then returns without writing its outputs.
  bool handled(const std::vector<std::string>& names, const std::function<void(std::size_t)>& step) const {
    if (list_) {
      for (const auto& name : names) std::printf("%s\n", name.c_str());
      d_.printing_only();  // nothing ran: no completion record in --out
      return true;
    }
    if (step_.empty()) return false;
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == step_) {
        step(i);
        return true;
      }
    throw std::invalid_argument("--step-runs " + step_ + ": not among this driver's runs with these options "
                                "(--list-runs true prints them)");
  }

  /// The folder of run `name` when this run collects (--runs-from), checked; nullopt when it steps its runs.
  std::optional<RunFolder> folder(const std::string& name) const {
    if (from_.empty()) return std::nullopt;
    return RunFolder(std::filesystem::path(from_) / name, d_.info(), {"step-runs"});
  }

  /// The result of run `name`: read(folder) from its run job's folder when this run collects, else step().
  template <class Read, class Step>
  auto result(const std::string& name, Read&& read, Step&& step) const -> decltype(step()) {
    if (const auto f = folder(name)) return read(*f);
    return step();
  }

 private:
  Driver& d_;
  std::string step_, from_;
  bool list_ = false;
};

}  // namespace sph
