#include "gray2001/scenes/hexagon_gray.hpp"

#include <algorithm>
#include <cmath>

#include "core/diagnostics.hpp"
#include "core/fragments.hpp"
#include "core/lattices.hpp"
#include "core/run_loop.hpp"
#include "frame/progress.hpp"
#include "updated_lagrangian/elastic_body.hpp"

namespace scenes {

sph::GrayParameters gray_hexagon_scheme(const sph::SpamParams& spam, double cfl) {
  sph::GrayParameters p;
  p.rho0 = std::sqrt(4.0 / 3.0);  // m = 1 per sqrt(3)/2 of area
  p.c0 = std::sqrt((spam.lambda + spam.eta) / p.rho0);
  p.mu = spam.eta / (p.rho0 * p.c0 * p.c0);  // in units of rho0 c0^2
  p.cfl = cfl;
  return p;
}

GrayHexagonResult run_gray_hexagon(const GrayHexagonSpec& s, const std::string& progress_label) {
  if (!(s.angle > 0) || !(s.sample_dt > 0) || !(s.fracture_link > 0))
    throw std::invalid_argument("Gray hexagon: need angle, sample_dt and fracture_link > 0");
  const sph::GrayParameters scheme = gray_hexagon_scheme(s.hexagon.params, s.cfl);
  const double omega = s.hexagon.omega();
  sph::ElasticBody body;
  body.dp = 1.0;
  for (const sph::Vec2& x : s.hexagon.lattice()) body.add(x, omega * sph::Vec2(-x.y(), x.x()), 1.0, scheme.rho0);
  const double a = s.hexagon.shells + 4.0;
  body.box = {-a, -a, a, a, false, false};
  sph::GraySolver solver(body, scheme, s.options);
  GrayHexagonResult r;
  r.particles = body.size();
  r.dt = solver.time_step(s.hexagon.vmax);
  const double L0 = sph::centre_of_mass_frame(solver).angular_momentum, t_end = s.angle / omega;
  sph::Progress progress(progress_label, t_end);
  sph::Cadence checks(s.sample_dt);
  auto observe = [&](const sph::GraySolver& sv) {
    if (checks.due(sv.time()))
      r.max_fragments = std::max(r.max_fragments, sph::find_fragments(body.x, body.box, s.fracture_link).sizes.size());
    return false;
  };
  r.blow_up = sph::run(solver, {r.dt, -1, t_end}, observe,
                       [&](const sph::GraySolver& sv) { progress.update(sv.time(), sv.steps()); }).blow_up;
  if (r.blow_up.empty()) r.L_loss = 1.0 - sph::centre_of_mass_frame(solver).angular_momentum / L0;
  r.steps = solver.steps();
  r.wall_s = progress.elapsed_s();
  return r;
}

}  // namespace scenes
