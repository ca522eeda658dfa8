#include "hoover2004/scenes/hexagon_store.hpp"

#include <sstream>

#include "frame/run_store.hpp"

namespace sph::scenes {

// A field added to one of these structs must be added below: the sizes make the compiler say so.
static_assert(sizeof(Box2) == 40, "Box2 changed: update hexagon_run_key");
static_assert(sizeof(SpamParams) == 9 * 8 + 40, "SpamParams changed: update hexagon_run_key");
static_assert(sizeof(SpamOptions) == 20, "SpamOptions changed: update hexagon_run_key");
static_assert(sizeof(HexagonSetup) == 184, "HexagonSetup changed: update hexagon_run_key");
static_assert(sizeof(HexagonRun) == 384, "HexagonRun changed: update the hexagon store's payload");

namespace {

// Every field of a run but the variant's name (the key's), in one order for writing and reading
// (frame/run_store.hpp's visitors).
auto fields = [](auto& r, auto&& f) {
  return f(r.t) && f(r.L) && f(r.K) && f(r.U) && f(r.shape_rms) && f(r.angle) && f(r.gauss_D) && f(r.gauss_beta) &&
         f(r.snapshot_angles) && f(r.snapshots) && f(r.snapshot_density) && f(r.advection_torque_integral) && f(r.L0) &&
         f(r.E0) && f(r.failed) && f(r.failed_at) && f(r.steps) && f(r.wall_s) && f(r.gauss_floor_hits) && f(r.reflections);
};

}  // namespace

std::string hexagon_run_key(const HexagonSetup& s, const HexagonVariant& v) {
  const SpamParams& p = s.params;
  const SpamOptions& o = v.options;
  std::ostringstream k;
  k << run_store_key_prefix() << " hexagon shells " << s.shells << " vmax " << exact_text(s.vmax) << " dt " << exact_text(s.dt)
    << " revolutions " << exact_text(s.revolutions) << " sample_every " << s.sample_every << " snapshot_angles";
  for (const double a : s.snapshot_angles) k << " " << exact_text(a);
  k << " mass " << exact_text(p.mass) << " h " << exact_text(p.h) << " lambda " << exact_text(p.lambda) << " eta "
    << exact_text(p.eta) << " visc_c " << exact_text(p.viscosity_coefficient) << " visc_dx " << exact_text(p.viscosity_length)
    << " closest " << exact_text(p.closest_distance) << " gauss_floor " << exact_text(p.gauss_floor) << " skin "
    << exact_text(p.skin_over_h) << " box " << exact_text(p.box.xmin) << " " << exact_text(p.box.ymin) << " "
    << exact_text(p.box.xmax) << " " << exact_text(p.box.ymax) << " " << p.box.periodic_x << p.box.periodic_y
    << " advection_torque " << s.track_advection_torque << " variant " << v.name << " density " << to_string(o.density)
    << " advection " << to_string(o.advection) << " chain " << o.chain_rule << " torque " << to_string(o.torque) << " visc "
    << o.viscosity << " approach " << o.closest_approach;
  return k.str();
}

HexagonRun run_hexagon_stored(const HexagonSetup& s, const HexagonVariant& v) {
  return served_or_stepped<HexagonRun>(
      "hexagon", hexagon_run_key(s, v), "hexagon " + v.name, fields,
      [&] { return v.name == "md" ? run_hexagon_md(s) : run_hexagon_spam(s, v.options, v.name); },
      [&](HexagonRun& r) {
        r.variant = v.name;
        return static_cast<long long>(s.lattice().size()) * r.steps;
      });
}

}  // namespace sph::scenes
