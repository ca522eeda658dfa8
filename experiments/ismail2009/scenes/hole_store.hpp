// The sheet-with-a-hole runs in the store of runs (frame/run_store.hpp): a run of the resolution study stepped
// by a job of its own (Makefile run_rules; issue 17) is served to the driver that collects the study, bit for
// bit. The key holds every field of HoleParams; a stored result is the whole HoleResult, history included.
// run_hole serves and stores runs without snapshots only (a snapshot needs the solver's state).
#pragma once

#include <optional>
#include <string>

#include "ismail2009/scenes/hole.hpp"

namespace scenes {

/// The text of the key: the build, the thread count and every field of p.
std::string hole_run_key(const HoleParams& p);

/// The stored result of p, if the store is on and holds it.
std::optional<HoleResult> serve_hole_run(const HoleParams& p);

/// Stores the result of p (when the store is on).
void store_hole_run(const HoleParams& p, const HoleResult& r);

}  // namespace scenes
