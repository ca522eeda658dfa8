#include "ismail2009/scenes/hole_files.hpp"

namespace scenes {

namespace {

// The fields of each table, once, by name (frame/run_folder.hpp): the columns written and read back.
const auto scalars = [](auto& r, auto&& f) {
  return f("particles", r.particles) && f("steps", r.steps) && f("wall_s", r.wall_s) && f("build_s", r.build_s) &&
         f("peak_sigma1", r.peak_sigma1) && f("sigma1_hole_top", r.sigma1_hole_top) &&
         f("peak_sigma1_dynamic", r.peak_sigma1_dynamic) && f("smoothed_peak_sigma1", r.smoothed_peak_sigma1) &&
         f("smoothed_sigma1_hole_top", r.smoothed_sigma1_hole_top) && f("settle_change", r.settle_change) &&
         f("zigzag", r.zigzag) && f("speed_rise", r.speed_rise) && f("rest_speed_ratio", r.rest_speed_ratio) &&
         f("fastest_X", r.fastest_X.x()) && f("fastest_Y", r.fastest_X.y()) && f("growth_rate", r.growth_rate) &&
         f("finite", r.finite);
};
const auto sample = [](auto& h, auto&& f) {
  return f("t", h.t) && f("smoothed_top", h.smoothed_top) && f("peak", h.peak) && f("vmax", h.vmax);
};

}  // namespace

void write_hole_run(const sph::Driver& d, const std::string& name, const HoleResult& r) {
  sph::write_rows(d, name + "_run.csv", std::vector<HoleResult>{r}, scalars);
  sph::write_rows(d, name + "_history.csv", r.history, sample);
}

HoleResult read_hole_run(const sph::RunFolder& folder, const std::string& name) {
  HoleResult r = sph::read_row<HoleResult>(folder, name + "_run.csv", scalars);
  r.history = sph::read_rows<HoleResult::Sample>(folder, name + "_history.csv", sample);
  return r;
}

}  // namespace scenes
