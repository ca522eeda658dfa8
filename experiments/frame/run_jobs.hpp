// A driver whose simulation runs are jobs of their own (Makefile run_rules, experiments/targets.mk T_RUNS; issue 17):
// `--step-runs <names>` steps only those runs into the store of runs (frame/run_store.hpp) and writes nothing else,
// `--list-runs true` prints the names of the runs the driver plans (ctest run_names_declared holds them to the
// declaration), and the collecting run (neither option) reads the stored runs back. One declaration of the two
// options and one handling of them for every such driver.
#pragma once

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "frame/driver.hpp"
#include "frame/run_store.hpp"

namespace sph {

class RunJobs {
 public:
  /// `writes`: what a run job writes besides the store (for --help).
  explicit RunJobs(Driver& d, const std::string& writes = "no output is written") {
    d.param("step-runs", step_only_, "step only these runs (names as printed by --list-runs) into the store of runs "
            "(SPH_RUN_CACHE), for the run that collects them (Makefile run_rules); " + writes);
    d.param("list-runs", list_, "print the names of the runs and exit");
  }

  /// With --list-runs, prints `names`; with --step-runs, calls step(i) for each given name that is names[i]
  /// (step_named_runs). True if either was asked: the driver then returns without writing its outputs.
  bool handled(const std::vector<std::string>& names, const std::function<void(std::size_t)>& step) const {
    if (list_) {
      for (const auto& name : names) std::printf("%s\n", name.c_str());
      return true;
    }
    if (step_only_.empty()) return false;
    step_named_runs(step_only_, names, step);
    return true;
  }

 private:
  std::vector<std::string> step_only_;
  bool list_ = false;
};

}  // namespace sph
