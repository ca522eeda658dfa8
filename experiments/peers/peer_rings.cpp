// Gray 2001's colliding rubber rings (Sec 7.2, Figs 6-7) for independent codes (make peers, issue 44), and our
// measurement of the particle frames they return.
//
//   --action layout   writes the rings as our driver builds them (scenes::make_rings with the settings of
//                     experiments/gray2001/gray2001_fig6_7_rings.cpp at --dp, --gap): layout.csv (one row per
//                     particle: x,y,u,v,m,rho,ring with ring 0 = left, moving +x, 1 = right) and settings.csv
//                     (name,value: every scheme parameter a peer needs, our time step, the run's length and stop
//                     rule and the measurement's settings), so a peer starts from our particles.
//   --action measure  reads a peer's frames (--frames: t,id,x,y,u,v of every particle, experiments/peers/
//                     frames_reader.hpp) and measures them with the code our run_rings measures its samples with
//                     (scenes::RingsProbe, RingsCollision; gray2001/scenes/rings_measure.hpp): values_peer_rings.csv
//                     and trace.csv (the columns of our driver's trace_eps*.csv; elastic energy NaN: frames carry
//                     no stress). The frames are cut where run_rings would have stopped (run_after_contact after
//                     the rings separated), so a peer that ran longer is measured over the same span as ours.
//   --action ours     runs scenes::run_rings at these settings and writes its samples as frames (--frames) and its
//                     summary as values_peer_rings.csv: measuring those frames must give the same values (the
//                     check that the measure action is run_rings's measurement).
// Parameters (source): the rings of Gray, Monaghan & Swift 2001 Sec 7.2 as our driver runs them: radii 3 and 4,
//   mu = 0.22, 0.059 each, dp = 0.1 (--dp), gap 0.2 (--gap; the driver's --quick: dp 0.2, gap 0.4), the scheme's
//   defaults (src/updated_lagrangian/parameters.hpp: h = 1.5 dp, n = 4, XSPH 0.5, alpha = beta = 1, cfl 0.5),
//   eps = 0 (Fig 6) or 0.3 (Fig 7) (--eps); t_max 300, run 60 after separation, samples every 1, fracture link
//   1.5 dp, fragments of >= 10 particles (scenes::RingsRunSpec's defaults, as the driver uses them).
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "core/kernels.hpp"
#include "core/materials.hpp"
#include "frame/driver.hpp"
#include "gray2001/scenes/rings_run.hpp"
#include "gray2001/scenes/rings_trace.hpp"
#include "peers/frames_reader.hpp"

namespace {

struct Params {
  std::string action = "layout", frames;
  scenes::RingsRunSpec run;  // t_max, run_after_contact, sample_dt, fracture_link, min_fragment: the driver's
  double eps = 0.3;
};

void declare(sph::Driver& d, Params& p) {
  scenes::RingsRunSpec& run = p.run;
  d.param("action", p.action, "layout: write our particles and settings; measure: measure a peer's frames").one_of({"layout", "measure", "ours"});
  d.param("frames", p.frames, "the peer's frames (action measure; action ours writes ours there): t,id,x,y,u,v of every particle");
  d.param("dp", run.rings.dp, "particle spacing (Sec 7.2: 0.1)").positive();
  d.param("gap", run.rings.gap, "distance between the rings' outer edges at t = 0 (the driver: 0.2)").non_negative();
  d.param("speed", run.rings.speed, "speed of each ring toward the other / c0 (Sec 7.2: 0.059)").positive();
  d.param("mu", run.scheme.mu, "shear modulus / (rho0 c0^2) (Sec 7.2: 0.22)").positive();
  d.param("cfl", run.scheme.cfl, "time-step factor: dt = cfl h / (c_L + speed)").positive();
  d.param("eps", p.eps, "artificial stress epsilon (0: Fig 6; 0.3: Fig 7)").non_negative();
  d.param("t-max", run.t_max, "longest run (the driver: 300; its eps = 0 run: the eps = 0.3 run's end)").positive();
  d.param("after-contact", run.run_after_contact, "run time after the rings separate (< 0: to t-max, the driver's eps = 0)");
}

// The collision's values, named alike for our run (RingsRunResult) and a peer's frames (RingsCollision), so that
// run_peers.py reads both the same way.
template <class Collision>
void write_collision_values(sph::Driver& d, const Collision& c) {
  const double duration = c.contact_end >= 0 ? c.contact_end - c.contact_start : NAN;
  d.value("restitution", c.restitution, "relative speed after / before (-1: not separated)");
  d.value("rebound_speed", c.rebound_speed, "each ring's speed after the bounce (-1: not separated)");
  d.value("contact_start", c.contact_start, "first sample with the main pieces inside 2h");
  d.value("contact_end", c.contact_end, "first sample out of contact after it (-1: never)");
  d.value("contact_duration", duration, "contact_end - contact_start (NaN: not separated)");
  d.value("max_fragments", static_cast<double>(c.max_fragments), "most fragments of either ring (1 = intact)");
  d.value("min_main_share", c.min_main_share, "smallest share of a ring in its largest piece");
  d.value("max_stray", static_cast<double>(c.max_stray), "most particles outside the fragments");
  d.value("fracture_time", c.fracture_time, "first split of a ring (-1: never)");
}

// --action ours: run_rings's samples as frames and its summary as values (measuring those frames must give them).
void run_ours(sph::Driver& d, const Params& p) {
  if (p.frames.empty()) throw std::invalid_argument("--action ours needs --frames <file>");
  std::ofstream out(p.frames);
  out << "# peer = ours (scenes::run_rings)\nt,id,x,y,u,v\n";
  out.precision(17);
  const auto r = scenes::run_rings(p.run, [&](const sph::GraySolver& solver, const sph::ElasticBody& body) {
    for (std::size_t a = 0; a < body.size(); ++a)
      out << solver.time() << ',' << a << ',' << body.x[a].x() << ',' << body.x[a].y() << ',' << body.v[a].x() << ','
          << body.v[a].y() << '\n';
  });
  if (!out) throw std::runtime_error(p.frames + ": cannot write");
  write_collision_values(d, r);
  d.value("t_last", r.trace.back().t, "the last sample");
  d.value("steps", static_cast<double>(r.steps), "steps taken");
  d.value("wall_s", r.wall_s, "wall time of the run");
}

// --action measure: a peer's frames through run_rings's measurement, cut where run_rings would have stopped.
void measure_frames(sph::Driver& d, const Params& p, const sph::ElasticBody& b, const scenes::RingsProbeSpec& probe_spec) {
  const std::string& frames = p.frames;
  if (frames.empty()) throw std::invalid_argument("--action measure needs --frames <file>");
  const scenes::RingsProbe probe(probe_spec, b.m);
  scenes::RingsCollision collision;
  std::vector<scenes::RingsSample> trace;
  bool stopped = false;
  std::size_t count = 0;
  peers::for_each_frame(frames, b.size(), [&](const peers::Frame& f) {
    if (count++ == 0) {
      // The first frame must be our layout at t = 0: frames of other settings are not measured.
      double worst = 0;
      for (std::size_t a = 0; a < b.size(); ++a) worst = std::max(worst, (f.x[a] - b.x[a]).norm());
      if (f.t != 0 || worst > 1e-6 * p.run.rings.dp)
        throw std::runtime_error(frames + ": the first frame is not this layout at t = 0 (t = " + std::to_string(f.t) +
                                 ", largest distance from our particles " + std::to_string(worst) + ")");
    }
    if (stopped) return;
    trace.push_back(probe(f.t, f.x, f.v, std::numeric_limits<double>::quiet_NaN()));
    collision.add(trace.back());
    stopped = trace.size() > 1 && collision.separated_for(f.t, p.run.run_after_contact);  // run_rings's stop
  });
  if (trace.size() < 2) throw std::runtime_error(frames + ": fewer than 2 frames");
  collision.finish(trace.back(), p.run.rings.speed, false);
  write_collision_values(d, collision);
  d.value("t_last", trace.back().t, "the last sample measured (the frames cut at run_rings's stop)");
  d.value("frames", static_cast<double>(count), "frames in the file");
  scenes::write_rings_trace(d, "trace.csv", trace);
}

// --action layout: our particles (layout.csv) and every setting a peer needs (settings.csv).
void write_layout(sph::Driver& d, const Params& prm, const scenes::Rings& rings, const scenes::RingsProbeSpec& probe_spec) {
  const scenes::RingsRunSpec& run = prm.run;
  const sph::ElasticBody& b = rings.body;
  const auto& p = run.scheme;
  const double h = p.h_over_dp * run.rings.dp;
  const sph::CubicSpline kernel(2);
  const double K = p.rho0 * p.c0 * p.c0;
  const double dt = sph::gray_time_step(p, run.rings.dp, run.rings.speed);  // = GraySolver::time_step(speed), run_rings's dt
  const double E = sph::young_from_bulk_shear(K, p.mu), nu = sph::poisson_ratio_from_bulk_shear(K, p.mu);
  auto layout = d.csv("layout.csv", {"x", "y", "u", "v", "m", "rho", "ring"});
  for (std::size_t a = 0; a < b.size(); ++a)
    layout.row(b.x[a].x(), b.x[a].y(), b.v[a].x(), b.v[a].y(), b.m[a], b.rho[a], a < rings.first_right ? 0 : 1);
  auto settings = d.csv("settings.csv", {"name", "value"});
  const std::pair<const char*, double> rows[] = {
      {"dp", run.rings.dp}, {"gap", run.rings.gap}, {"speed", run.rings.speed}, {"r_inner", run.rings.r_inner},
      {"r_outer", run.rings.r_outer}, {"h", h}, {"support", probe_spec.support}, {"W_dp", kernel.W(run.rings.dp, h)},
      {"rho0", p.rho0}, {"c0", p.c0}, {"K", K}, {"mu", p.mu}, {"E", E}, {"nu", nu}, {"eps_artificial", prm.eps},
      {"n_artificial", static_cast<double>(p.n_artificial)}, {"eps_xsph", p.eps_xsph}, {"alpha", p.alpha},
      {"beta", p.beta}, {"dt", dt}, {"t_max", run.t_max}, {"sample_dt", run.sample_dt},
      {"run_after_contact", run.run_after_contact}, {"fracture_link", run.fracture_link},
      {"min_fragment", static_cast<double>(run.min_fragment)}, {"particles", static_cast<double>(b.size())},
      {"first_right", static_cast<double>(rings.first_right)}};
  for (const auto& [name, value] : rows) settings.row(name, value);
  d.value("particles", static_cast<double>(b.size()), "particles of the two rings");
  d.value("dt", dt, "our time step for this scene");
}

}  // namespace

int main(int argc, char** argv) {
  sph::Driver d("peer_rings", "peers", "our colliding rings written for independent codes, and their frames measured");
  Params p;
  declare(d, p);

  return d.run(argc, argv, [&] {
    p.run.options.artificial_stress = p.eps > 0;  // as the driver (gray2001_fig6_7_rings.cpp)
    p.run.scheme.eps_artificial = p.eps;
    const scenes::Rings rings = scenes::make_rings(p.run.rings, p.run.scheme.rho0);
    const scenes::RingsProbeSpec probe_spec = scenes::rings_probe_spec(p.run, rings);
    if (p.action == "ours") return run_ours(d, p);
    if (p.action == "measure") return measure_frames(d, p, rings.body, probe_spec);
    write_layout(d, p, rings, probe_spec);
  });
}
