// Throughput of the Gray et al. 2001 scheme (make bench): particle-steps per second of the
// predictor-corrector (two force evaluations per step) on 1 and 2 threads, for
//   rings  the layout of PySPH's rings example (dp = 0.05: 17 582 particles here, 17 592 in PySPH): the scene of the speed
//          target (PySPH: ~2.7e5 particle-steps/s on 2 cores; the bar for ours is >= 5e6 on 2 cores and >= 1.8x from 1 to 2 threads)
//   plate  n = 20 particles across H = 2 (Tables 1-2 at twice the tables' default resolution)
//   slab   the slab of Figs 8-10 at the paper's dp = 0.016 (11 844 particles, driven end bands, von Mises
//          return), and without the return (the plastic pass must cost little and nothing when off)
// and, on the plate, the options switched off one by one: a term that is off must cost nothing.
// Writes <out>/bench_gray_scenes.csv with the columns of results/bench.csv.
#include <omp.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "frame/driver.hpp"
#include "core/run_loop.hpp"
#include "updated_lagrangian/gray_solver.hpp"
#include "gray2001/scenes/plate.hpp"
#include "gray2001/scenes/rings.hpp"
#include "gray2001/scenes/slab.hpp"

namespace {

struct Timing { double wall_s; long steps; std::size_t particles; };

Timing time_run(sph::ElasticBody body, const sph::GrayParameters& p, const sph::GrayOptions& o, int threads, int steps) {
  omp_set_num_threads(threads);
  sph::GraySolver solver(body, p, o);
  const double dt = solver.time_step(0.06);
  auto none = [](const sph::GraySolver&) { return false; };
  sph::run(solver, {dt, 5}, none);  // warm-up: first pair collection, page faults
  const auto timed = sph::run(solver, {dt, steps}, none);
  if (timed.blew_up()) throw std::runtime_error(timed.blow_up);
  return {timed.wall_s, steps, body.size()};
}

}  // namespace

int main(int argc, char** argv) {
  sph::Driver d("bench_gray_scenes", "bench", "Throughput of the Gray 2001 scheme on the rings and plate scenes");
  int steps = 200, max_threads = 2;
  d.param("steps", steps, "timed steps per run (after 5 warm-up steps)").positive().quick(5);
  d.param("max-threads", max_threads, "largest thread count (runs 1 and this)").positive();
  double cfl = sph::GrayParameters{}.cfl;  // the scheme's default: the step sets how often the pairs are re-collected
  d.param("cfl", cfl, "time-step factor of every run").positive();
  double skin = sph::GrayParameters{}.skin_over_h;  // the scheme's default
  d.param("skin-over-h", skin, "Verlet skin of the pair list in units of h, every run (0: search every step)").non_negative();
  std::vector<std::string> scenes{"rings", "plate", "slab"};
  d.param("scenes", scenes, "scenes to run, comma-separated (make bench-peer: rings)")
      .delimiter(',')
      .one_of({"rings", "plate", "slab"});
  return d.run(argc, argv, [&] {
    auto out = d.csv("bench_gray_scenes.csv", {"scene", "variant", "particles", "steps", "threads", "wall_s",
                                               "particle_steps_per_s", "error_name", "error"});
    const auto want = [&](const char* s) { return std::find(scenes.begin(), scenes.end(), s) != scenes.end(); };
    struct Variant { const char* name; sph::GrayOptions o; };
    std::vector<int> threads{1};
    if (max_threads > 1) threads.push_back(max_threads);
    // Rings, PySPH layout.
    if (want("rings")) {
      scenes::RingsSpec rs;
      rs.dp = 0.05;
      sph::GrayParameters rp;  // the scheme's defaults: Sec 7.2's mu = 0.22, h = 1.5 dp
      rp.cfl = cfl;
      rp.skin_over_h = skin;
      const auto rings = scenes::make_rings(rs, rp.rho0);
      double rate[3] = {0, 0, 0};
      for (int t : threads) {
        const auto tm = time_run(rings.body, rp, sph::GrayOptions{}, t, steps);
        const double r = tm.particles * static_cast<double>(tm.steps) / tm.wall_s;
        out.row("rings_pysph_layout", "artstress+xsph+visc", tm.particles, tm.steps, t, tm.wall_s, r, "none", NAN);
        rate[t == 1 ? 1 : 2] = r;
      }
      if (max_threads > 1) d.value("rings_scaling_1_to_2_threads", rate[2] / rate[1], "throughput ratio");
      d.value("rings_particle_steps_per_s", rate[max_threads > 1 ? 2 : 1], "on the largest thread count");
    }
    // Plate at n = 20, with each option switched off in turn.
    if (want("plate")) {
      scenes::PlateSpec ps;
      ps.dp = 0.1;
      ps.Vf = 0.01;
      sph::GrayParameters pp;
      pp.cfl = cfl;
      pp.skin_over_h = skin;
      const auto plate = scenes::make_plate(ps, pp);
      sph::GrayOptions full, no_as, no_xsph, no_visc, none;
      no_as.artificial_stress = false;
      no_xsph.xsph = false;
      no_visc.viscosity = false;
      none.artificial_stress = none.xsph = none.viscosity = false;
      for (const Variant& v : {Variant{"artstress+xsph+visc", full}, Variant{"no artificial stress", no_as},
                               Variant{"no xsph", no_xsph}, Variant{"no viscosity", no_visc}, Variant{"none", none}})
        for (int t : threads) {
          if (t == 1 && v.name != std::string("artstress+xsph+visc")) continue;  // variants: largest count only
          const auto tm = time_run(plate.body, pp, v.o, t, steps);
          out.row("plate_n20", v.name, tm.particles, tm.steps, t, tm.wall_s, tm.particles * static_cast<double>(tm.steps) / tm.wall_s,
                  "none", NAN);
        }
    }
    // Slab of Figs 8-10 at the paper's resolution, with and without the plastic return.
    if (want("slab")) {
      scenes::SlabSpec ss;
      ss.dp = 0.016;
      sph::GrayParameters sp = scenes::slab_scheme();
      sp.cfl = cfl;
      sp.skin_over_h = skin;
      const auto slab = scenes::make_slab(ss, sp.rho0);
      sph::GrayOptions plastic = scenes::slab_options(), elastic;
      for (const Variant& v : {Variant{"artstress+xsph+visc+vonmises", plastic}, Variant{"no plasticity", elastic}})
        for (int t : threads) {
          if (t == 1 && !v.o.plasticity) continue;
          const auto tm = time_run(slab.body, sp, v.o, t, steps);
          out.row("slab_dp0.016", v.name, tm.particles, tm.steps, t, tm.wall_s, tm.particles * static_cast<double>(tm.steps) / tm.wall_s,
                  "none", NAN);
        }
    }
  });
}
