#include "gray2001/scenes/slab.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/fragments.hpp"

// The slab's measurement (the second and third parts of slab.hpp): a sample from the particle state alone, the
// run's summary from its samples and the values of one run, so that run_slab (slab.cpp) and a peer's frames
// (experiments/peers/peer_slab.cpp) are measured by the same code.

namespace scenes {

namespace {

// The width of the free part of the slab in x bins: for each bin, the y extent of its particles plus dp
// (the particles' own size), 0 for an empty bin (the body is cut there). Arrays sized once, for the box.
class NeckMeter {
 public:
  NeckMeter(const sph::Box2& box, double bin) : bin_(bin) {
    const std::size_t n = static_cast<std::size_t>(std::ceil(box.Lx() / bin)) + 2;
    ymin_.resize(n);
    ymax_.resize(n);
    count_.resize(n);
    width_.resize(n);
    scratch_.resize(n);
  }

  struct Neck { double width, x, median; };

  // The free particles are those of band 0.
  Neck measure(const std::vector<sph::Vec2>& x, const std::vector<int>& band, double x_from, double x_to, double dp) {
    const std::size_t nb = x_to > x_from ? static_cast<std::size_t>((x_to - x_from) / bin_) : 0;
    if (nb == 0 || nb > width_.size()) return {NAN, NAN, NAN};
    std::fill_n(ymin_.begin(), nb, std::numeric_limits<double>::infinity());
    std::fill_n(ymax_.begin(), nb, -std::numeric_limits<double>::infinity());
    std::fill_n(count_.begin(), nb, 0);
    for (std::size_t a = 0; a < x.size(); ++a) {
      if (band[a] != 0) continue;
      const double u = (x[a].x() - x_from) / bin_;
      if (u < 0 || u >= static_cast<double>(nb)) continue;
      const std::size_t k = static_cast<std::size_t>(u);
      ymin_[k] = std::min(ymin_[k], x[a].y());
      ymax_[k] = std::max(ymax_[k], x[a].y());
      ++count_[k];
    }
    Neck best{std::numeric_limits<double>::infinity(), NAN, NAN};
    for (std::size_t k = 0; k < nb; ++k) {
      width_[k] = count_[k] > 0 ? ymax_[k] - ymin_[k] + dp : 0.0;
      if (width_[k] < best.width) best = {width_[k], x_from + (k + 0.5) * bin_, NAN};
    }
    std::copy_n(width_.begin(), nb, scratch_.begin());
    std::nth_element(scratch_.begin(), scratch_.begin() + nb / 2, scratch_.begin() + nb);
    best.median = scratch_[nb / 2];
    return best;
  }

 private:
  double bin_;
  std::vector<double> ymin_, ymax_, width_, scratch_;
  std::vector<int> count_;
};

// The mean x of each lattice column and the widest gap between neighbouring columns: where the body opens.
// Clumping pairs columns up (gaps alternate ~0.6 and ~1.4 dp); a gap of two spacings is a column's worth of
// void. Arrays sized once.
class ColumnGaps {
 public:
  explicit ColumnGaps(long nx) : sum_(static_cast<std::size_t>(nx)), count_(static_cast<std::size_t>(nx)) {}

  struct Gap { double width, x; };

  Gap widest(const std::vector<sph::Vec2>& x, const std::vector<long>& column) {
    const std::size_t nx = sum_.size();
    std::fill(sum_.begin(), sum_.end(), 0.0);
    std::fill(count_.begin(), count_.end(), 0);
    for (std::size_t a = 0; a < x.size(); ++a) {
      sum_[column[a]] += x[a].x();
      ++count_[column[a]];
    }
    Gap best{-1, NAN};
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      const double xl = sum_[i] / count_[i], xr = sum_[i + 1] / count_[i + 1];
      if (xr - xl > best.width) best = {xr - xl, 0.5 * (xl + xr)};
    }
    return best;
  }

 private:
  std::vector<double> sum_;
  std::vector<int> count_;
};

double mean_x(const std::vector<sph::Vec2>& x, const std::vector<std::size_t>& idx) {
  double s = 0;
  for (std::size_t a : idx) s += x[a].x();
  return s / static_cast<double>(idx.size());
}

// The search radius of the closest free pair, in dp (CHOSEN): the closest pair of a slab that holds together is
// within ~1.5 dp (lattice neighbours at dp, clumped ones nearer); a slab with no two free particles within 3 dp
// has fallen apart into single particles, and its closest distance is reported as infinite.
constexpr double kClosestSearch = 3.0;

}  // namespace

SlabGeometry slab_geometry(const Slab& slab) {
  SlabGeometry g;
  const sph::ElasticBody& body = slab.body;
  g.dp = body.dp;
  g.box = body.box;
  g.length = slab.length;
  g.columns = slab.nx;
  g.column.resize(body.size());
  g.band.assign(body.size(), 0);
  for (std::size_t a = 0; a < body.size(); ++a) g.column[a] = static_cast<long>(a % static_cast<std::size_t>(slab.nx));
  for (std::size_t a : slab.left_band) g.band[a] = -1;
  for (std::size_t a : slab.right_band) g.band[a] = 1;
  g.left_band = slab.left_band;
  g.right_band = slab.right_band;
  g.sep0 = mean_x(body.x, slab.right_band) - mean_x(body.x, slab.left_band);
  return g;
}

struct SlabMeter::Impl {
  Impl(const SlabGeometry& geometry, const SlabRunSpec& s)
      : g(geometry), link(s.fracture_link * geometry.dp), clump_radius(kClosestSearch * geometry.dp),
        neck(geometry.box, s.neck_bin * geometry.dp), columns(geometry.columns), cells(geometry.box, clump_radius) {}
  SlabGeometry g;
  double link, clump_radius;
  NeckMeter neck;
  ColumnGaps columns;
  sph::CellList2D cells;
};

SlabMeter::SlabMeter(const SlabGeometry& g, const SlabRunSpec& s) {
  const std::size_t n = g.band.size();
  if (!(g.dp > 0) || !(g.length > 0) || g.columns < 2 || g.column.size() != n || g.left_band.empty() || g.right_band.empty())
    throw std::invalid_argument("slab meter: need dp, length > 0, two columns or more, a column per particle and both bands");
  for (std::size_t a = 0; a < n; ++a)
    if (g.column[a] < 0 || g.column[a] >= g.columns || g.band[a] < -1 || g.band[a] > 1)
      throw std::invalid_argument("slab meter: particle " + std::to_string(a) + " has a column outside 0..nx-1 or a band not -1, 0, 1");
  for (std::size_t a : g.left_band)
    if (a >= n || g.band[a] != -1) throw std::invalid_argument("slab meter: the left band's list and the band marks differ");
  for (std::size_t a : g.right_band)
    if (a >= n || g.band[a] != 1) throw std::invalid_argument("slab meter: the right band's list and the band marks differ");
  if (!(s.fracture_link > 0) || !(s.neck_bin >= 1))
    throw std::invalid_argument("slab meter: need fracture_link > 0 and neck_bin >= 1");
  impl_ = std::make_unique<Impl>(g, s);
}

SlabMeter::~SlabMeter() = default;

SlabMeasurement SlabMeter::measure(double t, const std::vector<sph::Vec2>& x, double ke, double ee) {
  const SlabGeometry& g = impl_->g;
  if (x.size() != g.band.size())
    throw std::invalid_argument("slab meter: " + std::to_string(x.size()) + " positions for a slab of " + std::to_string(g.band.size()));
  const double dp = g.dp;
  const auto f = sph::find_fragments(x, g.box, impl_->link);
  const std::size_t piece_l = f.label[g.left_band.front()], piece_r = f.label[g.right_band.front()];
  const bool parted = piece_l != piece_r;
  SlabMeasurement m;
  double junction_l = -std::numeric_limits<double>::infinity(), junction_r = std::numeric_limits<double>::infinity();
  for (std::size_t a : g.left_band) junction_l = std::max(junction_l, x[a].x());
  for (std::size_t a : g.right_band) junction_r = std::min(junction_r, x[a].x());
  const auto nk = impl_->neck.measure(x, g.band, junction_l, junction_r, dp);
  const double ext = mean_x(x, g.right_band) - mean_x(x, g.left_band) - g.sep0;
  // The closest pair of free particles (each pair seen from both ends: |x_a - x_c| is the same number).
  double closest = std::numeric_limits<double>::infinity();
  impl_->cells.build(x);
  for (std::size_t a = 0; a < x.size(); ++a) {
    if (g.band[a] != 0) continue;
    impl_->cells.for_each_neighbour(x, a, impl_->clump_radius, [&](std::size_t c, const sph::Vec2&, double) {
      if (g.band[c] == 0) closest = std::min(closest, (x[a] - x[c]).norm());
    });
  }
  const auto gap = impl_->columns.widest(x, g.column);
  m.sample = {t, ext, ext / g.length, ke, ee, nk.width, nk.x, nk.median, closest, gap.width, gap.x, f.count, parted ? 1 : 0};
  m.junction_l = junction_l;
  m.junction_r = junction_r;
  if (parted) {
    double xl = -std::numeric_limits<double>::infinity(), xr = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < x.size(); ++a) {
      if (f.label[a] == piece_l) xl = std::max(xl, x[a].x());
      if (f.label[a] == piece_r) xr = std::min(xr, x[a].x());
    }
    m.reach_l = xl;
    m.reach_r = xr;
  }
  return m;
}

SlabSummary summarise_slab(const std::vector<SlabMeasurement>& samples, const SlabRunSpec& s, double dp) {
  SlabSummary r;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const SlabMeasurement& m = samples[i];
    const SlabSample& x = m.sample;
    if (x.closest < s.clump_ratio * dp && r.clumping_time < 0) r.clumping_time = x.t;
    if (x.widest_gap > s.opening_gap * dp && r.opening_time < 0) {
      r.opening_time = x.t;
      r.opening_from_junction = std::max(0.0, std::min(x.gap_x - m.junction_l, m.junction_r - x.gap_x));
    }
    if (x.pieces > 1 && r.first_split_time < 0) r.first_split_time = x.t;
    if (!x.parted && std::isnan(r.onset_time) && x.neck_width < s.neck_ratio_onset * x.median_width) {
      r.onset_time = x.t;
      r.onset_strain = x.strain;
    }
    if (x.parted && r.fracture_time < 0) {
      r.fracture_time = x.t;
      r.crack_x = 0.5 * (m.reach_l + m.reach_r);
      r.crack_from_junction = std::min(m.reach_l - m.junction_l, m.junction_r - m.reach_r);
      if (i >= 1) r.neck_before_fracture = samples[i - 1].sample.neck_width;
    }
  }
  return r;
}

bool slab_stops_at(double fracture_time, double t, const SlabRunSpec& s) {
  return fracture_time >= 0 && s.run_after_fracture >= 0 && t >= fracture_time + s.run_after_fracture;
}

double first_neck_at_most(const std::vector<SlabSample>& trace, double width) {
  for (const auto& m : trace) {
    if (m.parted) break;
    if (m.neck_width <= width) return m.t;
  }
  return -1;
}

const SlabSample& sample_at_time(const std::vector<SlabSample>& trace, double t) {
  if (trace.empty()) throw std::invalid_argument("slab: no samples");
  std::size_t best = 0;
  for (std::size_t i = 0; i < trace.size(); ++i)
    if (std::abs(trace[i].t - t) < std::abs(trace[best].t - t)) best = i;
  return trace[best];
}

std::vector<SlabValue> slab_run_values(const SlabRunResult& r, bool artificial_stress, double dp, double sample_dt) {
  if (!artificial_stress)
    return {{"eps0_clumping_time", r.clumping_time, "first time two free particles were closer than 0.75 dp (-1: never)"},
            {"eps0_fracture_time", r.fracture_time, "the two ends in different pieces (-1: never)"},
            {"eps0_first_split_time", r.first_split_time, "first piece broken off (-1: never)"},
            {"eps0_opening_time", r.opening_time, "first gap of more than 2 dp between neighbouring columns (-1: never)"},
            {"eps0_opening_from_junction", r.opening_from_junction, "distance of that gap from the nearer band edge"}};
  // Where the text's neck is read (Sec 7.3, "at t = 542 ... only ~10 particles thick"): measurement points.
  const double neck_time = 542, neck_particles = 10;
  const auto& s394 = sample_at_time(r.trace, 394.0);  // the time of the Fig 10 caption
  // READING of "at t = 542, the notching reduces the central neck until it is only ~10 particles thick and it
  // fractures" (Sec 7.3): 542 the time the neck has narrowed to ~10 particles, the fracture after it; and ~10
  // particles the neck at t = 542, not at the last moment before parting.
  const auto& s542 = sample_at_time(r.trace, neck_time);
  // A run that stopped (parted) more than a sample before t = 394 has no value there (a peer's run can: nan).
  const bool has394 = std::abs(s394.t - 394.0) <= sample_dt;
  return {{"strain_at_t394", has394 ? s394.strain : NAN, "strain of the ends' separation at t = 394, measured from the bands"},
          {"eps0.3_pieces_at_t394", has394 ? static_cast<double>(s394.pieces) : NAN, "pieces at t = 394 (1 = intact)"},
          {"eps0.3_fracture_time", r.fracture_time, "the two ends in different pieces (-1: never)"},
          {"eps0.3_clumping_time", r.clumping_time, "first time two free particles were closer than 0.75 dp (-1: never)"},
          {"eps0.3_neck_before_fracture", r.neck_before_fracture, "neck width (cm) at the last sample before the ends parted"},
          {"eps0.3_neck_before_fracture_particles", r.neck_before_fracture / dp, "the same in particle spacings"},
          {"eps0.3_neck_10dp_time", first_neck_at_most(r.trace, neck_particles * dp),
           "first sample, before parting, with the neck at most 10 dp wide (-1: none)"},
          {"eps0.3_neck_at_t542", std::abs(s542.t - neck_time) <= sample_dt ? s542.neck_width : NAN,
           "neck width (cm) at t = 542, the time of the text's neck of ~10 particles (nan: the run ended before)"},
          {"eps0.3_onset_strain", r.onset_strain, "strain when the neck fell below 0.9 x the median width"},
          {"eps0.3_crack_from_centre", std::abs(r.crack_x - 0.5 * std::lround(3.0 / dp) * dp) / 3.0,
           "|crack x - slab centre| / length at fracture"}};
}

void set_summary(SlabRunResult& r, const SlabSummary& sum) {
  r.first_split_time = sum.first_split_time;
  r.fracture_time = sum.fracture_time;
  r.crack_x = sum.crack_x;
  r.crack_from_junction = sum.crack_from_junction;
  r.neck_before_fracture = sum.neck_before_fracture;
  r.onset_strain = sum.onset_strain;
  r.onset_time = sum.onset_time;
  r.clumping_time = sum.clumping_time;
  r.opening_time = sum.opening_time;
  r.opening_from_junction = sum.opening_from_junction;
}

}  // namespace scenes
