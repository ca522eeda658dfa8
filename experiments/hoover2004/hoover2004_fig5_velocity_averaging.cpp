// Hoover, Hoover & Merritt 2004, Fig. 5 (Secs. IV, VI): the 217-particle hexagon with dr/dt = <v> (Shepard)
// and <v>_M (Monaghan; arithmetic rho_ij, and geometric as an extra), continuity densities from
// rho(0) = sqrt(4/3), with the usual continuity equation (top rows) and its chain-rule form with the averaged
// velocities (bottom rows); snapshots at 2 pi/3 and 2 pi. Claim: with velocity averaging the hexagon keeps
// its shape for a revolution, Monaghan's form best. CHOSEN: dt = 0.05.
#include <cmath>

#include "frame/driver.hpp"
#include "hoover2004/scenes/hexagon.hpp"

using namespace sph;

int main(int argc, char** argv) {
  Driver d("hoover2004_fig5_velocity_averaging", "H-fig5", "rotating hexagon with velocity averaging: snapshots");
  scenes::HexagonSetup s;
  scenes::quick_hexagon(scenes::hexagon_params(d, s));
  return d.run(argc, argv, [&] {
    const double pi = std::acos(-1.0);
    s.snapshot_angles = {2 * pi / 3, 2 * pi};
    scenes::run_and_record(d, s, scenes::variants({"cont/shepard", "cont/monaghan_arith", "cont/shepard/chain",
                                                   "cont/monaghan_arith/chain", "cont/monaghan_geom", "cont/v"}));
  });
}
