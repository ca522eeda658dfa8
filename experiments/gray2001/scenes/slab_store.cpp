#include "gray2001/scenes/slab_store.hpp"

#include <cstdint>
#include <cstdio>
#include <sstream>

#include "core/run_loop.hpp"
#include "frame/run_store.hpp"
#include "gray2001/scenes/scheme_key.hpp"

namespace scenes {

// A field added to one of these structs must be added below: the sizes make the compiler say so.
static_assert(sizeof(SlabSpec) == 64, "SlabSpec changed: update slab_run_key");
static_assert(sizeof(SlabRunSpec) == 64 + 96 + 8 + 8 * 8, "SlabRunSpec changed: update slab_run_key");
static_assert(sizeof(SlabSample) == 12 * 8 + 8, "SlabSample changed: update the slab store's payload");
static_assert(sizeof(SlabRunResult) == 168, "SlabRunResult changed: update the slab store's payload");

namespace {
using sph::store_get;
using sph::store_put;
using sph::store_get_text;
using sph::store_put_text;
}  // namespace

std::string slab_run_key(const SlabRunSpec& s, const std::string& files_tag) {
  using sph::exact_text;
  const SlabSpec& b = s.slab;
  std::ostringstream k;
  k << sph::run_store_key_prefix() << " slab L " << exact_text(b.L) << " H " << exact_text(b.H) << " dp " << exact_text(b.dp)
    << " band " << exact_text(b.band) << " accel " << exact_text(b.end_accel) << " margin " << exact_text(b.margin)
    << " jitter " << exact_text(b.jitter) << " seed " << b.seed << " " << gray_scheme_key(s.scheme, s.options) << " t_max "
    << exact_text(s.t_max) << " after " << exact_text(s.run_after_fracture) << " sample_dt " << exact_text(s.sample_dt)
    << " link " << exact_text(s.fracture_link) << " bin " << exact_text(s.neck_bin) << " onset "
    << exact_text(s.neck_ratio_onset) << " clump " << exact_text(s.clump_ratio) << " gap " << exact_text(s.opening_gap)
    << " files " << files_tag;
  return k.str();
}

std::optional<StoredSlabRun> serve_slab_run(const SlabRunSpec& s, const std::string& files_tag) {
  const auto payload = sph::run_store_read(sph::run_store_dir(), "slab", slab_run_key(s, files_tag));
  if (!payload) return std::nullopt;
  std::istringstream in(*payload);
  StoredSlabRun stored;
  SlabRunResult& r = stored.result;
  std::uint64_t particles = 0, samples = 0, files = 0;
  std::int64_t steps = 0;
  if (!store_get(in, steps) || !store_get(in, particles) || !store_get(in, r.dt) || !store_get(in, r.wall_s) ||
      !store_get(in, r.first_split_time) || !store_get(in, r.fracture_time) || !store_get(in, r.crack_x) ||
      !store_get(in, r.crack_from_junction) || !store_get(in, r.neck_before_fracture) || !store_get(in, r.onset_strain) ||
      !store_get(in, r.onset_time) || !store_get(in, r.clumping_time) || !store_get(in, r.opening_time) ||
      !store_get(in, r.opening_from_junction) || !store_get_text(in, r.blow_up) || !store_get(in, samples))
    return std::nullopt;
  r.steps = steps;
  r.particles = particles;
  r.trace.resize(samples);
  for (auto& m : r.trace) {
    std::uint64_t pieces = 0;
    std::int32_t parted = 0;
    if (!store_get(in, m.t) || !store_get(in, m.extension) || !store_get(in, m.strain) || !store_get(in, m.ke) ||
        !store_get(in, m.ee) || !store_get(in, m.neck_width) || !store_get(in, m.neck_x) || !store_get(in, m.median_width) ||
        !store_get(in, m.closest) || !store_get(in, m.widest_gap) || !store_get(in, m.gap_x) || !store_get(in, pieces) ||
        !store_get(in, parted))
      return std::nullopt;  // truncated: treat as absent
    m.pieces = pieces;
    m.parted = parted;
  }
  if (!store_get(in, files)) return std::nullopt;
  stored.files.resize(files);
  for (auto& [name, bytes] : stored.files)
    if (!store_get_text(in, name) || !store_get_text(in, bytes)) return std::nullopt;
  return stored;
}

void store_slab_run(const SlabRunSpec& s, const std::string& files_tag, const StoredSlabRun& stored) {
  const std::string dir = sph::run_store_dir();
  if (dir.empty()) return;
  const SlabRunResult& r = stored.result;
  std::ostringstream out;
  store_put(out, static_cast<std::int64_t>(r.steps)); store_put(out, static_cast<std::uint64_t>(r.particles));
  store_put(out, r.dt); store_put(out, r.wall_s); store_put(out, r.first_split_time); store_put(out, r.fracture_time);
  store_put(out, r.crack_x); store_put(out, r.crack_from_junction); store_put(out, r.neck_before_fracture);
  store_put(out, r.onset_strain); store_put(out, r.onset_time); store_put(out, r.clumping_time);
  store_put(out, r.opening_time); store_put(out, r.opening_from_junction); store_put_text(out, r.blow_up);
  store_put(out, static_cast<std::uint64_t>(r.trace.size()));
  for (const auto& m : r.trace) {
    store_put(out, m.t); store_put(out, m.extension); store_put(out, m.strain); store_put(out, m.ke); store_put(out, m.ee);
    store_put(out, m.neck_width); store_put(out, m.neck_x); store_put(out, m.median_width); store_put(out, m.closest);
    store_put(out, m.widest_gap); store_put(out, m.gap_x); store_put(out, static_cast<std::uint64_t>(m.pieces));
    store_put(out, static_cast<std::int32_t>(m.parted));
  }
  store_put(out, static_cast<std::uint64_t>(stored.files.size()));
  for (const auto& [name, bytes] : stored.files) {
    store_put_text(out, name);
    store_put_text(out, bytes);
  }
  sph::run_store_write(dir, "slab", slab_run_key(s, files_tag), out.str());
}

SlabRunResult run_slab_stored(const SlabRunSpec& s, const std::string& progress_label) {
  if (auto stored = serve_slab_run(s, "none")) {
    sph::particle_steps_reused() += static_cast<long long>(stored->result.particles) * stored->result.steps;
    std::fprintf(stderr, "%s: a stored run (%s), not stepped again\n", progress_label.c_str(), sph::run_store_dir().c_str());
    return stored->result;
  }
  StoredSlabRun done;
  done.result = run_slab(s, {}, progress_label);
  store_slab_run(s, "none", done);
  return done.result;
}

}  // namespace scenes
