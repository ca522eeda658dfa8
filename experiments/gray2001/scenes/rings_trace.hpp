// The rings' trace as a CSV (one row per sample, scenes::RingsSample's fields): the columns of
// gray2001_fig6_7_rings's trace_eps*.csv, which peer_rings's measure action writes too, so that a peer's measured
// trace reads as ours.
#pragma once

#include <string>
#include <vector>

#include "frame/driver.hpp"
#include "gray2001/scenes/rings_measure.hpp"

namespace scenes {

/// Writes `trace` to `filename` in d's output folder (min_distance beyond the support, inf, as NaN).
void write_rings_trace(const sph::Driver& d, const std::string& filename, const std::vector<RingsSample>& trace);

}  // namespace scenes
