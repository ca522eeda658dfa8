// Running the colliding rings of Gray, Monaghan & Swift 2001 Section 7.2 and measuring the collision at every
// sample from the particle state (rings_measure.hpp, which a peer's frames are measured with too): the pieces
// of each ring, contact (a pair of particles of the two rings' main pieces inside the kernel support: the
// rings touch through the ordinary SPH sums, nothing else), the rings' centre-of-mass velocities (rebound
// speed), and the kinetic and elastic energies.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "updated_lagrangian/gray_solver.hpp"
#include "gray2001/scenes/rings.hpp"
#include "gray2001/scenes/rings_measure.hpp"

namespace scenes {

struct RingsRunSpec {
  RingsSpec rings;
  sph::GrayParameters scheme;      ///< mu = 0.22 (Sec 7.2) is the scheme's default (parameters.hpp)
  sph::GrayOptions options;
  double t_max = 300;              ///< the run stops here at the latest
  double run_after_contact = 60;   ///< and this long after the rings have separated (< 0: to t_max)
  double sample_dt = 1.0;
  double fracture_link = 1.5;      ///< pieces are connected components at this link distance / dp
  std::size_t min_fragment = 10;   ///< smallest piece counted as a fragment (rings_measure.hpp)
};


struct RingsRunResult {
  std::vector<RingsSample> trace;
  long steps = 0;
  std::size_t particles = 0;
  double dt = 0, wall_s = 0;
  double contact_start = -1, contact_end = -1;  ///< first and last sample time in contact (end < 0: still)
  double rebound_speed = -1;       ///< (v_right - v_left) / 2 at the end, if the rings separated (else -1)
  double restitution = -1;         ///< relative speed after / before the collision (-1 if not separated)
  double fracture_time = -1;       ///< first time a ring was in more than one fragment
  std::size_t max_fragments = 1;   ///< most fragments of either ring at any sample
  std::size_t max_stray = 0;       ///< most stray particles at any sample
  double min_main_share = 1;       ///< smallest main-piece share of either ring at any sample
  std::string blow_up;
};

/// What the run's samples are measured with: the run's link, minimum fragment, and the solver's support 2h.
RingsProbeSpec rings_probe_spec(const RingsRunSpec& s, const Rings& rings);

/// Runs the collision; `on_sample(solver, body)` is called at every sample.
RingsRunResult run_rings(const RingsRunSpec& s,
                         const std::function<void(const sph::GraySolver&, const sph::ElasticBody&)>& on_sample = {},
                         const std::string& progress_label = "rings");

}  // namespace scenes
