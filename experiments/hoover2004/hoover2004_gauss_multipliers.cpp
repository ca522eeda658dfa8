// Hoover, Hoover & Merritt 2004, Sec. VII: Gauss's principle holding E and L with the multipliers alpha and
// beta, whose denominator D = m R^2 - L^2/(2K) "vanishes periodically". D >= 0 by Cauchy-Schwarz and D = 0
// exactly for rigid rotation, so it touches zero rather than changing sign; series.csv records
// D/(m R^2) = 1 - L^2/(2 K m R^2) for every run; here the hexagon with Gauss's constraint (dr/dt = v and
// <v>_M), and standard SPAM for comparison. Values: the minima of D/(m R^2) after the start and their times.
// CHOSEN: dt = 0.05; multipliers off while D < 1e-12 m R^2 (the start is an exact rigid rotation).
#include <cmath>

#include "io/csv.hpp"
#include "frame/driver.hpp"
#include "hoover2004/scenes/hexagon.hpp"

using namespace sph;

int main(int argc, char** argv) {
  Driver d("hoover2004_gauss_multipliers", "H-gauss", "Gauss's principle: where the multipliers' denominator vanishes");
  scenes::HexagonSetup s;
  scenes::quick_hexagon(scenes::hexagon_params(d, s));
  return d.run(argc, argv, [&] {
    const double pi = std::acos(-1.0);
    s.snapshot_angles = {2 * pi};
    const auto runs = scenes::run_and_record(d, s, scenes::variants({"cont/v/gauss", "cont/monaghan_arith/gauss", "cont/v", "md"}));
    auto minima = d.csv("denominator_minima.csv", {"variant", "t", "angle_deg", "D_over_mR2"});
    for (const auto& r : runs) {
      // Local minima of D/(m R^2) after the first sample (D = 0 at t = 0: rigid start).
      double global = 1e300;
      int count = 0;
      for (std::size_t k = 2; k + 1 < r.t.size(); ++k) {
        const double a = r.gauss_D[k - 1], b = r.gauss_D[k], c = r.gauss_D[k + 1];
        global = std::min(global, b);
        if (b < a && b <= c) { minima.row(r.variant, r.t[k], s.omega() * r.t[k] * 180 / pi, b); ++count; }
      }
      const std::string n = scenes::value_name(r.variant);
      d.value("min_D_over_mR2_" + n, global, "smallest D/(m R^2) after the start");
      d.value("D_minima_count_" + n, count, "local minima of D/(m R^2) in the run");
      d.value("gauss_floor_hits_" + n, static_cast<double>(r.gauss_floor_hits), "evaluations with the multipliers off");
    }
  });
}
