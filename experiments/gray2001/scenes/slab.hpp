// The slab under tension of Gray, Monaghan & Swift 2001 Section 7.3: a 3 x 1 block on a square grid whose
// particles within `band` of each end are Driven (elastic_body.hpp) at a constant acceleration along the
// long axis, outward, while the rest is free; and the run that measures it: extension and strain, the
// width of the neck, the widest gap between lattice columns (where the body opens), and fracture (the two
// driven ends no longer connected).
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "updated_lagrangian/elastic_body.hpp"
#include "updated_lagrangian/gray_solver.hpp"
#include "core/neighbours.hpp"

namespace scenes {

struct SlabSpec {
  double L = 3.0, H = 1.0;    ///< Gray 2001 Sec 7.3
  double dp = 0.016;          ///< Gray 2001 Sec 7.3
  double band = 0.2;          ///< driven particles: centre within `band` of an end (Sec 7.3)
  double end_accel = 2.5e-6;  ///< acceleration of EACH end, outward (READING: see the slab driver)
  double margin = 2.0;        ///< room around the slab in the cell-list box (sizing only)
  /// Ensembles (CHOSEN, beyond the paper): every particle displaced by a uniform random amount of up to
  /// jitter x dp in each direction, from `seed`. The tensile instability grows from whatever seed the
  /// lattice carries, round-off included, so one run's parting time is one draw; jitter = 0 is the lattice.
  double jitter = 0;
  unsigned seed = 0;
};

struct Slab {
  sph::ElasticBody body;
  double length = 0, height = 0;  ///< of the particle block: nx dp and ny dp
  long nx = 0, ny = 0;            ///< particle a is in lattice column a % nx (added row by row)
  std::vector<std::size_t> left_band, right_band;
};

/// Particles at ((i + 1/2) dp, (j + 1/2) dp), i < nx = round(L / dp), j < ny = round(H / dp) (at dp = 0.016
/// the slab is 188 x 63 particles, 3.008 x 1.008: L / dp is not an integer); the bands are Driven at
/// -end_accel (left) and +end_accel (right) along x, everything starts at rest.
/// Refuses (std::invalid_argument, before anything is allocated) a slab whose particles cannot fit in memory
/// (sph::check_particle_count); make_slab calls it, and a driver that runs several scenes calls it for each
/// before its first run, so that a spacing typed wrong stops at once, not after the other scenes.
void check_size(const SlabSpec& s);
Slab make_slab(const SlabSpec& s, double rho0);

/// The scheme of Section 7.3: the scheme's defaults (parameters.hpp) with mu = 0.3.
sph::GrayParameters slab_scheme();
/// The terms of Section 7.3: the default terms with the von Mises return on.
sph::GrayOptions slab_options();

struct SlabRunSpec {
  SlabSpec slab;
  sph::GrayParameters scheme = slab_scheme();  ///< mu = 0.3 (Sec 7.3); the von Mises yield 0.03 is the default
  sph::GrayOptions options = slab_options();   ///< plasticity on: Sec 7.3 includes it in every slab run
  double t_max = 700;
  double run_after_fracture = 10;  ///< stop this long after the ends part (< 0: run to t_max)
  double sample_dt = 2.0;          ///< interval of samples and fracture checks
  double fracture_link = 1.5;      ///< link distance / dp of the connectivity (the criterion of G-fig2)
  double neck_bin = 2.0;           ///< width of the x bins of the neck measurement, in dp
  double neck_ratio_onset = 0.9;   ///< necking has begun when min width / median width falls below this
  double clump_ratio = 0.75;       ///< the tensile instability is visible once two free particles come
                                   ///< closer than this x dp (stretching only moves them apart; clumping
                                   ///< pairs up lattice columns at ~0.5-0.7 dp)
  double opening_gap = 2.0;        ///< the body has visibly opened once two neighbouring lattice columns'
                                   ///< mean x are more than this x dp apart (a column's worth of void)
};

struct SlabSample {
  double t, extension, strain;     ///< separation of the bands' centres of mass minus its initial value; / length
  double ke, ee;
  double neck_width, neck_x;       ///< narrowest bin of the free part: y extent of its particles + dp; its x
  double median_width;             ///< median over the free part's bins (the neck ratio is neck / median)
  double closest;                  ///< smallest distance between two free particles
  double widest_gap, gap_x;        ///< largest distance between the mean x of neighbouring lattice columns; its midpoint
  std::size_t pieces;              ///< pieces of the whole slab at the fracture link
  int parted;                      ///< 1 once the two driven bands are in different pieces
};

struct SlabRunResult {
  std::vector<SlabSample> trace;
  long steps = 0;
  std::size_t particles = 0;
  double dt = 0, wall_s = 0;
  double first_split_time = -1;    ///< first time the slab was in more than one piece
  double fracture_time = -1;       ///< first time the two ends were in different pieces
  double crack_x = NAN;            ///< where it parted: midway between the left end's piece and the right end's
  double crack_from_junction = NAN;///< how far the left end's piece reaches beyond its band edge, or the right
                                   ///< one's, whichever is less: the crack nearest a junction (t = fracture;
                                   ///< a slab broken at both junctions leaves a middle piece, and crack_x is
                                   ///< then its centre)
  double neck_before_fracture = NAN;   ///< neck width at the last sample before the ends parted
  double onset_strain = NAN, onset_time = NAN;  ///< necking onset (neck ratio below the threshold)
  double clumping_time = -1;       ///< first time the closest free pair fell below clump_ratio dp (-1: never)
  double opening_time = -1;        ///< first time the widest column gap exceeded opening_gap dp (-1: never)
  double opening_from_junction = NAN;  ///< distance of that gap from the nearer band edge (t = opening_time)
  std::string blow_up;
};

// ------------------------------------------------------------------------------------------------------------
// The measurement of one sample, a function of the particle state only, and the run's summary from the samples:
// run_slab measures our solver's state with them, experiments/peers/peer_slab.cpp a peer's frames. Defined in
// slab_measure.cpp with the values below; the slab and its run in slab.cpp.

/// What a sample is measured from besides the positions, fixed over a run: our slab's (slab_geometry) or the same
/// read back from the layout a peer ran.
struct SlabGeometry {
  double dp = 0;
  sph::Box2 box;                   ///< the domain of the fragment search (particles outside it count as well)
  double length = 0;               ///< of the particle block (nx dp): strain = extension / length
  std::vector<long> column;        ///< lattice column of each particle (ours: a % nx)
  long columns = 0;                ///< nx
  std::vector<int> band;           ///< -1 left driven band, +1 right driven band, 0 free
  std::vector<std::size_t> left_band, right_band;  ///< the bands' particles in index order
  double sep0 = 0;                 ///< separation of the bands' mean x at t = 0
};
/// The geometry of a slab as make_slab built it (before any step: sep0 from its positions).
SlabGeometry slab_geometry(const Slab& slab);

/// One sample and what the summary needs of its instant besides the trace row.
struct SlabMeasurement {
  SlabSample sample;
  double junction_l = NAN, junction_r = NAN;  ///< the left band's largest x, the right band's smallest
  double reach_l = NAN, reach_r = NAN;        ///< once parted: the left end's piece's largest x, the right one's smallest
};

/// Measures samples of one run (arrays sized once, for the geometry). `settings` gives the measurement settings
/// (fracture_link, neck_bin, clump_ratio; the rest is the summary's).
class SlabMeter {
 public:
  SlabMeter(const SlabGeometry& g, const SlabRunSpec& settings);
  ~SlabMeter();
  /// The sample of the state at time t: x every particle's position in the geometry's order; ke, ee the
  /// energies (our solver's; NaN where there is no solver, a peer's frames). Velocities are not needed.
  SlabMeasurement measure(double t, const std::vector<sph::Vec2>& x, double ke, double ee);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The run's summary from its samples in time order (scenes::run_slab's, and a peer's).
struct SlabSummary {
  double first_split_time = -1, fracture_time = -1;
  double crack_x = NAN, crack_from_junction = NAN, neck_before_fracture = NAN;
  double onset_strain = NAN, onset_time = NAN;
  double clumping_time = -1, opening_time = -1, opening_from_junction = NAN;
};
SlabSummary summarise_slab(const std::vector<SlabMeasurement>& samples, const SlabRunSpec& settings, double dp);
/// Copies a summary into a run's result (its fields of the same names).
void set_summary(SlabRunResult& r, const SlabSummary& sum);

/// Whether run_slab stops at a sample at time t, the ends having first parted at fracture_time (-1: not yet):
/// run_after_fracture after the parting (never if run_after_fracture < 0). A peer's frames are read up to it.
bool slab_stops_at(double fracture_time, double t, const SlabRunSpec& settings);

/// Runs the slab; `on_sample(solver, body, sample)` is called at every sample, after it is recorded.
using SlabObserver = std::function<void(const sph::GraySolver&, const sph::ElasticBody&, const SlabSample&)>;
SlabRunResult run_slab(const SlabRunSpec& s, const SlabObserver& on_sample = {}, const std::string& progress_label = "slab");

// ------------------------------------------------------------------------------------------------------------
// The values the Figs 8-10 driver writes for one of its main runs, from the run's trace and summary: the driver
// writes them for our runs, experiments/peers/peer_slab.cpp for a peer's.

/// The first sample, before the ends part, whose neck is at most `width` wide (-1: none).
double first_neck_at_most(const std::vector<SlabSample>& trace, double width);
/// The sample closest to time t (the first of two equally close).
const SlabSample& sample_at_time(const std::vector<SlabSample>& trace, double t);

struct SlabValue {
  std::string name;
  double value;
  std::string note;
};
/// The eps = 0 run's values (eps0_*) or the eps = 0.3 run's (strain_at_t394, eps0.3_*), in the driver's order;
/// `dp` the run's spacing, `sample_dt` its sample interval. The eps > 0 run must not have blown up (the driver
/// refuses it before).
std::vector<SlabValue> slab_run_values(const SlabRunResult& r, bool artificial_stress, double dp, double sample_dt);

}  // namespace scenes
