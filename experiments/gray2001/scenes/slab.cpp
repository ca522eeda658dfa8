#include "gray2001/scenes/slab.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "core/diagnostics.hpp"
#include "core/fragments.hpp"
#include "core/lattices.hpp"
#include "core/run_loop.hpp"
#include "frame/progress.hpp"

namespace scenes {

sph::GrayParameters slab_scheme() {
  sph::GrayParameters p;
  p.mu = 0.3;
  return p;
}

sph::GrayOptions slab_options() {
  sph::GrayOptions o;
  o.plasticity = true;
  return o;
}

void check_size(const SlabSpec& s) {
  sph::check_particle_count((s.L / s.dp) * (s.H / s.dp), s.dp, "slab");
}

Slab make_slab(const SlabSpec& s, double rho0) {
  if (!(s.dp > 0) || !(s.L > 0) || !(s.H > 0) || !(s.band > 0) || s.end_accel < 0 || !(s.margin > 0))
    throw std::invalid_argument("slab: need dp, L, H, band, margin > 0 and end acceleration >= 0");
  check_size(s);
  const long nx = std::lround(s.L / s.dp), ny = std::lround(s.H / s.dp);
  Slab slab;
  slab.nx = nx;
  slab.ny = ny;
  slab.length = nx * s.dp;
  slab.height = ny * s.dp;
  if (ny < 3 || 2.0 * s.band >= slab.length - 2.0 * s.dp)
    throw std::invalid_argument("slab: need at least 3 particles across and free particles between the bands");
  if (!(s.jitter >= 0) || s.jitter >= 0.1) throw std::invalid_argument("slab: need 0 <= jitter < 0.1 (in dp)");
  const double m = rho0 * s.dp * s.dp;
  std::mt19937_64 random(s.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (long j = 0; j < ny; ++j)
    for (long i = 0; i < nx; ++i) {
      sph::Vec2 x((i + 0.5) * s.dp, (j + 0.5) * s.dp);
      const bool left = x.x() < s.band, right = x.x() > slab.length - s.band;  // of the lattice site
      if (s.jitter > 0) x += s.jitter * s.dp * sph::Vec2(unit(random), unit(random));
      if (left || right) {
        (left ? slab.left_band : slab.right_band).push_back(slab.body.size());
        slab.body.add(x, sph::Vec2::Zero(), m, rho0, sph::Motion::Driven, sph::Vec2(left ? -s.end_accel : s.end_accel, 0.0));
      } else {
        slab.body.add(x, sph::Vec2::Zero(), m, rho0);
      }
    }
  if (slab.left_band.empty() || slab.right_band.empty()) throw std::invalid_argument("slab: band narrower than dp / 2");
  slab.body.dp = s.dp;
  slab.body.box = {-s.margin, -s.margin, slab.length + s.margin, slab.height + s.margin, false, false};
  return slab;
}

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

  Neck measure(const sph::ElasticBody& body, double x_from, double x_to, double dp) {
    const std::size_t nb = x_to > x_from ? static_cast<std::size_t>((x_to - x_from) / bin_) : 0;
    if (nb == 0 || nb > width_.size()) return {NAN, NAN, NAN};
    std::fill_n(ymin_.begin(), nb, std::numeric_limits<double>::infinity());
    std::fill_n(ymax_.begin(), nb, -std::numeric_limits<double>::infinity());
    std::fill_n(count_.begin(), nb, 0);
    for (std::size_t a = 0; a < body.size(); ++a) {
      if (body.motion[a] != sph::Motion::Free) continue;
      const double u = (body.x[a].x() - x_from) / bin_;
      if (u < 0 || u >= static_cast<double>(nb)) continue;
      const std::size_t k = static_cast<std::size_t>(u);
      ymin_[k] = std::min(ymin_[k], body.x[a].y());
      ymax_[k] = std::max(ymax_[k], body.x[a].y());
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

// The mean x of each lattice column (particle a in column a % nx) and the widest gap between neighbouring
// columns: where the body opens. Clumping pairs columns up (gaps alternate ~0.6 and ~1.4 dp); a gap of two
// spacings is a column's worth of void. Arrays sized once.
class ColumnGaps {
 public:
  explicit ColumnGaps(long nx) : sum_(static_cast<std::size_t>(nx)), count_(static_cast<std::size_t>(nx)) {}

  struct Gap { double width, x; };

  Gap widest(const sph::ElasticBody& body) {
    const std::size_t nx = sum_.size();
    std::fill(sum_.begin(), sum_.end(), 0.0);
    std::fill(count_.begin(), count_.end(), 0);
    for (std::size_t a = 0; a < body.size(); ++a) {
      sum_[a % nx] += body.x[a].x();
      ++count_[a % nx];
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

double mean_x(const sph::ElasticBody& body, const std::vector<std::size_t>& idx) {
  double s = 0;
  for (std::size_t a : idx) s += body.x[a].x();
  return s / static_cast<double>(idx.size());
}

}  // namespace

SlabRunResult run_slab(const SlabRunSpec& s, const SlabObserver& on_sample, const std::string& progress_label) {
  if (!(s.t_max > 0) || !(s.sample_dt > 0) || !(s.fracture_link > 0) || !(s.neck_bin >= 1) || !(s.clump_ratio > 0) ||
      !(s.opening_gap > 1))
    throw std::invalid_argument("slab run: need t_max, sample_dt, fracture_link, clump_ratio > 0, neck_bin >= 1, opening_gap > 1");
  const double reach = 0.5 * s.slab.end_accel * s.t_max * s.t_max;
  if (reach > 0.9 * s.slab.margin)
    throw std::invalid_argument("slab run: the ends would travel " + std::to_string(reach) + " by t_max: raise the margin");
  Slab slab = make_slab(s.slab, s.scheme.rho0);
  sph::ElasticBody& body = slab.body;
  sph::GraySolver solver(body, s.scheme, s.options);
  SlabRunResult r;
  r.dt = solver.time_step(s.slab.end_accel * s.t_max);
  r.particles = body.size();
  const double dp = s.slab.dp;
  const double sep0 = mean_x(body, slab.right_band) - mean_x(body, slab.left_band);
  NeckMeter neck(body.box, s.neck_bin * dp);
  ColumnGaps columns(slab.nx);

  auto sample = [&] {
    const auto f = sph::find_fragments(body.x, body.box, s.fracture_link * dp);
    const std::size_t piece_l = f.label[slab.left_band.front()], piece_r = f.label[slab.right_band.front()];
    const bool parted = piece_l != piece_r;
    double junction_l = -std::numeric_limits<double>::infinity(), junction_r = std::numeric_limits<double>::infinity();
    for (std::size_t a : slab.left_band) junction_l = std::max(junction_l, body.x[a].x());
    for (std::size_t a : slab.right_band) junction_r = std::min(junction_r, body.x[a].x());
    const auto nk = neck.measure(body, junction_l, junction_r, dp);
    const double ext = mean_x(body, slab.right_band) - mean_x(body, slab.left_band) - sep0;
    const auto& pairs = solver.pairs();
    double closest = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < body.size(); ++a) {
      if (body.motion[a] != sph::Motion::Free) continue;
      for (std::uint32_t k = pairs.start[a]; k < pairs.start[a + 1]; ++k) {  // every candidate (the box is not periodic)
        const std::uint32_t c = pairs.cand[k];
        if (body.motion[c] == sph::Motion::Free) closest = std::min(closest, (body.x[a] - body.x[c]).norm());
      }
    }
    const auto gap = columns.widest(body);
    r.trace.push_back({solver.time(), ext, ext / slab.length, sph::kinetic_energy(solver), solver.elastic_energy(), nk.width, nk.x,
                       nk.median, closest, gap.width, gap.x, f.count, parted ? 1 : 0});
    if (closest < s.clump_ratio * dp && r.clumping_time < 0) r.clumping_time = solver.time();
    if (gap.width > s.opening_gap * dp && r.opening_time < 0) {
      r.opening_time = solver.time();
      r.opening_from_junction = std::max(0.0, std::min(gap.x - junction_l, junction_r - gap.x));
    }
    if (f.count > 1 && r.first_split_time < 0) r.first_split_time = solver.time();
    if (!parted && std::isnan(r.onset_time) && nk.width < s.neck_ratio_onset * nk.median) {
      r.onset_time = solver.time();
      r.onset_strain = ext / slab.length;
    }
    if (parted && r.fracture_time < 0) {
      r.fracture_time = solver.time();
      double xl = -std::numeric_limits<double>::infinity(), xr = std::numeric_limits<double>::infinity();
      for (std::size_t a = 0; a < body.size(); ++a) {
        if (f.label[a] == piece_l) xl = std::max(xl, body.x[a].x());
        if (f.label[a] == piece_r) xr = std::min(xr, body.x[a].x());
      }
      r.crack_x = 0.5 * (xl + xr);
      r.crack_from_junction = std::min(xl - junction_l, junction_r - xr);
      if (r.trace.size() >= 2) r.neck_before_fracture = r.trace[r.trace.size() - 2].neck_width;
    }
    if (on_sample) on_sample(solver, body, r.trace.back());
  };
  sph::Progress progress(progress_label, s.t_max);
  auto parted_long_enough = [&] {
    return r.fracture_time >= 0 && s.run_after_fracture >= 0 && solver.time() >= r.fracture_time + s.run_after_fracture;
  };
  sph::Cadence samples(s.sample_dt);
  auto observe = [&](const sph::GraySolver& sv) {
    if (!samples.due(sv.time())) return false;
    sample();
    return sv.steps() > 0 && parted_long_enough();
  };
  r.blow_up = sph::run(solver, {r.dt, -1, s.t_max}, observe,
                       [&](const sph::GraySolver& sv) { progress.update(sv.time(), sv.steps()); }).blow_up;
  r.steps = solver.steps();
  r.wall_s = progress.elapsed_s();
  return r;
}

}  // namespace scenes
