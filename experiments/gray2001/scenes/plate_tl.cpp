#include "gray2001/scenes/plate_tl.hpp"

#include <cmath>
#include <stdexcept>

#include "core/materials.hpp"
#include "core/run_loop.hpp"
#include "frame/progress.hpp"
#include "gray2001/scenes/plate.hpp"
#include "ismail2009/scenes/domain_2d.hpp"
#include "total_lagrangian/solver_2d.hpp"

namespace scenes {

using sph::Vec2;

TlPlateResult run_tl_plate(const TlPlateSpec& s, const std::string& progress_label) {
  const double across = s.H / s.ps, along = s.L / s.ps;
  if (!(s.ps > 0) || std::abs(across - std::round(across)) > 1e-9 || std::abs(along - std::round(along)) > 1e-9 ||
      std::lround(across) % 2 != 0)
    throw std::invalid_argument("run_tl_plate: L / ps and H / ps must be integers, H / ps even (a particle at (L, H/2))");
  const double E = sph::young_from_bulk_shear(s.K, s.mu), nu = sph::poisson_ratio_from_bulk_shear(s.K, s.mu);
  const sph::Lame lame = sph::lame_from_young_poisson(E, nu);
  const double rho = 1.0;
  auto zero = [](const Vec2&, double) { return 0.0; };
  const auto cond = sph::boundary_condition;
  // Conditions: 0 the clamp x = 0 (u = 0), 1 free (right, bottom, top).
  std::vector<sph::BoundaryCondition2D> conds{cond(true, zero, true, zero), cond(false, zero, false, zero)};
  auto cfg = make_body(rectangle_domain(s.L, s.H, 0, 1, 1, 1), conds, s.ps, s.h_over_ps);
  cfg.rho = rho;
  cfg.lame = lame;
  cfg.law = s.hooke ? sph::TlConfig2D::Law::Hooke : sph::TlConfig2D::Law::NeoHookean;
  cfg.closure = s.variational ? sph::TlConfig2D::Closure::Variational : sph::TlConfig2D::Closure::GhostReflection;
  sph::TlSolver2D body(std::move(cfg));
  TlPlateResult r;
  r.particles = body.n_real();
  r.dt = s.dt_factor * body.h() / sph::longitudinal_wave_speed(lame, rho);
  const double c0 = std::sqrt(s.K / rho);
  body.set_initial_velocity([&](const Vec2& X) { return Vec2(0.0, c0 * cantilever_mode_velocity(X.x(), s.L, s.Vf)); }, r.dt);
  const int tip = body.nearest({s.L, 0.5 * s.H});
  const double dV = s.ps * s.ps;
  int crossings = 0;
  auto observe = [&](const sph::TlSolver2D& b) {
    if (b.steps() == 0) return false;
    double ke = 0, ee = 0;
    for (int i = 0; i < b.n_real(); ++i) {
      ke += 0.5 * rho * dV * b.velocity(i).squaredNorm();
      ee += dV * sph::neo_hookean_energy<2>(lame, b.F(i));
    }
    // u and the velocity are of t; F of the step before (TlSolver2D::F): the energy is sampled a step apart.
    r.trace.push_back({b.time(), b.u(tip).y(), ke, ee, 1});
    const std::size_t k = r.trace.size();
    if (k > 2 && (r.trace[k - 1].y > 0) != (r.trace[k - 2].y > 0)) ++crossings;
    return s.stop_after_crossings >= 0 && crossings >= s.stop_after_crossings;
  };
  sph::Progress progress(progress_label, s.t_end);
  const auto outcome = sph::run(body, {r.dt, static_cast<long>(std::ceil(s.t_end / r.dt))}, observe,
                                [&](const sph::TlSolver2D& b) { progress.update(b.time(), b.steps()); });
  r.steps = outcome.steps;
  r.wall_s = outcome.wall_s;
  r.blow_up = outcome.blow_up;
  return r;
}

}  // namespace scenes
