// The measurement of the colliding rings (Gray, Monaghan & Swift 2001 Section 7.2) from the particle state
// alone (positions, velocities, masses), so that scenes::run_rings and a peer's frames (experiments/peers/
// peer_rings.cpp, issue 44) are measured by the same code:
//   RingsProbe      one sample: the pieces of each ring (connected components at the fracture link), the
//                   fragments (pieces of >= min_fragment particles) and stray particles, the rings' centre-of-mass
//                   velocities and positions, the closest pair of the two rings' main pieces and contact;
//   RingsCollision  the collision summary from the samples in time order (contact start and end, fracture time,
//                   most fragments and stray particles, smallest main share; restitution at the end).
// Contact: some pair of particles of the two main pieces closer than the kernel support 2h, i.e. (the cubic
// spline) a pair with W > 0, the pairs through which the rings interact in our solver: the same set as the
// solver's pair list holds (tested as its refresh does: r^2 < (2h)^2 and W(r) > 0).
// Fragments: SPH has no contact algorithm, so a few surface particles of one ring can stay stuck to the other
// after the bounce; they form tiny "pieces" of their ring. A FRAGMENT is therefore a piece of at least
// `min_fragment` particles (CHOSEN 10); the smaller ones are counted as stray particles.
#pragma once

#include <cstddef>
#include <vector>

#include "core/neighbours.hpp"
#include "core/types.hpp"

namespace scenes {

struct RingsSample {
  double t, ke, ke_com, ee;        ///< kinetic (total, of the rings' centre-of-mass motion), elastic energy
  double v_left, v_right;          ///< x velocity of each ring's centre of mass
  double x_left, x_right;          ///< x of each ring's centre of mass
  double min_distance;             ///< closest pair of particles of the two main pieces (inf beyond the support)
  int contact;                     ///< 1 while the main pieces of the two rings interact
  std::size_t fragments_left, fragments_right;  ///< pieces of >= min_fragment particles
  std::size_t stray;               ///< particles outside both rings' fragments (torn off or stuck to the other)
  double main_share;               ///< smaller of the two rings' largest piece / ring size
};

/// What the measurement needs besides the state: particles [0, first_right) are the left ring, the rest the
/// right; box sizes the cell lists (particles outside it are still found); support = 2h of the cubic spline.
struct RingsProbeSpec {
  std::size_t first_right = 0;
  sph::Box2 box;
  double dp = 0, support = 0;
  double fracture_link = 1.5;      ///< pieces are connected components at this link distance / dp
  std::size_t min_fragment = 10;   ///< smallest piece counted as a fragment
};

class RingsProbe {
 public:
  /// Throws std::invalid_argument on a spec that cannot measure (empty ring, non-positive lengths).
  RingsProbe(const RingsProbeSpec& spec, std::vector<double> masses);
  /// One sample of the state at time t; `elastic_energy` is carried into the sample as it is (NaN when the
  /// state has no stresses, as a peer's frames).
  RingsSample operator()(double t, const std::vector<sph::Vec2>& x, const std::vector<sph::Vec2>& v,
                         double elastic_energy) const;
  std::size_t size() const { return m_.size(); }

 private:
  RingsProbeSpec s_;
  std::vector<double> m_;
  std::vector<bool> in_left_, in_right_;
  double mass_l_ = 0, mass_r_ = 0;
};

/// The collision summary, fed the samples in time order (add), then closed (finish).
struct RingsCollision {
  double contact_start = -1, contact_end = -1;  ///< first sample in contact; first sample out of it after (< 0: none)
  double fracture_time = -1;       ///< first time a ring was in more than one fragment
  std::size_t max_fragments = 1;   ///< most fragments of either ring at any sample
  std::size_t max_stray = 0;       ///< most stray particles at any sample
  double min_main_share = 1;       ///< smallest main-piece share of either ring at any sample
  double rebound_speed = -1;       ///< (v_right - v_left) / 2 at the last sample, if the rings separated (else -1)
  double restitution = -1;         ///< rebound speed / approach speed (-1 if not separated)

  void add(const RingsSample& s);
  /// True once the rings have separated and the time since is at least run_after_contact (>= 0): run_rings's stop.
  bool separated_for(double t, double run_after_contact) const;
  /// The rebound from the last sample, if the rings separated and the run went through (not blown up).
  void finish(const RingsSample& last, double speed, bool blew_up);
};

}  // namespace scenes
