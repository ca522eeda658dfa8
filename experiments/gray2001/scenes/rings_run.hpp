// Running the colliding rings of Gray, Monaghan & Swift 2001 Section 7.2 and measuring the collision:
// the pieces of each ring (connected components at the fracture link, every sample), contact (a pair of
// particles of the two rings' main pieces inside the kernel support, read from the solver's pair list: the
// rings touch through the ordinary SPH sums, nothing else), the rings' centre-of-mass velocities (rebound
// speed), and the kinetic and elastic energies.
// Fragments: SPH has no contact algorithm, so a few surface particles of one ring can stay stuck to the
// other after the bounce; they form tiny "pieces" of their ring. A FRAGMENT is therefore a piece of at
// least `min_fragment` particles (CHOSEN 10); the smaller ones are counted as stray particles.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "updated_lagrangian/gray_solver.hpp"
#include "gray2001/scenes/rings.hpp"

namespace scenes {

struct RingsRunSpec {
  RingsSpec rings;
  sph::GrayParameters scheme;      ///< mu = 0.22 (Sec 7.2) is the scheme's default (parameters.hpp)
  sph::GrayOptions options;
  double t_max = 300;              ///< the run stops here at the latest
  double run_after_contact = 60;   ///< and this long after the rings have separated (< 0: to t_max)
  double sample_dt = 1.0;
  double fracture_link = 1.5;      ///< pieces are connected components at this link distance / dp
  std::size_t min_fragment = 10;   ///< smallest piece counted as a fragment (see above)
};

struct RingsSample {
  double t, ke, ke_com, ee;        ///< kinetic (total, of the rings' centre-of-mass motion), elastic energy
  double v_left, v_right;          ///< x velocity of each ring's centre of mass
  double x_left, x_right;          ///< x of each ring's centre of mass
  double min_distance;             ///< closest pair of particles of different rings (inf beyond the support)
  int contact;                     ///< 1 while the main pieces of the two rings interact
  std::size_t fragments_left, fragments_right;  ///< pieces of >= min_fragment particles
  std::size_t stray;               ///< particles outside both rings' fragments (torn off or stuck to the other)
  double main_share;               ///< smaller of the two rings' largest piece / ring size
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

/// Runs the collision; `on_sample(solver, body)` is called at every sample.
RingsRunResult run_rings(const RingsRunSpec& s,
                         const std::function<void(const sph::GraySolver&, const sph::ElasticBody&)>& on_sample = {},
                         const std::string& progress_label = "rings");

}  // namespace scenes
