// Ismail 2009 (thesis), Figs 5.7-5.12 (Section 5.4): 2D plane-strain neo-Hookean total Lagrangian SPH.
//   Figs 5.7, 5.3  strain wave: the 0.15 m bar, 6 particles thick, sides held transversely (u2 = 0, free to
//                  slide): a tensile pulse travels at c_L = 5801 m/s, uniform across the thickness
//   Figs 5.8, 5.9  stress wave: the same bar with free sides; the thesis expects c_b = sqrt(E/rho) = 5000 m/s
//   Figs 5.10-5.12 a 31 x 6 particle block stretched to l1 = 6 with l2 = 1, l2 = 2, and l2 rising linearly to
//                  2; the centre particle's Cauchy T11 against eq (5.5) (l3 = 1, plane strain)
// Material as Section 5.3.1: rho = 8000, E = 200 GPa, nu = 0.3 (the text names no other for Section 5.4).
// CHOSEN: square lattice, h = 3.5 ps (the interior lattice error of the plain SPH gradient of a linear field is
// 0.13% at 3.5 ps, 1.8% at 2.5 ps: a uniform stretch would not be an equilibrium at smaller covers); wave bar:
// ps = 0.5 mm (301 x 6 particles), the pulse and gauges of I-bar (5 us, smoothing 0.5 us, 100 kPa), dt =
// 0.3 h/c_L; block: ps = 0.5 mm (15 mm x 2.5 mm, the 1D test's 15 mm bar), left/right edges hold u1 (right end
// ramped linearly over 30 transit times L/c_L, as I-nh1d) and are free to slide, top/bottom hold u2 = (l2 - 1) Y
// and are free to slide; l2 = 2 is applied as the initial state (at rest); the linear path ramps u2 with u1.
#include <cmath>
#include <string>
#include <vector>

#include "frame/driver.hpp"
#include "core/materials.hpp"
#include "ismail2009/scenes/bar.hpp"
#include "core/run_loop.hpp"
#include "io/snapshot.hpp"
#include "ismail2009/scenes/domain_2d.hpp"
#include "ismail2009/scenes/wave_2d.hpp"
#include "total_lagrangian/solver_2d.hpp"

namespace {

using sph::Vec2;

const auto condition = sph::boundary_condition;
const auto zero = [](const Vec2&, double) { return 0.0; };

struct Params {
  double rho = 8000, E = 200e9, nu = 0.3, L = 0.15, ps_wave = 0.5e-3, ps_block = 0.5e-3, h_over_ps = 3.5, p0 = 1e5,
         pulse = 5e-6, smooth = 0.5e-6, transits = 30, stretch = 6;
  int rows = 6, block_nx = 31;
};

void declare(sph::Driver& d, Params& p) {
  d.param("rho", p.rho, "density, kg/m^3").positive();
  d.param("E", p.E, "Young's modulus, Pa");
  d.param("nu", p.nu, "Poisson's ratio").above(-1).below(0.5);
  d.param("ps-wave", p.ps_wave, "spacing of the wave bar, m (CHOSEN)").positive().quick(1.5e-3);
  d.param("rows", p.rows, "particles across the thickness (Section 5.4.2: six)");
  d.param("ps-block", p.ps_block, "spacing of the 31 x 6 block, m (CHOSEN)").positive();
  d.param("block-nx", p.block_nx, "particles along the block (Section 5.4.3: 31)").positive();
  d.param("h-over-ps", p.h_over_ps, "cover radius in spacings (CHOSEN)").positive();
  d.param("transits", p.transits, "loading time in transit times (CHOSEN as Section 5.3.2)").positive();
}

// Figs 5.7-5.9: strain and stress waves (scenes/wave_2d.hpp: the strip, its run, its measurements).
void strain_and_stress_waves(sph::Driver& d, const Params& p) {
  auto wcsv = d.csv("waves.csv", {"case", "t", "gauge_x", "row", "T11"});
  for (const std::string kind : {"strain", "stress"}) {
    scenes::Wave2DSpec spec;
    spec.kind = kind;
    spec.rho = p.rho;
    spec.E = p.E;
    spec.nu = p.nu;
    spec.L = p.L;
    spec.ps = p.ps_wave;
    spec.h_over_ps = p.h_over_ps;
    spec.p0 = p.p0;
    spec.pulse = p.pulse;
    spec.smooth = p.smooth;
    spec.rows = p.rows;
    const scenes::WaveRecord rec = scenes::run_wave_2d(spec);
    const auto gx = spec.gauge_x();
    for (std::size_t k = 0; k < rec.t.size(); ++k)
      for (std::size_t g = 0; g < gx.size(); ++g)
        for (int r = 0; r < p.rows; ++r) wcsv.row(kind, rec.t[k], gx[g], r, rec.T[g][r][k]);
    const scenes::WaveMeasures w = scenes::measure_wave(spec, rec.t, rec.T);
    d.value("wave_speed_" + kind, w.speed, "pulse centroids at x = 0.05, 0.1 m, mid-thickness");
    d.value("plateau_over_p0_" + kind, w.plateau_over_p0, "mean T11 mid-pulse at x = 0.05 m, mid-thickness / p0");
    d.value("thickness_spread_over_p0_" + kind, w.spread_over_p0, "max over rows of |plateau - mid-row plateau| / p0");
  }
}

// Figs 5.10-5.12: large stretch of the 31 x 6 block along one path of (l1, l2).
void stretch_block(sph::Driver& d, const Params& p, const sph::Lame& m, double cL, sph::CsvWriter& bcsv,
                   const std::string& path) {
  const double ps_block = p.ps_block, stretch = p.stretch;
  const double Lb = (p.block_nx - 1) * ps_block, Hb = (p.rows - 1) * ps_block, T_load = p.transits * Lb / cL;
  auto l1 = [=](double t) { return 1.0 + (stretch - 1.0) * std::min(t / T_load, 1.0); };
  auto l2 = [=](double t) {
    if (path == "l2_1") return 1.0;
    if (path == "l2_2") return 2.0;
    return 1.0 + (l1(t) - 1.0) / (stretch - 1.0);
  };
  auto dom = scenes::rectangle_domain(Lb, Hb, 0, 1, 2, 2);
  std::vector<sph::BoundaryCondition2D> conds{
      condition(true, zero, false, zero),
      condition(true, [=](const Vec2&, double t) { return (l1(t) - 1.0) * Lb; }, false, zero),
      condition(false, zero, true, [=](const Vec2& X, double t) { return (l2(t) - 1.0) * (X.y() - Hb / 2); })};
  auto cfg = scenes::make_body(dom, conds, ps_block, p.h_over_ps);
  cfg.rho = p.rho;
  cfg.lame = m;
  sph::TlSolver2D body(std::move(cfg));
  body.set_initial_displacement([&](const Vec2& X) { return Vec2(0.0, (l2(0) - 1.0) * (X.y() - Hb / 2)); });
  const double dt = 0.3 * body.h() / cL;
  const int centre = body.nearest({Lb / 2, Hb / 2});
  const int n = static_cast<int>(std::ceil(T_load / dt)), every = std::max(1, n / 1500);
  sph::SnapshotSeries snaps(d.out_dir() / ("snapshots_block_" + path + ".h5"), d.info());
  double s2 = 0, lost = 0;
  int ns = 0;
  sph::Tensor2 Fend = sph::Tensor2::Identity();
  double Tend = 0, Taend = 1;
  double t = 0;  // the time before the step just taken
  auto observe = [&](const sph::TlSolver2D& b) {
    const long s = b.steps() - 1;  // index of the step just taken
    if (s >= 0) {
      const sph::Tensor2 F = b.F(centre);
      const double T11 = b.cauchy(centre)(0, 0);
      sph::Tensor2 Fa;
      Fa << l1(t), 0, 0, l2(t);
      const double Ta = sph::neo_hookean_cauchy<2>(m, Fa)(0, 0);
      if (t > 0.5 * T_load) { s2 += (T11 - Ta) * (T11 - Ta); ++ns; }
      if (s % every == 0) bcsv.row(path, t, l1(t), l2(t), F(0, 0), F(1, 1), T11, Ta);
      if (s % std::max(1, n / 12) == 0 || s == n - 1) snaps.write(sph::snapshot_of(b));
      Fend = F;
      Tend = T11;
      Taend = Ta;
    }
    t = b.time();
    return false;
  };
  if (sph::run(body, {dt, n}, observe).blew_up()) lost = l1(t);  // t: the start of the step that blew up
  d.value("stability_lost_at_l1_" + path, lost, "imposed l1 when the run became non-finite (0 = never)");
  d.value("rms_T11_dev_over_final_" + path, std::sqrt(s2 / std::max(ns, 1)) / std::abs(Taend), "centre, second half of the loading");
  d.value("final_T11_over_analytic_" + path, Tend / Taend, "centre particle at l1 = 6");
  d.value("final_F22_centre_" + path, Fend(1, 1), "centre particle's transverse stretch at the end");
  d.value("final_F11_centre_" + path, Fend(0, 0), "centre particle's stretch at the end");
}

}  // namespace

int main(int argc, char** argv) {
  sph::Driver d("ismail2009_fig5_7to5_12_neohookean_2d", "I-2d", "2D neo-Hookean: strain and stress waves, large stretch");
  Params p;
  declare(d, p);
  return d.run(argc, argv, [&] {
    const sph::Lame m = sph::lame_from_young_poisson(p.E, p.nu);
    const double cL = sph::longitudinal_wave_speed(m, p.rho);
    strain_and_stress_waves(d, p);
    const double rho = p.rho, E = p.E, nu = p.nu;
    d.value("plate_speed_plane_strain", std::sqrt(E / (rho * (1 - nu * nu))), "sqrt(E / (rho (1 - nu^2))): free sides, eps33 = 0");
    auto bcsv = d.csv("block.csv", {"case", "t", "l1_imposed", "l2_imposed", "F11", "F22", "T11", "T11_analytic"});
    for (const std::string path : {"l2_1", "l2_2", "l2_linear"}) stretch_block(d, p, m, cL, bcsv, path);
  });
}
