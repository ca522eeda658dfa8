#include "gray2001/scenes/plate_run_cache.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sstream>

#include "core/run_loop.hpp"
#include "frame/run_store.hpp"
#include "gray2001/scenes/scheme_key.hpp"

namespace scenes {

namespace {

// A field added to PlateSpec must be added to the key below: the size makes the compiler say so.
static_assert(sizeof(PlateSpec) == 64, "PlateSpec changed: update plate_run_key");
static_assert(sizeof(PlateRunSpec) == 64 + 96 + 8 + 6 * 8 + 8, "PlateRunSpec changed: update plate_run_key and plate_whole_run_key");
static_assert(sizeof(TipSample) == 64 && sizeof(PlateRunResult) == 104, "PlateRunResult changed: update run_plate_stored's payload");

using sph::exact_text;

// Runs with and without the power budget are stored apart (the budget does not change the trajectory, but
// only a run that recorded it can serve a run that asks for it).
const char* variant(bool power_budget) { return power_budget ? "power" : ""; }

template <class T>
void put(std::ostream& o, const T& v) { sph::store_put(o, v); }
template <class T>
bool get(std::istream& i, T& v) { return sph::store_get(i, v); }

/// The stored run under `key`, if its file exists and names exactly that key.
std::optional<StoredPlateRun> load(const std::string& dir, const std::string& key, bool power_budget) {
  const auto payload = sph::run_store_read(dir, "plate", key, variant(power_budget));
  if (!payload) return std::nullopt;
  std::istringstream in(*payload);
  StoredPlateRun r;
  std::uint64_t n = 0, particles = 0;
  std::uint8_t power = 0;
  if (!get(in, r.dt) || !get(in, r.t_end) || !get(in, r.fracture_time) || !get(in, particles) || !get(in, power) ||
      !get(in, n))
    return std::nullopt;
  r.particles = particles;
  r.power_budget = power != 0;
  r.trace.resize(n);
  r.steps.resize(n);
  r.wall.resize(n);
  for (std::uint64_t k = 0; k < n; ++k) {
    TipSample& t = r.trace[k];
    std::uint64_t fragments = 0;
    std::int64_t step = 0;
    if (!get(in, t.t) || !get(in, t.y) || !get(in, t.ke) || !get(in, t.ee) || !get(in, fragments) ||
        !get(in, t.p_art) || !get(in, t.p_visc) || !get(in, t.p_xsph) || !get(in, step) || !get(in, r.wall[k]))
      return std::nullopt;  // truncated: treat as absent
    t.fragments = fragments;
    r.steps[k] = step;
  }
  return r;
}

}  // namespace

std::string plate_run_cache_dir() { return sph::run_store_dir(); }

std::string plate_run_key(const PlateRunSpec& s) {
  const PlateSpec& p = s.plate;
  std::ostringstream k;
  k << sph::run_store_key_prefix() << " plate L " << exact_text(p.L) << " H " << exact_text(p.H) << " dp "
    << exact_text(p.dp) << " clamp " << exact_text(p.clamp_length) << " layers " << p.clamp_layers << " Vf "
    << exact_text(p.Vf) << " perturbation " << exact_text(p.perturbation) << " seed " << p.seed << " "
    << gray_scheme_key(s.scheme, s.options) << " sample_dt " << exact_text(s.sample_dt) << " link " << exact_text(s.fracture_link) << " check_dt "
    << exact_text(s.fracture_check_dt);
  return k.str();
}

std::optional<PlateRunResult> serve_plate_run(const PlateRunSpec& s, const std::string& dir) {
  // Served: runs that stop at a zero crossing, without a step limit or a stop after fracture.
  if (dir.empty() || s.stop_after_crossings < 0 || s.max_steps >= 0 || s.run_after_fracture >= 0) return std::nullopt;
  const std::string key = plate_run_key(s);
  auto stored = load(dir, key, true);
  if (!s.power_budget) {  // either store serves it: the longer one
    auto plain = load(dir, key, false);
    if (plain && (!stored || plain->trace.size() > stored->trace.size())) stored = std::move(plain);
  }
  if (!stored) return std::nullopt;
  // The loop's own rule (run_plate): a crossing when sample k and k - 1 differ in sign, from k = 2 on.
  // Every sample of the prefix must lie before both runs' t_end, so that no step of it was shortened.
  const double t_limit = std::min(s.t_end, stored->t_end) - 1e-12;
  int crossings = 0;
  for (std::size_t k = 0; k < stored->trace.size(); ++k) {
    if (!(stored->trace[k].t < t_limit)) return std::nullopt;
    if (k == 0) continue;  // the start sample: the loop decides nothing there
    if (k >= 2 && (stored->trace[k].y > 0) != (stored->trace[k - 1].y > 0)) ++crossings;
    if (crossings < s.stop_after_crossings) continue;
    PlateRunResult r;
    r.trace.assign(stored->trace.begin(), stored->trace.begin() + static_cast<long>(k) + 1);
    if (!s.power_budget)
      for (TipSample& t : r.trace) t.p_art = t.p_visc = t.p_xsph = NAN;
    r.steps = stored->steps[k];
    r.particles = stored->particles;
    r.dt = stored->dt;
    r.fracture_time = (stored->fracture_time >= 0 && stored->fracture_time <= r.trace.back().t) ? stored->fracture_time : -1;
    r.wall_s = stored->wall[k];  // not stepped here: the stepping run's time loop up to the prefix's last sample
    r.reused = true;
    return r;
  }
  return std::nullopt;  // the stored run is too short
}

void store_plate_run(const PlateRunSpec& s, const StoredPlateRun& run, const std::string& dir) {
  if (dir.empty() || run.trace.empty()) return;
  const std::string key = plate_run_key(s);
  if (const auto old = load(dir, key, run.power_budget); old && old->trace.size() >= run.trace.size())
    return;  // the stored run already holds this one
  std::ostringstream out;
  put(out, run.dt);
  put(out, run.t_end);
  put(out, run.fracture_time);
  put(out, static_cast<std::uint64_t>(run.particles));
  put(out, static_cast<std::uint8_t>(run.power_budget));
  put(out, static_cast<std::uint64_t>(run.trace.size()));
  for (std::size_t k = 0; k < run.trace.size(); ++k) {
    const TipSample& t = run.trace[k];
    put(out, t.t); put(out, t.y); put(out, t.ke); put(out, t.ee);
    put(out, static_cast<std::uint64_t>(t.fragments));
    put(out, t.p_art); put(out, t.p_visc); put(out, t.p_xsph);
    put(out, static_cast<std::int64_t>(run.steps[k]));
    put(out, run.wall[k]);
  }
  sph::run_store_write(dir, "plate", key, out.str(), variant(run.power_budget));
}

std::string plate_whole_run_key(const PlateRunSpec& s) {
  std::ostringstream k;
  k << plate_run_key(s) << " t_end " << exact_text(s.t_end) << " max_steps " << s.max_steps << " after "
    << exact_text(s.run_after_fracture) << " crossings " << s.stop_after_crossings << " power " << s.power_budget;
  return k.str();
}

PlateRunResult run_plate_stored(const PlateRunSpec& s, const std::string& progress_label) {
  // Every field of the result (frame/run_store.hpp's visitors); the samples as their bytes.
  auto fields = [](auto& r, auto&& f) {
    return f(r.steps) && f(r.particles) && f(r.dt) && f(r.wall_s) && f(r.fracture_time) && f(r.blow_up) && f(r.trace);
  };
  return sph::served_or_stepped<PlateRunResult>(
      "plate-whole", plate_whole_run_key(s), progress_label, fields, [&] { return run_plate(s, {}, progress_label); },
      [](PlateRunResult& q) {
        q.reused = true;
        return static_cast<long long>(q.particles) * q.steps;
      });
}

}  // namespace scenes
