#include "gray2001/scenes/rings_store.hpp"

#include <sstream>

#include "frame/run_store.hpp"
#include "gray2001/scenes/scheme_key.hpp"

namespace scenes {

// A field added to one of these structs must be added below: the sizes make the compiler say so.
static_assert(sizeof(RingsSpec) == 5 * 8, "RingsSpec changed: update rings_run_key");
static_assert(sizeof(RingsRunSpec) == 40 + 96 + 8 + 5 * 8, "RingsRunSpec changed: update rings_run_key");
static_assert(sizeof(RingsSample) == 112, "RingsSample changed: update the rings store's payload");
static_assert(sizeof(RingsRunResult) == 152, "RingsRunResult changed: update the rings store's payload");

namespace {

// Every field of a result, in one order for writing and reading (frame/run_store.hpp's visitors); the samples as
// their bytes.
auto fields = [](auto& r, auto&& f) {
  return f(r.steps) && f(r.particles) && f(r.dt) && f(r.wall_s) && f(r.contact_start) && f(r.contact_end) &&
         f(r.rebound_speed) && f(r.restitution) && f(r.fracture_time) && f(r.max_fragments) && f(r.max_stray) &&
         f(r.min_main_share) && f(r.blow_up) && f(r.trace);
};

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
  return sph::served_or_stepped<RingsRunResult>(
      "rings", rings_run_key(s), progress_label, fields, [&] { return run_rings(s, {}, progress_label); },
      [](RingsRunResult& r) { return static_cast<long long>(r.particles) * r.steps; });
}

}  // namespace scenes
