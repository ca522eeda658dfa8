// Gray's scenes' runs as files of a run job's folder (frame/run_folder.hpp; issue 45): a run job writes the result of
// its plate, rings or slab run with write_*_run, and the run that collects it reads it back with read_*_run, every
// number as stepped. A result is two tables: <name>_run.csv (its scalars, one row) and <name>_trace.csv (its
// samples); the fields of each are listed once, in run_files.cpp.
#pragma once

#include <string>

#include "frame/run_folder.hpp"
#include "gray2001/scenes/plate_run.hpp"
#include "gray2001/scenes/rings_run.hpp"
#include "gray2001/scenes/slab.hpp"

namespace scenes {

void write_plate_run(const sph::Driver& d, const std::string& name, const PlateRunResult& r);
PlateRunResult read_plate_run(const sph::RunFolder& folder, const std::string& name);

void write_rings_run(const sph::Driver& d, const std::string& name, const RingsRunResult& r);
RingsRunResult read_rings_run(const sph::RunFolder& folder, const std::string& name);

void write_slab_run(const sph::Driver& d, const std::string& name, const SlabRunResult& r);
SlabRunResult read_slab_run(const sph::RunFolder& folder, const std::string& name);

}  // namespace scenes
