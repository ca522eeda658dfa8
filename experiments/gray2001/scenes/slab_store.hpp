// The slab runs in the store of runs (frame/run_store.hpp): a run of Figs 8-10 stepped by a job of its own
// (Makefile run_rules; issue 17) is served to the driver that collects them, bit for bit. The key holds every
// field of SlabRunSpec and a description of what the run's observer wrote (`files_tag`); a stored run is the
// whole SlabRunResult, trace included, and the bytes of the files its observer wrote (the snapshots and frames
// of the main runs), which the collecting driver writes again: those files carry the header of the job that
// stepped the run (its command line names the run: --step-runs).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gray2001/scenes/slab.hpp"

namespace scenes {

struct StoredSlabRun {
  SlabRunResult result;
  std::vector<std::pair<std::string, std::string>> files;  ///< file name (no directory), contents
};

/// The text of the key: the build, the thread count, every field of s and files_tag.
std::string slab_run_key(const SlabRunSpec& s, const std::string& files_tag);

/// The stored run of (s, files_tag), if the store is on and holds it.
std::optional<StoredSlabRun> serve_slab_run(const SlabRunSpec& s, const std::string& files_tag);

/// Stores the run of (s, files_tag) (when the store is on).
void store_slab_run(const SlabRunSpec& s, const std::string& files_tag, const StoredSlabRun& run);

/// A run without an observer (files_tag "none"), served when the store holds it, else stepped and stored: a point
/// of a sweep that a run job steps and the collecting driver reads back (G-stab-rs). A served run's wall_s is the
/// stepping run's.
SlabRunResult run_slab_stored(const SlabRunSpec& s, const std::string& progress_label);

}  // namespace scenes
