// Work done once (issue 13 item 5): the plate runs that several targets need, stored and reused.
//
// Several targets run the same plate trajectory and stop it at different points: Fig 4's n = 10 plate is also
// the coarse reference of Tables 1 and 2, Table 1's rows are prefixes of the runs of Figs 2, 4 and 5 and of
// the work-precision sweep. A run stores its tip trace (every sample, with the step it was taken at) under the
// key of everything that decides the trajectory and the samples: the plate, the scheme's parameters and
// options, the sample and fracture-check intervals, the thread count, the instruction set and the code version. A later run with
// the same key whose stop (its zero crossings) falls inside the stored trace takes that prefix instead of
// stepping: the same numbers, bit for bit, as stepping would give (the loop's stop is decided at samples, the
// time step is fixed, and no step of the prefix is shortened to meet t_end).
//
// Off unless the environment names a directory, SPH_RUN_CACHE (the Makefile sets <results>/.run_cache), and
// only for a clean code version (not '-dirty', not 'unknown'), so that two different builds never share a key
// (the unit test, one process and one build, sets SPH_RUN_CACHE_ALLOW_DIRTY=1).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gray2001/scenes/plate_run.hpp"

namespace scenes {

/// A stored run: its trace with the step of every sample, and what ends the stored prefix's validity.
struct StoredPlateRun {
  std::vector<TipSample> trace;
  std::vector<long> steps;   ///< solver steps at each sample
  std::vector<double> wall;  ///< seconds of the time loop up to each sample, in the run that stepped it
  double dt = 0, t_end = 0, fracture_time = -1;
  std::size_t particles = 0;
  bool power_budget = false;
};

/// The directory of the store, or "" when reuse is off (no SPH_RUN_CACHE, or a dirty/unknown code version).
std::string plate_run_cache_dir();

/// The text of the key: every field that decides the trajectory and its samples, and the code version.
std::string plate_run_key(const PlateRunSpec& s);

/// The result of `s` served from the store, if a stored run of the same key contains it.
std::optional<PlateRunResult> serve_plate_run(const PlateRunSpec& s, const std::string& dir);

/// Stores a finished run (kept only if it is longer than the run already stored under its key), and removes
/// the runs stored by other code versions.
void store_plate_run(const PlateRunSpec& s, const StoredPlateRun& run, const std::string& dir);

/// The key of a whole run: plate_run_key and every field that decides where the run stops.
std::string plate_whole_run_key(const PlateRunSpec& s);

/// A run served whole when the store holds one of the same whole-run key, else stepped and stored whole (when
/// the store is on): for the points of a sweep, which stop at a fracture, a blow-up or t_end (the prefix store
/// above serves only runs that stop at zero crossings), stepped by run jobs and read back by the collecting
/// driver (G-stab). A served run's wall_s is the stepping run's.
PlateRunResult run_plate_stored(const PlateRunSpec& s, const std::string& progress_label);

}  // namespace scenes
