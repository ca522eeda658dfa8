#include "gray2001/scenes/rings_store.hpp"

#include <cstdint>
#include <cstdio>
#include <sstream>

#include "core/run_loop.hpp"
#include "frame/run_store.hpp"
#include "gray2001/scenes/scheme_key.hpp"

namespace scenes {

// A field added to one of these structs must be added below: the sizes make the compiler say so.
static_assert(sizeof(RingsSpec) == 5 * 8, "RingsSpec changed: update rings_run_key");
static_assert(sizeof(RingsRunSpec) == 40 + 96 + 8 + 5 * 8, "RingsRunSpec changed: update rings_run_key");
static_assert(sizeof(RingsSample) == 112, "RingsSample changed: update the rings store's payload");
static_assert(sizeof(RingsRunResult) == 152, "RingsRunResult changed: update the rings store's payload");

namespace {

using sph::store_get;
using sph::store_put;

// Every field of a sample, in one order for writing and reading.
template <class Sample, class F>
bool each_field(Sample& m, F&& f) {
  return f(m.t) && f(m.ke) && f(m.ke_com) && f(m.ee) && f(m.v_left) && f(m.v_right) && f(m.x_left) && f(m.x_right) &&
         f(m.min_distance) && f(m.contact) && f(m.fragments_left) && f(m.fragments_right) && f(m.stray) && f(m.main_share);
}

template <class Result, class F>
bool each_scalar(Result& r, F&& f) {
  return f(r.steps) && f(r.particles) && f(r.dt) && f(r.wall_s) && f(r.contact_start) && f(r.contact_end) &&
         f(r.rebound_speed) && f(r.restitution) && f(r.fracture_time) && f(r.max_fragments) && f(r.max_stray) &&
         f(r.min_main_share);
}

}  // namespace

std::string rings_run_key(const RingsRunSpec& s) {
  using sph::exact_text;
  const RingsSpec& g = s.rings;
  std::ostringstream k;
  k << sph::run_store_key_prefix() << " rings inner " << exact_text(g.r_inner) << " outer " << exact_text(g.r_outer) << " dp "
    << exact_text(g.dp) << " gap " << exact_text(g.gap) << " speed " << exact_text(g.speed) << " "
    << gray_scheme_key(s.scheme, s.options) << " t_max " << exact_text(s.t_max) << " after " << exact_text(s.run_after_contact)
    << " sample_dt " << exact_text(s.sample_dt) << " link " << exact_text(s.fracture_link) << " min_fragment " << s.min_fragment;
  return k.str();
}

RingsRunResult run_rings_stored(const RingsRunSpec& s, const std::string& progress_label) {
  const std::string dir = sph::run_store_dir(), key = rings_run_key(s);
  if (const auto payload = sph::run_store_read(dir, "rings", key)) {
    std::istringstream in(*payload);
    RingsRunResult r;
    auto get = [&](auto& v) { return store_get(in, v); };
    std::uint64_t n = 0;
    bool ok = each_scalar(r, get) && sph::store_get_text(in, r.blow_up) && get(n);
    if (ok) {
      r.trace.resize(n);
      for (auto& m : r.trace) ok = ok && each_field(m, get);
    }
    if (ok) {  // else truncated: stepped again
      sph::particle_steps_reused() += static_cast<long long>(r.particles) * r.steps;
      std::fprintf(stderr, "%s: a stored run (%s), not stepped again\n", progress_label.c_str(), dir.c_str());
      return r;
    }
  }
  RingsRunResult r = run_rings(s, {}, progress_label);
  if (!dir.empty()) {
    std::ostringstream out;
    auto put = [&](const auto& v) { store_put(out, v); return true; };
    each_scalar(r, put);
    sph::store_put_text(out, r.blow_up);
    store_put(out, static_cast<std::uint64_t>(r.trace.size()));
    for (auto& m : r.trace) each_field(m, put);
    sph::run_store_write(dir, "rings", key, out.str());
  }
  return r;
}

}  // namespace scenes
