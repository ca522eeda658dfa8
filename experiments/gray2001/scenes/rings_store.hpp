// The rings' runs in the store of runs (frame/run_store.hpp): a run of the stability sweeps (G-stab-rs) stepped by a
// job of its own (Makefile run_rules; issue 17) is served to the driver that collects them, bit for bit. The key
// holds every field of RingsRunSpec; a stored run is the whole RingsRunResult, trace included. Runs with an observer
// (the snapshots of Figs 6-7) are not stored: only runs without one go through here.
#pragma once

#include <string>

#include "gray2001/scenes/rings_run.hpp"

namespace scenes {

/// The text of the key: the build, the thread count and every field of s.
std::string rings_run_key(const RingsRunSpec& s);

/// The run of s served when the store holds it, else stepped (without an observer) and stored when the store is
/// on. A served run's wall_s is the stepping run's.
RingsRunResult run_rings_stored(const RingsRunSpec& s, const std::string& progress_label);

}  // namespace scenes
