// Hoover, Hoover & Merritt 2004, Fig. 7 (Sec. VIII): the 217-particle hexagon with the pair torques Ldot_ij,
// or the particle torques Ldot_i, rescaled by R and 1/R so that they sum to zero, with dr/dt = <v> and
// <v>_M (arithmetic rho_ij), continuity densities; snapshots after 2 pi. Claim: L held fixed (to round-off).
// Note: torque scaling zeroes the torque of the forces; L = sum m r x v also changes through
// sum m (dr/dt) x v, which vanishes for <v>_M (symmetric weights) but not for the Shepard <v>.
// CHOSEN: dt = 0.05.
#include <cmath>

#include "frame/driver.hpp"
#include "hoover2004/scenes/hexagon.hpp"

using namespace sph;

int main(int argc, char** argv) {
  Driver d("hoover2004_fig7_torque_scaling", "H-fig7", "rotating hexagon with torque scaling");
  scenes::HexagonSetup s;
  scenes::quick_hexagon(scenes::hexagon_params(d, s));
  return d.run(argc, argv, [&] {
    const double pi = std::acos(-1.0);
    s.snapshot_angles = {2 * pi};
    s.track_advection_torque = true;
    scenes::run_and_record(d, s, scenes::variants({"cont/shepard/pair_torque", "cont/shepard/particle_torque",
                                                   "cont/monaghan_arith/pair_torque", "cont/monaghan_arith/particle_torque",
                                                   "cont/v/pair_torque"}));
  });
}
