// Hoover, Hoover & Merritt 2004, Fig. 6 (Sec. VI): angular momentum against time for the 217-particle hexagon
// with dr/dt = <v> and <v>_M (arithmetic rho_ij), continuity densities. Claim: L falls to about half its
// initial value in a revolution. Standard SPAM (dr/dt = v) is drawn beside them. CHOSEN: dt = 0.05.
#include <cmath>

#include "frame/driver.hpp"
#include "hoover2004/scenes/hexagon.hpp"

using namespace sph;

int main(int argc, char** argv) {
  Driver d("hoover2004_fig6_angular_momentum", "H-fig6", "rotating hexagon: L(t) with velocity averaging");
  scenes::HexagonSetup s;
  scenes::quick_hexagon(scenes::hexagon_params(d, s));
  return d.run(argc, argv, [&] {
    const double pi = std::acos(-1.0);
    s.snapshot_angles = {2 * pi};
    scenes::run_and_record(d, s, scenes::variants({"cont/shepard", "cont/monaghan_arith", "cont/v"}));
  });
}
