// Gray 2001's slab under tension (Sec 7.3, Figs 8-10) for independent codes (make peers, issue 44), and our
// measurement of the particle frames they return.
//
//   --action layout   writes the slab as scenes::run_slab builds it (scenes::make_slab at --dp): layout.csv (one row
//                     per particle: x, y, u, v, m, rho, its lattice column, band -1 left driven / +1 right driven /
//                     0 free) and settings.csv (name,value: every scheme setting a peer needs, our time step, the
//                     run's length and sample interval, and the measurement settings), so a peer starts from our
//                     particles, not a re-derivation of them.
//   --action measure  reads a peer's frames (--frames: experiments/peers/frames_reader.hpp, every particle every
//                     sample_dt) and measures each with scenes::SlabMeter, the function of the particle state that
//                     run_slab measures our solver with, up to the sample at which run_slab would have stopped
//                     (scenes::slab_stops_at); the run's summary by scenes::summarise_slab and the driver's values
//                     by scenes::slab_run_values, as gray2001_fig8_10_slab writes them for its own run:
//                     values_peer_slab.csv, trace.csv (the driver's trace columns; kinetic and elastic energy NaN:
//                     they need the solver) and summary.csv (the driver's summary columns).
// Parameters (source): the slab of Gray, Monaghan & Swift 2001 Sec 7.3 as experiments/gray2001/gray2001_fig8_10_slab.cpp
//   runs it (its defaults: band 0.2, each end at 2.5e-6 outward, mu = 0.3, yield 0.03, t_max 300 at eps = 0 and
//   700 at eps = 0.3, samples every 2); the scheme's defaults from src/updated_lagrangian/parameters.hpp.
#include <cmath>
#include <stdexcept>

#include "core/kernels.hpp"
#include "core/materials.hpp"
#include "frame/driver.hpp"
#include "gray2001/scenes/slab.hpp"
#include "peers/frames_reader.hpp"

namespace {

struct Params {
  std::string action = "layout", frames;
  double dp = 0.064, eps = 0.3, end_accel = 2.5e-6, band = 0.2, t_max = -1, sample_dt = 2.0;
  sph::GrayParameters scheme = scenes::slab_scheme();
};

void declare(sph::Driver& d, Params& p) {
  d.param("action", p.action, "layout: write our particles and settings; measure: measure a peer's frames").one_of({"layout", "measure"});
  d.param("frames", p.frames, "the peer's frames (action measure): CSV t,id,x,y,u,v");
  d.param("dp", p.dp, "particle spacing (Sec 7.3: 0.016)").positive();
  d.param("eps", p.eps, "artificial stress epsilon (0: standard SPH, Fig 8; 0.3: Figs 9-10)").non_negative();
  d.param("end-accel", p.end_accel, "outward acceleration of EACH end band (the driver's reading)").non_negative();
  d.param("band", p.band, "width of the driven end bands (Sec 7.3: 0.2)").positive();
  d.param("mu", p.scheme.mu, "shear modulus (Sec 7.3: 0.3)").positive();
  d.param("yield", p.scheme.yield_stress, "von Mises yield strength (Sec 7.3: 0.03)").positive();
  d.param("cfl", p.scheme.cfl, "time-step factor").positive();
  d.param("t-max", p.t_max, "longest run (< 0: the driver's, 300 at eps = 0 and 700 at eps > 0)");
  d.param("sample-dt", p.sample_dt, "interval of the samples (the driver's 2)").positive();
}

// The driver's run spec (gray2001_fig8_10_slab.cpp spec()), at this spacing and eps.
scenes::SlabRunSpec run_spec(const Params& p) {
  scenes::SlabRunSpec s;
  s.slab.dp = p.dp;
  s.slab.band = p.band;
  s.slab.end_accel = p.end_accel;
  s.scheme = p.scheme;
  s.options.artificial_stress = p.eps > 0;
  s.scheme.eps_artificial = p.eps;
  s.t_max = p.t_max > 0 ? p.t_max : (p.eps > 0 ? 700.0 : 300.0);
  s.sample_dt = p.sample_dt;
  return s;
}

// A peer's frames measured by SlabMeter, up to the sample at which run_slab would have stopped.
struct MeasuredFrames {
  std::vector<scenes::SlabMeasurement> samples;
  double fracture_time = -1, first_offset = NAN;  // first_offset: largest |x - our layout| at t = 0
  bool stopped = false;
  std::size_t read = 0;
};

MeasuredFrames measure_frames(const std::string& frames, const scenes::SlabRunSpec& s, const sph::ElasticBody& b,
                              const scenes::SlabGeometry& geometry) {
  scenes::SlabMeter meter(geometry, s);
  MeasuredFrames m;
  peers::for_each_frame(frames, b.size(), [&](const peers::Frame& f) {
    ++m.read;
    if (m.stopped) return;  // run_slab would have stopped before this frame
    if (m.samples.empty()) {
      if (f.t != 0.0) throw std::runtime_error(frames + ": the first frame is at t = " + std::to_string(f.t) + ", not 0");
      m.first_offset = 0;
      for (std::size_t a = 0; a < b.size(); ++a) m.first_offset = std::max(m.first_offset, (f.x[a] - b.x[a]).norm());
    }
    m.samples.push_back(meter.measure(f.t, f.x, NAN, NAN));
    if (m.samples.back().sample.parted && m.fracture_time < 0) m.fracture_time = f.t;
    m.stopped = m.samples.size() > 1 && scenes::slab_stops_at(m.fracture_time, f.t, s);
  });
  if (m.samples.size() < 2) throw std::runtime_error(frames + ": fewer than 2 frames");
  return m;
}

// The run's result as run_slab returns it: the trace and scenes::summarise_slab's summary.
scenes::SlabRunResult result_of(const MeasuredFrames& m, const scenes::SlabRunSpec& s, double dp, std::size_t particles,
                                double dt) {
  scenes::SlabRunResult r;
  for (const auto& x : m.samples) r.trace.push_back(x.sample);
  const scenes::SlabSummary sum = scenes::summarise_slab(m.samples, s, dp);
  scenes::set_summary(r, sum);
  r.particles = particles;
  r.dt = dt;
  return r;
}

// trace.csv and summary.csv (the driver's columns) and the values: the driver's for this run, then the summary's.
void write_measured(sph::Driver& d, const Params& p, const scenes::SlabRunSpec& s, const MeasuredFrames& m,
                    const scenes::SlabRunResult& r) {
  const double dp = p.dp, eps = p.eps;
  const double t_last = r.trace.back().t;
  // Complete: stopped where run_slab stops, or sampled to within one sample interval of t_max (a peer that blew
  // up or was cut short is not: its first-time events may not have come yet).
  const bool complete = m.stopped || t_last > s.t_max - s.sample_dt - 1e-9;
  auto trace = d.csv("trace.csv", {"t", "extension", "strain", "kinetic", "elastic", "neck_width", "neck_x", "median_width",
                                   "closest", "widest_gap", "gap_x", "pieces", "parted"});
  for (const auto& x : r.trace)
    trace.row(x.t, x.extension, x.strain, x.ke, x.ee, x.neck_width, x.neck_x, x.median_width, x.closest, x.widest_gap, x.gap_x,
              x.pieces, x.parted);
  const double strain_f = r.fracture_time >= 0 ? scenes::sample_at_time(r.trace, r.fracture_time).strain : NAN;
  auto summary = d.csv("summary.csv", {"eps", "dp", "particles", "clumping_time", "first_split_time", "fracture_time", "crack_x",
                                       "crack_from_junction", "opening_time", "opening_from_junction", "neck_before_fracture",
                                       "neck_before_fracture_over_dp", "onset_time", "onset_strain", "strain_at_fracture"});
  summary.row(eps, dp, r.particles, r.clumping_time, r.first_split_time, r.fracture_time, r.crack_x, r.crack_from_junction,
              r.opening_time, r.opening_from_junction, r.neck_before_fracture, r.neck_before_fracture / dp, r.onset_time,
              r.onset_strain, strain_f);
  // The driver's values for this run (its names: eps0_* or the eps = 0.3 ones), then the summary by plain names.
  for (const auto& v : scenes::slab_run_values(r, eps > 0, dp, s.sample_dt)) d.value(v.name, v.value, v.note);
  d.value("fracture_time", r.fracture_time, "the two ends in different pieces (-1: never)");
  d.value("first_split_time", r.first_split_time, "first piece broken off (-1: never)");
  d.value("clumping_time", r.clumping_time, "first time two free particles were closer than 0.75 dp (-1: never)");
  d.value("opening_time", r.opening_time, "first gap of more than 2 dp between neighbouring columns (-1: never)");
  d.value("opening_from_junction", r.opening_from_junction, "distance of that gap from the nearer band edge");
  d.value("crack_x", r.crack_x, "where the ends parted");
  d.value("crack_from_junction", r.crack_from_junction, "the crack nearest a band edge, its distance from it");
  d.value("neck_before_fracture", r.neck_before_fracture, "neck width at the last sample before the ends parted");
  d.value("onset_time", r.onset_time, "necking onset: neck below 0.9 x the median width");
  d.value("onset_strain", r.onset_strain, "strain at the necking onset");
  d.value("strain_at_fracture", strain_f, "strain at the parting");
  d.value("neck_10dp_time", scenes::first_neck_at_most(r.trace, 10 * dp), "first sample before parting with the neck <= 10 dp (-1: none)");
  d.value("samples", static_cast<double>(m.samples.size()), "frames measured (up to run_slab's stop)");
  d.value("frames_read", static_cast<double>(m.read), "frames in the file");
  d.value("t_last", t_last, "the last frame measured");
  d.value("complete", complete ? 1.0 : 0.0, "1: the frames reach run_slab's stop or t_max");
  d.value("first_frame_offset", m.first_offset, "largest |x - our layout| in the frame at t = 0 (0: our particles)");
}

// --action layout: our particles (layout.csv) and every setting a peer needs (settings.csv).
void write_layout(sph::Driver& d, const scenes::SlabRunSpec& s, const scenes::Slab& slab,
                  const scenes::SlabGeometry& geometry, double dt) {
  const sph::ElasticBody& b = slab.body;
  const double dp = s.slab.dp;
  const double h = s.scheme.h_over_dp * dp;
  const sph::CubicSpline kernel(2);
  const double K = s.scheme.rho0 * s.scheme.c0 * s.scheme.c0;
  const double E = sph::young_from_bulk_shear(K, s.scheme.mu), nu = sph::poisson_ratio_from_bulk_shear(K, s.scheme.mu);
  auto layout = d.csv("layout.csv", {"x", "y", "u", "v", "m", "rho", "column", "band"});
  for (std::size_t a = 0; a < b.size(); ++a)
    layout.row(b.x[a].x(), b.x[a].y(), b.v[a].x(), b.v[a].y(), b.m[a], b.rho[a], geometry.column[a], geometry.band[a]);
  auto settings = d.csv("settings.csv", {"name", "value"});
  const std::pair<const char*, double> rows[] = {
      {"dp", dp}, {"h", h}, {"W_dp", kernel.W(dp, h)}, {"rho0", s.scheme.rho0}, {"c0", s.scheme.c0}, {"K", K},
      {"mu", s.scheme.mu}, {"E", E}, {"nu", nu}, {"yield_stress", s.scheme.yield_stress},
      {"plasticity", s.options.plasticity ? 1.0 : 0.0}, {"artificial_stress", s.options.artificial_stress ? 1.0 : 0.0},
      {"eps_artificial", s.options.artificial_stress ? s.scheme.eps_artificial : 0.0},
      {"n_artificial", static_cast<double>(s.scheme.n_artificial)}, {"xsph", s.options.xsph ? 1.0 : 0.0},
      {"eps_xsph", s.scheme.eps_xsph}, {"viscosity", s.options.viscosity ? 1.0 : 0.0}, {"alpha", s.scheme.alpha},
      {"beta", s.scheme.beta}, {"summation_density", s.options.summation_density ? 1.0 : 0.0},
      {"end_accel", s.slab.end_accel}, {"band", s.slab.band}, {"L", s.slab.L}, {"H", s.slab.H}, {"length", slab.length},
      {"height", slab.height}, {"nx", static_cast<double>(slab.nx)}, {"ny", static_cast<double>(slab.ny)},
      {"cfl", s.scheme.cfl}, {"dt", dt}, {"t_max", s.t_max}, {"sample_dt", s.sample_dt},
      {"run_after_fracture", s.run_after_fracture}, {"fracture_link", s.fracture_link}, {"neck_bin", s.neck_bin},
      {"neck_ratio_onset", s.neck_ratio_onset}, {"clump_ratio", s.clump_ratio}, {"opening_gap", s.opening_gap},
      {"particles", static_cast<double>(b.size())}};
  for (const auto& [name, value] : rows) settings.row(name, value);
  d.value("particles", static_cast<double>(b.size()), "particles of the layout, driven ones included");
  d.value("dt", dt, "our time step for this scene");
}

}  // namespace

int main(int argc, char** argv) {
  sph::Driver d("peer_slab", "peers", "our slab under tension written for independent codes, and their frames measured");
  Params p;
  declare(d, p);

  return d.run(argc, argv, [&] {
    const scenes::SlabRunSpec s = run_spec(p);
    const scenes::Slab slab = scenes::make_slab(s.slab, s.scheme.rho0);
    const sph::ElasticBody& b = slab.body;
    const scenes::SlabGeometry geometry = scenes::slab_geometry(slab);
    const double dt = sph::gray_time_step(s.scheme, p.dp, s.slab.end_accel * s.t_max);  // run_slab's r.dt

    if (p.action == "measure") {
      if (p.frames.empty()) throw std::invalid_argument("--action measure needs --frames <file>");
      const MeasuredFrames m = measure_frames(p.frames, s, b, geometry);
      write_measured(d, p, s, m, result_of(m, s, p.dp, b.size(), dt));
      return;
    }
    write_layout(d, s, slab, geometry, dt);
  });
}
