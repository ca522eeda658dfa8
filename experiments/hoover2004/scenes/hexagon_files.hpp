// The hexagon's runs as files of a run job's folder (frame/run_folder.hpp; issue 45): H-72's run job writes the
// result of its combination with write_hexagon_run, and the run that collects them reads it back with
// read_hexagon_run, every number as stepped. Three tables: <name>_run.csv (the scalars, one row), <name>_trace.csv
// (the time series) and <name>_snapshots.csv (the kept positions and densities, by snapshot).
#pragma once

#include <string>

#include "frame/run_folder.hpp"
#include "hoover2004/scenes/hexagon.hpp"

namespace sph::scenes {

void write_hexagon_run(const Driver& d, const std::string& name, const HexagonRun& r);
HexagonRun read_hexagon_run(const RunFolder& folder, const std::string& name);

}  // namespace sph::scenes
