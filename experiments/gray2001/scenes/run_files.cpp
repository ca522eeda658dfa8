#include "gray2001/scenes/run_files.hpp"

namespace scenes {

namespace {

// Each result's fields, once, by name (frame/run_folder.hpp): the columns written and read back.
const auto tip_sample = [](auto& s, auto&& f) {
  return f("t", s.t) && f("y", s.y) && f("ke", s.ke) && f("ee", s.ee) && f("fragments", s.fragments) &&
         f("p_art", s.p_art) && f("p_visc", s.p_visc) && f("p_xsph", s.p_xsph);
};
const auto plate_run = [](auto& r, auto&& f) {
  return f("steps", r.steps) && f("particles", r.particles) && f("dt", r.dt) && f("wall_s", r.wall_s) &&
         f("fracture_time", r.fracture_time) && f("blow_up", r.blow_up);
};

const auto rings_sample = [](auto& s, auto&& f) {
  return f("t", s.t) && f("ke", s.ke) && f("ke_com", s.ke_com) && f("ee", s.ee) && f("v_left", s.v_left) &&
         f("v_right", s.v_right) && f("x_left", s.x_left) && f("x_right", s.x_right) && f("min_distance", s.min_distance) &&
         f("contact", s.contact) && f("fragments_left", s.fragments_left) && f("fragments_right", s.fragments_right) &&
         f("stray", s.stray) && f("main_share", s.main_share);
};
const auto rings_run = [](auto& r, auto&& f) {
  return f("steps", r.steps) && f("particles", r.particles) && f("dt", r.dt) && f("wall_s", r.wall_s) &&
         f("contact_start", r.contact_start) && f("contact_end", r.contact_end) && f("rebound_speed", r.rebound_speed) &&
         f("restitution", r.restitution) && f("fracture_time", r.fracture_time) && f("max_fragments", r.max_fragments) &&
         f("max_stray", r.max_stray) && f("min_main_share", r.min_main_share) && f("blow_up", r.blow_up);
};

const auto slab_sample = [](auto& s, auto&& f) {
  return f("t", s.t) && f("extension", s.extension) && f("strain", s.strain) && f("ke", s.ke) && f("ee", s.ee) &&
         f("neck_width", s.neck_width) && f("neck_x", s.neck_x) && f("median_width", s.median_width) &&
         f("closest", s.closest) && f("widest_gap", s.widest_gap) && f("gap_x", s.gap_x) && f("pieces", s.pieces) &&
         f("parted", s.parted);
};
const auto slab_run = [](auto& r, auto&& f) {
  return f("steps", r.steps) && f("particles", r.particles) && f("dt", r.dt) && f("wall_s", r.wall_s) &&
         f("first_split_time", r.first_split_time) && f("fracture_time", r.fracture_time) && f("crack_x", r.crack_x) &&
         f("crack_from_junction", r.crack_from_junction) && f("neck_before_fracture", r.neck_before_fracture) &&
         f("onset_strain", r.onset_strain) && f("onset_time", r.onset_time) && f("clumping_time", r.clumping_time) &&
         f("opening_time", r.opening_time) && f("opening_from_junction", r.opening_from_junction) && f("blow_up", r.blow_up);
};

template <class Result, class Run, class Sample>
void write_run(const sph::Driver& d, const std::string& name, const Result& r, Run&& run, Sample&& sample) {
  sph::write_rows(d, name + "_run.csv", std::vector<Result>{r}, run);
  sph::write_rows(d, name + "_trace.csv", r.trace, sample);
}

template <class Result, class Run, class Sample>
Result read_run(const sph::RunFolder& folder, const std::string& name, Run&& run, Sample&& sample) {
  Result r = sph::read_row<Result>(folder, name + "_run.csv", run);
  r.trace = sph::read_rows<typename decltype(r.trace)::value_type>(folder, name + "_trace.csv", sample);
  return r;
}

}  // namespace

void write_plate_run(const sph::Driver& d, const std::string& name, const PlateRunResult& r) {
  write_run(d, name, r, plate_run, tip_sample);
}
PlateRunResult read_plate_run(const sph::RunFolder& folder, const std::string& name) {
  return read_run<PlateRunResult>(folder, name, plate_run, tip_sample);
}

void write_rings_run(const sph::Driver& d, const std::string& name, const RingsRunResult& r) {
  write_run(d, name, r, rings_run, rings_sample);
}
RingsRunResult read_rings_run(const sph::RunFolder& folder, const std::string& name) {
  return read_run<RingsRunResult>(folder, name, rings_run, rings_sample);
}

void write_slab_run(const sph::Driver& d, const std::string& name, const SlabRunResult& r) {
  write_run(d, name, r, slab_run, slab_sample);
}
SlabRunResult read_slab_run(const sph::RunFolder& folder, const std::string& name) {
  return read_run<SlabRunResult>(folder, name, slab_run, slab_sample);
}

}  // namespace scenes
