#include "ismail2009/scenes/hole_store.hpp"

#include <cstdint>
#include <sstream>

#include "frame/run_store.hpp"

namespace scenes {

// A field added to HoleParams or HoleResult must be added below: the sizes make the compiler say so.
static_assert(sizeof(HoleParams) == 120, "HoleParams changed: update hole_run_key");
static_assert(sizeof(HoleResult) == 160, "HoleResult changed: update the hole store's payload");

std::string hole_run_key(const HoleParams& p) {
  using sph::exact_text;
  std::ostringstream k;
  k << sph::run_store_key_prefix() << " hole n " << p.n << " a " << exact_text(p.a) << " R " << exact_text(p.R) << " E "
    << exact_text(p.E) << " nu " << exact_text(p.nu) << " rho " << exact_text(p.rho) << " traction "
    << exact_text(p.traction) << " h/ps " << exact_text(p.h_over_ps) << " dt " << exact_text(p.dt_factor) << " ramp "
    << exact_text(p.ramp_transits) << " settle " << exact_text(p.settle) << " damping " << exact_text(p.damping)
    << " variational " << p.variational << " hourglass " << exact_text(p.hourglass) << " hooke " << p.hooke
    << " passes " << p.closure_passes;
  return k.str();
}

std::optional<HoleResult> serve_hole_run(const HoleParams& p) {
  const auto payload = sph::run_store_read(sph::run_store_dir(), "hole", hole_run_key(p));
  if (!payload) return std::nullopt;
  std::istringstream in(*payload);
  HoleResult r;
  std::uint8_t finite = 0;
  std::uint64_t samples = 0;
  using sph::store_get;
  if (!store_get(in, r.particles) || !store_get(in, r.steps) || !store_get(in, r.wall_s) || !store_get(in, r.build_s) ||
      !store_get(in, r.peak_sigma1) || !store_get(in, r.sigma1_hole_top) || !store_get(in, r.peak_sigma1_dynamic) ||
      !store_get(in, r.smoothed_peak_sigma1) || !store_get(in, r.smoothed_sigma1_hole_top) ||
      !store_get(in, r.settle_change) || !store_get(in, r.zigzag) || !store_get(in, r.speed_rise) ||
      !store_get(in, r.rest_speed_ratio) || !store_get(in, r.fastest_X.x()) || !store_get(in, r.fastest_X.y()) ||
      !store_get(in, r.growth_rate) || !store_get(in, finite) || !store_get(in, samples))
    return std::nullopt;
  r.finite = finite != 0;
  r.history.resize(samples);
  for (auto& h : r.history)
    if (!store_get(in, h.t) || !store_get(in, h.smoothed_top) || !store_get(in, h.peak) || !store_get(in, h.vmax))
      return std::nullopt;  // truncated: treat as absent
  return r;
}

void store_hole_run(const HoleParams& p, const HoleResult& r) {
  const std::string dir = sph::run_store_dir();
  if (dir.empty()) return;
  std::ostringstream out;
  using sph::store_put;
  store_put(out, r.particles); store_put(out, r.steps); store_put(out, r.wall_s); store_put(out, r.build_s);
  store_put(out, r.peak_sigma1); store_put(out, r.sigma1_hole_top); store_put(out, r.peak_sigma1_dynamic);
  store_put(out, r.smoothed_peak_sigma1); store_put(out, r.smoothed_sigma1_hole_top); store_put(out, r.settle_change);
  store_put(out, r.zigzag); store_put(out, r.speed_rise); store_put(out, r.rest_speed_ratio);
  store_put(out, r.fastest_X.x()); store_put(out, r.fastest_X.y()); store_put(out, r.growth_rate);
  store_put(out, static_cast<std::uint8_t>(r.finite)); store_put(out, static_cast<std::uint64_t>(r.history.size()));
  for (const auto& h : r.history) {
    store_put(out, h.t); store_put(out, h.smoothed_top); store_put(out, h.peak); store_put(out, h.vmax);
  }
  sph::run_store_write(dir, "hole", hole_run_key(p), out.str());
}

}  // namespace scenes
