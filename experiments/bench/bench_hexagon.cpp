// Scene benchmark: the rotating 217-particle hexagon of Hoover, Hoover & Merritt 2004 (Sec. VIII) for a fixed
// number of RK4 steps, by MD, standard SPAM and SPAM with <v>_M and pair torque scaling. Writes
// <out>/bench_hexagon.csv with scene,variant,particles,steps,threads,wall_s,particle_steps_per_s,error_name,
// error; the error is |L/L0 - 1| at the end (the quantity the torque scaling is for).
#include <omp.h>

#include <cmath>

#include "frame/driver.hpp"
#include "hoover2004/scenes/hexagon.hpp"

using namespace sph;

int main(int argc, char** argv) {
  Driver d("bench_hexagon", "bench", "rotating hexagon benchmark");
  scenes::HexagonSetup s;
  int steps = 2000;
  d.param("shells", s.shells, "hexagon shells n").positive();
  d.param("dt", s.dt, "RK4 time step").positive();
  d.param("steps", steps, "RK4 steps per variant").positive().quick(100);
  return d.run(argc, argv, [&] {
    s.revolutions = steps * s.dt / s.revolution_time();
    s.sample_every = steps;
    auto out = d.csv("bench_hexagon.csv", {"scene", "variant", "particles", "steps", "threads", "wall_s",
                                           "particle_steps_per_s", "error_name", "error"});
    const double n = static_cast<double>(s.lattice().size());
    for (const char* label : {"md", "cont/v", "cont/monaghan_arith/pair_torque"}) {
      const std::string name = label;
      const auto r = name == "md" ? scenes::run_hexagon_md(s)
                                  : scenes::run_hexagon_spam(s, scenes::spam_options_from_label(name), name);
      out.row("hexagon217", name, n, static_cast<double>(r.steps), static_cast<double>(omp_get_max_threads()), r.wall_s,
              n * r.steps / r.wall_s, "L_change", std::abs(r.L.back() / r.L0 - 1));
    }
  });
}
