#include "gray2001/scenes/rings_trace.hpp"

#include <cmath>

namespace scenes {

void write_rings_trace(const sph::Driver& d, const std::string& filename, const std::vector<RingsSample>& trace) {
  auto out = d.csv(filename, {"t", "kinetic", "kinetic_com", "elastic", "v_left", "v_right", "x_left", "x_right",
                              "min_distance", "contact", "fragments_left", "fragments_right", "stray", "main_share"});
  for (const auto& m : trace)
    out.row(m.t, m.ke, m.ke_com, m.ee, m.v_left, m.v_right, m.x_left, m.x_right,
            std::isfinite(m.min_distance) ? m.min_distance : NAN, m.contact, m.fragments_left, m.fragments_right, m.stray,
            m.main_share);
}

}  // namespace scenes
