// Gray 2001's plate for independent codes (make peers, issue 44; one such tool per scene, peer_<scene>.cpp),
// and our measurement of the tip trace they return.
//
//   --action layout   writes the scene as we build it: layout.csv (one row per particle: position, velocity,
//                     mass, density, fixed flag, the tracked tip) and settings.csv (name,value: every scheme
//                     parameter the peer needs, our time step and run length), so a peer starts from our
//                     particles, not a re-derivation of them.
//   --action measure  reads the peer's trace (--trace: columns t,y_tip for the plate) and measures it with the
//                     functions our own drivers use (scenes::zero_crossings, period_from_crossings,
//                     half_cycle_extremes): values_peer_plate.csv.
// Parameters (source): the plate of Gray, Monaghan & Swift 2001 Sec 7.1 as Tables 1-2 run it here
//   (scenes::table_plate_run, which experiments/gray2001/gray2001_table1_2_plate_periods.cpp runs: L = 20,
//   clamp 2, 3 layers, sample 0.5, stop at the tip's first zero crossing, T = 2 t_1, t_end 2 thin-plate
//   periods); the scheme's defaults from src/updated_lagrangian/parameters.hpp (mu set per row).
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "core/kernels.hpp"
#include "core/materials.hpp"
#include "frame/driver.hpp"
#include "gray2001/scenes/plate_run.hpp"

int main(int argc, char** argv) {
  sph::Driver d("peer_plate", "peers", "our plate written for independent codes, and their tip traces measured");
  std::string action = "layout", trace;
  double dp = 0.2, H = 2.0, clamp = 2.0, Vf = 0.01, periods = 2.0;
  int crossings = 1;
  sph::GrayParameters scheme;
  d.param("action", action, "layout: write our particles and settings; measure: measure a peer's trace").one_of({"layout", "measure"});
  d.param("trace", trace, "the peer's trace (action measure): CSV with columns t,y_tip");
  d.param("dp", dp, "particle spacing (H/dp an integer)").positive();
  d.param("H", H, "plate thickness").positive();
  d.param("clamp-length", clamp, "plate length held between the fixed layers").non_negative();
  d.param("Vf", Vf, "tip speed of the initial mode / c0").positive();
  d.param("mu", scheme.mu, "shear modulus / (rho0 c0^2)").positive();
  d.param("cfl", scheme.cfl, "time-step factor: dt = cfl h / (c_L + V_f)").positive();
  d.param("periods", periods, "longest run in thin-plate periods").positive();
  d.param("crossings", crossings, "the run stops at this zero crossing of the tip").positive();

  return d.run(argc, argv, [&] {
    if (action == "measure") {
      if (trace.empty()) throw std::invalid_argument("--action measure needs --trace <file>");
      const sph::CsvTable t = sph::read_csv(trace);
      const std::size_t ct = t.column("t"), cy = t.column("y_tip");
      // strtod, not stod: a peer may write subnormal numbers (LAMMPS writes 1e-310 and the like), which stod refuses.
      auto number = [&](const std::string& text) {
        char* end = nullptr;
        const double x = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0') throw std::runtime_error(trace + ": '" + text + "' is not a number");
        return x;
      };
      std::vector<scenes::TipSample> samples;
      for (const auto& r : t.rows) {
        const double ti = number(r.at(ct)), yi = number(r.at(cy));
        if (!std::isfinite(ti) || !std::isfinite(yi)) throw std::runtime_error(trace + ": a non-finite sample at t = " + r.at(ct));
        samples.push_back({ti, yi, NAN, NAN, 1});
      }
      if (samples.size() < 3) throw std::runtime_error(trace + ": fewer than 3 samples");
      const auto c = scenes::zero_crossings(samples);
      const auto ext = scenes::half_cycle_extremes(samples);
      d.value("T_sph", scenes::period_from_crossings(c), "period from the tip's zero crossings (our finder)");
      d.value("crossings", static_cast<double>(c.size()), "zero crossings of the tip in the trace");
      d.value("tip_amplitude", ext.empty() ? NAN : std::abs(ext.front()), "first half cycle's extreme |y_tip|");
      d.value("t_last", samples.back().t, "the trace's last sample");
      return;
    }
    const scenes::PlateRunSpec run = scenes::table_plate_run(H, Vf, dp, clamp, scheme, periods, crossings);
    const scenes::Plate plate = scenes::make_plate(run.plate, scheme);
    const sph::ElasticBody& b = plate.body;
    const double h = scheme.h_over_dp * dp;
    const sph::CubicSpline kernel(2);
    const double K = scheme.rho0 * scheme.c0 * scheme.c0;
    const double dt = sph::gray_time_step(scheme, dp, Vf * scheme.c0);
    const double E = sph::young_from_bulk_shear(K, scheme.mu), nu = sph::poisson_ratio_from_bulk_shear(K, scheme.mu);
    auto layout = d.csv("layout.csv", {"x", "y", "u", "v", "m", "rho", "fixed", "tip"});
    for (std::size_t a = 0; a < b.size(); ++a)
      layout.row(b.x[a].x(), b.x[a].y(), b.v[a].x(), b.v[a].y(), b.m[a], b.rho[a], b.motion[a] == sph::Motion::Free ? 0 : 1,
                 a == plate.tip ? 1 : 0);
    auto settings = d.csv("settings.csv", {"name", "value"});
    const std::pair<const char*, double> rows[] = {
        {"dp", dp}, {"h", h}, {"W_dp", kernel.W(dp, h)}, {"rho0", scheme.rho0}, {"c0", scheme.c0}, {"K", K},
        {"mu", scheme.mu}, {"E", E}, {"nu", nu}, {"eps_artificial", scheme.eps_artificial},
        {"n_artificial", static_cast<double>(scheme.n_artificial)}, {"eps_xsph", scheme.eps_xsph}, {"alpha", scheme.alpha},
        {"beta", scheme.beta}, {"dt", dt}, {"t_end", run.t_end}, {"sample_dt", run.sample_dt},
        {"stop_after_crossings", static_cast<double>(run.stop_after_crossings)}, {"particles", static_cast<double>(b.size())}};
    for (const auto& [name, value] : rows) settings.row(name, value);
    d.value("particles", static_cast<double>(b.size()), "particles of the layout, fixed ones included");
    d.value("dt", dt, "our time step for this scene");
  });
}
