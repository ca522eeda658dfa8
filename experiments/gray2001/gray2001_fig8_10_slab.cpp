// Gray, Monaghan & Swift 2001, Figs 8-10 (Section 7.3): a 3 x 1 slab pulled by its end bands, with
// perfectly plastic von Mises yield. eps = 0 (Fig 8): "unphysical fracture near the junction between the
// particles with forced motion and the other particles ... evident at a time of 119". eps = 0.3 (Figs 9-10):
// intact; necking once the strain exceeds ~0.15 (Fig 10: strain ~0.13 at t = 394); at t = 542 the neck is
// ~10 particles thick and it fractures.
//
// Parameters (source):
//   slab 3 x 1, bands 0.2 wide at each end, acceleration 5e-6 along the long axis   (Sec 7.3)
//   mu = 0.3, von Mises yield strength 0.03 (uniaxial, sqrt(3 J2) = Y with the plane-strain S_zz:
//     src/core/materials.hpp section 6)                                                   (Sec 7.3)
//   rho0 = c0 = 1, h = 1.5 dp, eps = 0.3, n = 4, XSPH eps = 0.5                        (Secs 3, 5, 7)
//   READING of the acceleration: "the ends move a distance 2.5e-6 t^2 ... if t equals 400 the ends will move
//     a distance 0.4 cm, and the strain will be 0.13". Each band accelerating at 5e-6 would move each end
//     5e-6 t^2 / 2 = 2.5e-6 t^2 = 0.4 at t = 400, but the slab would then stretch by 0.8, a strain of
//     0.8 / 3 = 0.27, not 0.13. The numbers agree only if 2.5e-6 t^2 is the change of the ends' SEPARATION,
//     i.e. 5e-6 is the relative acceleration of the two ends: each band accelerates at 2.5e-6 outward
//     (--end-accel, per end), the separation grows by 0.4 at t = 400 and the strain 0.4 / 3 = 0.133
//     (0.129 at t = 394, as the Fig 10 caption). The driver measures the strain at t = 394 from the bands'
//     motion (strain_at_t394); --end-accel 5e-6 runs the other reading.
//   --quick: dp = 0.064, eps = 0.3 to t = 420, no resolution study.
//   dp = 0.016 (Sec 7.3; --dp 0.032 runs 8x faster). The resolution study (--study-dps, default 0.064 and
//     0.032, plus the main dp) gives the fracture time's dependence on dp.
//   slab of round(3 / dp) x round(1 / dp) particles at half-spacings (3/0.016 = 187.5: 188 x 63 at the
//     paper's dp); band = particles whose centre lies within 0.2 of an end (CHOSEN)
//   artificial viscosity alpha = beta = 1, dt = cfl h / (c_L + v_end), cfl = 0.5 (the scheme's default, from G-stab-rs)
// Measured (automatically, every --sample-dt): fracture = the two driven bands are in different pieces
//   at a link distance of 1.5 dp (the G-fig2 criterion applied to the ends); first split = any piece
//   breaks off; neck width = the narrowest x bin (2 dp wide) of the free part, as the y extent of its
//   particles + dp; necking onset = neck width below 0.9 x the median bin width (CHOSEN threshold);
//   clumping (the tensile instability made visible) = two free particles closer than 0.75 dp (CHOSEN:
//   stretching only separates them; clumping pairs columns up); opening (the fracture Fig 8 shows as
//   "evident at a time of 119" and places "near the junction") = the mean x of two neighbouring lattice
//   columns more than 2 dp apart (CHOSEN: a column's worth of void), with its distance from the nearer band
//   edge. With eps = 0 the instability pairs columns all along the slab and the surface rows hold the
//   pieces together, so the ends part (fracture_time) well after the first gap opens at a junction.
#include <cmath>
#include <sstream>

#include "frame/driver.hpp"
#include "frame/run_jobs.hpp"
#include "io/snapshot.hpp"
#include "gray2001/scenes/plate_run.hpp"
#include "gray2001/scenes/run_files.hpp"
#include "gray2001/scenes/slab.hpp"

namespace {

std::string dp_tag(double dp) {
  std::ostringstream s;
  s << "dp" << dp;
  return s.str();
}

// Where the text's neck is read (Sec 7.3, "only ~10 particles thick"): the resolution study's 10 dp time.
const double neck_particles = 10;

// The command line's parameters (declare() below: names, defaults, --quick values).
struct Params {
  double dp = 0.016, end_accel = 2.5e-6, band = 0.2, t_max_eps0 = 300, t_max = 700;
  sph::GrayParameters scheme = scenes::slab_scheme();  // Sec 7.3: mu = 0.3, the yield 0.03
  double frame_every_eps0 = 20, frame_every = 50, sample_dt = 2.0;
  std::vector<double> study_dps{0.064, 0.032}, runs{0.0, 0.3};
  scenes::SlabSpec seeding;  // the perfect lattice by default; a jitter and seed draw one member of an ensemble
};

void declare(sph::Driver& d, Params& p) {
  d.param("dp", p.dp, "particle spacing (Sec 7.3: 0.016)").positive().quick(0.064);
  d.param("end-accel", p.end_accel, "outward acceleration of EACH end band (reading: 5e-6 is the relative one)").non_negative();
  d.param("band", p.band, "width of the driven end bands (Sec 7.3: 0.2)").non_negative();
  d.param("mu", p.scheme.mu, "shear modulus (Sec 7.3: 0.3)").non_negative();
  d.param("yield", p.scheme.yield_stress, "von Mises yield strength (Sec 7.3: 0.03)").positive();
  d.param("cfl", p.scheme.cfl, "time-step factor").positive();
  d.param("t-max-eps0", p.t_max_eps0, "longest eps = 0 run").positive();
  d.param("t-max", p.t_max, "longest eps = 0.3 run").positive().quick(420);  // past t = 394 of Fig 10; the fracture needs a full run
  d.param("frame-every-eps0", p.frame_every_eps0, "time between frames of the eps = 0 run").positive();
  d.param("frame-every", p.frame_every, "time between frames of the eps = 0.3 run").positive();
  d.param("sample-dt", p.sample_dt, "interval of the measurements (fracture, neck)").positive();
  d.param("runs", p.runs, "which of the runs eps = 0 and eps = 0.3 to do (e.g. --runs 0.3 for a fine eps = 0.3 run only)").non_negative();
  d.param("study-dps", p.study_dps, "further spacings of the eps = 0.3 resolution study (0: none)").non_negative().quick({});
}

scenes::SlabRunSpec spec(const Params& p, double eps, double spacing) {
  scenes::SlabRunSpec s;
  s.slab.dp = spacing;
  s.slab.band = p.band;
  s.slab.end_accel = p.end_accel;
  s.slab.jitter = p.seeding.jitter;
  s.slab.seed = p.seeding.seed;
  s.scheme = p.scheme;
  s.options.artificial_stress = eps > 0;
  s.scheme.eps_artificial = eps;
  s.t_max = eps > 0 ? p.t_max : p.t_max_eps0;
  s.sample_dt = p.sample_dt;
  return s;
}

// The runs, named (the unit of a job: Makefile run_rules): the main runs (eps = 0 and 0.3 at dp, with snapshots
// and frames) and the eps = 0.3 study. Every run is stepped, or read from its run job's folder with the files its
// observer wrote there (--runs-from), before the outputs are written.
struct Planned { std::string name; double eps, dp; bool main; };

std::vector<Planned> plan_runs(const Params& p) {
  std::vector<Planned> plan;
  for (const double eps : p.runs) {
    if (eps != 0.0 && eps != 0.3) throw std::invalid_argument("runs: the figures' runs are eps = 0 and eps = 0.3");
    plan.push_back({eps > 0 ? "eps0.3" : "eps0", eps, p.dp, true});
  }
  for (const double sdp : p.study_dps) {
    if (sdp == 0) continue;  // --study-dps 0: no study
    if (!(sdp > 0)) throw std::invalid_argument("study-dps: spacings must be > 0 (0: no study)");
    plan.push_back({"eps0.3_" + dp_tag(sdp), 0.3, sdp, false});
  }
  return plan;
}

// A main run's snapshots and frames.
std::pair<std::string, std::string> files_of(const Planned& run) {
  return {"snapshots_" + run.name + ".h5", "frames_" + run.name + ".csv"};
}

// Stepped here, the main runs with their snapshots and frames.
scenes::SlabRunResult step(const sph::Driver& d, const Params& p, const Planned& run) {
  const auto s = spec(p, run.eps, run.dp);
  if (!run.main) return scenes::run_slab(s, {}, "slab eps0.3 " + dp_tag(run.dp));
  const double every = run.eps > 0 ? p.frame_every : p.frame_every_eps0;
  sph::SnapshotSeries snaps(d.out_dir() / files_of(run).first, d.info());
  auto frames = d.csv(files_of(run).second, scenes::frame_columns());
  double next_frame = 0;
  bool parted_shown = false;
  auto on_sample = [&](const sph::GraySolver& solver, const sph::ElasticBody& body, const scenes::SlabSample& smp) {
    const bool first_parted = smp.parted && !parted_shown;  // a frame at the fracture as well
    if (!first_parted && solver.time() + 1e-9 < next_frame) return;
    parted_shown = parted_shown || smp.parted;
    if (!first_parted) next_frame += every;
    snaps.write(sph::snapshot_of(solver));
    scenes::write_frame(frames, solver, body);
  };
  return scenes::run_slab(s, on_sample, "slab " + run.name);
}

// A run read from its job's folder: its result, and a main run's snapshots and frames written again here.
scenes::SlabRunResult read_run(const sph::Driver& d, const Planned& run, const sph::RunFolder& folder) {
  if (run.main) {
    sph::rewrite_snapshots(folder, d, files_of(run).first);
    sph::rewrite_table(folder, d, files_of(run).second);
  }
  return scenes::read_slab_run(folder, "slab");
}

// wall_s: of the run where it was stepped (its run job, or this process).
sph::CsvWriter summary_table(const sph::Driver& d) {
  return d.csv("summary.csv", {"eps", "dp", "particles", "steps", "wall_s", "clumping_time", "first_split_time", "fracture_time",
                               "crack_x", "crack_from_junction", "opening_time", "opening_from_junction", "neck_before_fracture", "neck_before_fracture_over_dp",
                               "onset_time", "onset_strain", "strain_at_fracture", "blow_up"});
}

void record(sph::CsvWriter& summary, double eps, double spacing, const scenes::SlabRunResult& r) {
  const double strain_f = r.fracture_time >= 0 ? scenes::sample_at_time(r.trace, r.fracture_time).strain : NAN;
  summary.row(eps, spacing, r.particles, r.steps, r.wall_s, r.clumping_time, r.first_split_time, r.fracture_time, r.crack_x,
              r.crack_from_junction, r.opening_time, r.opening_from_junction, r.neck_before_fracture, r.neck_before_fracture / spacing, r.onset_time, r.onset_strain,
              strain_f, r.blow_up);
}

void write_trace(const sph::Driver& d, const std::string& name, const scenes::SlabRunResult& r) {
  auto trace = d.csv(name, {"t", "extension", "strain", "kinetic", "elastic", "neck_width", "neck_x", "median_width",
                            "closest", "widest_gap", "gap_x", "pieces", "parted"});
  for (const auto& m : r.trace)
    trace.row(m.t, m.extension, m.strain, m.ke, m.ee, m.neck_width, m.neck_x, m.median_width, m.closest, m.widest_gap, m.gap_x, m.pieces, m.parted);
}

// The main runs' traces, rows and values; returns the eps = 0.3 run's fracture time (NaN: not run).
double write_main_runs(sph::Driver& d, const Params& p, const std::vector<Planned>& plan, const std::vector<scenes::SlabRunResult>& result,
                       sph::CsvWriter& summary) {
  double fracture_main = NAN;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    if (!plan[i].main) continue;
    const double eps = plan[i].eps;
    const std::string tag = plan[i].name;
    const auto& r = result[i];
    write_trace(d, "trace_" + tag + ".csv", r);
    record(summary, eps, p.dp, r);
    if (eps > 0 && !r.blow_up.empty()) throw std::runtime_error("eps = 0.3 run blew up: " + r.blow_up);
    for (const auto& v : scenes::slab_run_values(r, eps > 0, p.dp, p.sample_dt)) d.value(v.name, v.value, v.note);
    if (eps > 0) fracture_main = r.fracture_time;
  }
  return fracture_main;
}

// Resolution study of the eps = 0.3 fracture time.
void write_study(sph::Driver& d, const Params& p, const std::vector<Planned>& plan, const std::vector<scenes::SlabRunResult>& result,
                 sph::CsvWriter& summary, double fracture_main) {
  auto study = d.csv("resolution.csv", {"dp", "particles", "steps", "wall_s", "fracture_time", "neck_before_fracture_over_dp",
                                        "onset_strain", "neck_10dp_time"});
  double coarse_fracture = NAN, coarse_dp = 0;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    if (plan[i].main) continue;
    const double sdp = plan[i].dp;
    const auto& r = result[i];
    write_trace(d, "trace_eps0.3_" + dp_tag(sdp) + ".csv", r);
    record(summary, 0.3, sdp, r);
    study.row(sdp, r.particles, r.steps, r.wall_s, r.fracture_time, r.neck_before_fracture / sdp, r.onset_strain,
              scenes::first_neck_at_most(r.trace, neck_particles * sdp));
    if (std::abs(sdp - 2 * p.dp) < 1e-12) {
      coarse_fracture = r.fracture_time;
      coarse_dp = sdp;
    }
  }
  if (coarse_dp > 0 && fracture_main > 0 && coarse_fracture > 0)
    d.value("eps0.3_fracture_time_change_2dp", std::abs(fracture_main / coarse_fracture - 1),
            "|t_f(dp) / t_f(2 dp) - 1|: the resolution uncertainty of the fracture time");
}

}  // namespace

int main(int argc, char** argv) {
  sph::Driver d("gray2001_fig8_10_slab", "G-fig8", "Gray et al. 2001 Figs 8-10: slab under tension with von Mises plasticity");
  Params p;
  declare(d, p);
  const sph::RunJobs jobs(d, "its result (and a main run's snapshots and frames)");
  d.param("jitter", p.seeding.jitter, "random displacement of every particle, up to this x dp (0: the lattice; SlabSpec::jitter)").non_negative();
  d.param("seed", p.seeding.seed, "seed of the jitter");

  return d.run(argc, argv, [&] {
    const std::vector<Planned> plan = plan_runs(p);
    std::vector<std::string> names;
    for (const auto& r : plan) names.push_back(r.name);
    if (jobs.handled(names, [&](std::size_t i) { scenes::write_slab_run(d, "slab", step(d, p, plan[i])); })) return;
    // Sec 7.3's loading as printed and as read (issue 46 item 4: each a row): the particles 0.2 from each end
    // accelerate at 5e-6, so each end moves 2.5e-6 t^2 = 0.4 at t = 400 and the 3-long slab stretches by 0.8;
    // the printed strain 0.13 is 0.4 / 3, the reading in which 5e-6 is the ends' relative acceleration.
    d.value("strain_t400_each_band_at_5e-6", 2 * (0.5 * 5e-6 * 400.0 * 400.0) / 3.0,
            "as printed: each end moves 2.5e-6 t^2, the strain (two ends) / 3 at t = 400");
    d.value("strain_t400_separation_at_5e-6", 0.5 * 5e-6 * 400.0 * 400.0 / 3.0,
            "the reading: the ends' separation grows by 2.5e-6 t^2, / 3 at t = 400");
    std::vector<scenes::SlabRunResult> result;
    for (const auto& run : plan)
      result.push_back(jobs.result(run.name, [&](const sph::RunFolder& f) { return read_run(d, run, f); }, [&] { return step(d, p, run); }));
    auto summary = summary_table(d);
    const double fracture_main = write_main_runs(d, p, plan, result, summary);
    write_study(d, p, plan, result, summary, fracture_main);
  });
}
