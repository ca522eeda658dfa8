// The sheet-with-a-hole runs as files of a run job's folder (frame/run_folder.hpp; issue 45): a run job of the
// resolution study (I-hole) writes its run's result with write_hole_run, and the run that collects the study reads
// it back with read_hole_run, every number as stepped. Two tables: <name>_run.csv (the scalars, one row) and
// <name>_history.csv (the samples every 20 steps).
#pragma once

#include <string>

#include "frame/run_folder.hpp"
#include "ismail2009/scenes/hole.hpp"

namespace scenes {

void write_hole_run(const sph::Driver& d, const std::string& name, const HoleResult& r);
HoleResult read_hole_run(const sph::RunFolder& folder, const std::string& name);

}  // namespace scenes
