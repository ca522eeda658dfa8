// Ismail 2009 (thesis), Figs 5.4-5.6 (Section 5.3): 1D neo-Hookean total Lagrangian SPH (Algorithm 5.1).
//   Fig 5.4  a compressive pulse in the validation bar of Section 4.6.3 (rho = 8000, E = 200 GPa, nu = 0.3):
//            small strain, so it must travel at c_L = 5801 m/s (eq 4.38) with T11 = -p(t - x/c_L)
//   Fig 5.5  a 15 mm bar stretched to 90 mm over 30 small-strain transit times, nu = 0.3: T11 at the centre
//            particle against the static curve T11 = mu (l^2 - 1)/l + lambda ln l / l (eq 5.5, l2 = l3 = 1)
//   Fig 5.6  the same with nu = 0.49: where does it lose stability (thesis: past a stretch of 3.6)?
// The analysis (I-nh, src/core/materials.hpp): for nu = 0.49 P11(l) = T11(l) peaks at l = 3.6307; beyond it the
// tangent dP11/dl < 0, the wave speed is imaginary and the 1D problem is ill-posed: any discretisation then
// amplifies short waves. We test whether a smaller step or slower loading moves the loss of stability.
// CHOSEN: 151 particles on the 15 mm bar (ps = 0.1 mm), h = 5.5 ps; the left end fixed, the right end's
// displacement ramped linearly in time (constant end velocity from rest: the 'transient portion of the
// loading' the text blames for the oscillations) over 30 L/c_L of the bar's own nu; dt = 0.5 h/c_L (the
// tangent speed only falls with stretch for nu = 0.3); loss of stability = the first time the stretches F of
// two adjacent particles differ by more than 25% of the imposed stretch (a resolved wave changes F by
// < 0.1 l per spacing; a short-wave instability or localisation jumps), or F is not finite / not positive;
// peak crossing = the imposed stretch at which some particle's F first exceeds the peak of P11 (the loss's
// mechanism: the loss cannot come before it unless it has another cause);
// oscillation = RMS of (T11 - T11_static(l_imposed)) / T11_static(6) at the centre over the second half of
// the loading; slower loading = 2x and 4x the loading time. The pulse of Fig 5.4 as I-bar's intermediate.
#include <cmath>
#include <string>
#include <vector>

#include "core/run_loop.hpp"
#include "frame/driver.hpp"
#include "core/materials.hpp"
#include "ismail2009/scenes/bar.hpp"

namespace {

struct StretchResult {
  double lost_at = NAN;       // imposed stretch at the loss of stability (NaN: none)
  double peak_crossed_at = NAN;  // imposed stretch when some particle's F first passed the peak of P11 (NaN: never)
  double oscillation = NAN;   // RMS relative deviation from the static curve, second half
  double final_T_over_static = NAN;
};

/// The stretch at which the 1D-strain P11(l) (eq 5.4, l2 = l3 = 1) peaks, dP11/dl = 0, by bisection on
/// [1, 10]; 10 if it rises throughout (nu = 0.3).
double peak_stretch_P11(const sph::Lame& m) {
  auto slope = [&](double l) { return m.mu * (1 + 1 / (l * l)) + m.lambda * (1 - std::log(l)) / (l * l); };
  double a = 1.0, b = 10.0;
  for (int i = 0; i < 100; ++i) { const double c = 0.5 * (a + b); (slope(c) > 0 ? a : b) = c; }
  return a;
}

struct Params {
  double rho = 8000, E = 200e9, L = 0.015, stretch = 6.0, transits = 30, h_over_ps = 5.5, dt_factor = 0.5, tol = 0.25;
  int particles = 151;
};

void declare(sph::Driver& d, Params& p) {
  d.param("rho", p.rho, "density, kg/m^3 (Section 5.3.1)").positive();
  d.param("E", p.E, "Young's modulus, Pa (Section 5.3.1)");
  d.param("length", p.L, "bar length for the stretch test, m (Section 5.3.2: 15 mm)").positive();
  d.param("stretch", p.stretch, "final stretch (90 mm / 15 mm)").positive();
  d.param("transits", p.transits, "loading time in small-strain transit times L/c_L (Section 5.3.2: 30)").positive();
  d.param("particles", p.particles, "particles on the stretched bar (CHOSEN)").positive().quick(61);
  d.param("h-over-ps", p.h_over_ps, "cover radius in spacings").positive();
  d.param("dt-factor", p.dt_factor, "dt / (h/c_L) (CHOSEN)").positive();
  d.param("loss-tolerance", p.tol, "loss of stability: max |F_p+1 - F_p| / l above this (CHOSEN)").non_negative();
}

// A neo-Hookean bar of uniform density; the ends are set by the caller.
sph::TlConfig1D neo_hookean_bar(double length, double ps, double h_over_ps, const sph::Lame& m, double rho) {
  sph::TlConfig1D cfg;
  cfg.length = length;
  cfg.ps = ps;
  cfg.h_over_ps = h_over_ps;
  cfg.law = sph::TlConfig1D::Law::NeoHookean;
  cfg.lame = m;
  cfg.density = [rho](double) { return rho; };
  return cfg;
}

// Fig 5.4: the small-strain wave in the 0.15 m bar of Chapter 4, loaded at the left end, fixed at the right.
void small_strain_wave(sph::Driver& d, const Params& prm) {
  const double rho = prm.rho;
  const double nu = 0.3, Lb = 0.15, ps = d.quick() ? 0.6e-3 : 0.15e-3, p0 = 1e5, pulse = 5e-6;
  const sph::Lame m = sph::lame_from_young_poisson(prm.E, nu);
  const double c = sph::longitudinal_wave_speed(m, rho);
  const scenes::SmoothedPulse p(p0, pulse, 0.5e-6);
  sph::TlConfig1D cfg = neo_hookean_bar(Lb, ps, prm.h_over_ps, m, rho);
  cfg.left.value = [p](double t) { return -p(t); };
  cfg.right.kind = sph::EndCondition1D::Kind::Displacement;
  sph::TlSolver1D bar(cfg);
  const std::vector<double> gauges{0.0, Lb / 3, 2 * Lb / 3, Lb};
  const auto r = scenes::run_bar(bar, 0.5 * bar.h() / c, 40e-6, gauges);
  auto w = d.csv("wave.csv", {"t", "gauge", "x", "T11", "T11_exact"});
  for (std::size_t g = 0; g < gauges.size(); ++g)
    for (std::size_t i = 0; i < r.t.size(); ++i) {
      const double t = r.t[i], x = gauges[g];
      w.row(t, static_cast<int>(g + 1), x, r.T[g][i], -p(t - x / c) - (t > (2 * Lb - x) / c ? p(t - (2 * Lb - x) / c) : 0.0));
    }
  auto centroid = [&](int g) {
    const double t50 = scenes::crossing_time(r.t, r.T[g], -0.5 * p0);
    return scenes::centroid_time(r.t, r.T[g], t50 - 0.5 * pulse, t50 + 1.5 * pulse);
  };
  const double speed = (gauges[2] - gauges[1]) / (centroid(2) - centroid(1));
  d.value("wave_speed", speed, "pulse centroids, gauges 2-3, m/s");
  d.value("wave_speed_vs_paper_eq19", speed, "the same speed, compared with the appended paper's c_b (eqs 18-19)");
  const double mid = scenes::crossing_time(r.t, r.T[2], -0.5 * p0) + 0.5 * pulse;
  d.value("plateau_over_p0_gauge3", scenes::window_mean(r.t, r.T[2], mid - 0.1 * pulse, mid + 0.1 * pulse) / p0,
          "mean T11 mid-pulse at x = 0.1 m / p0");
}

// Figs 5.5-5.6: one stretch test, the right end pulled to `stretch` over slow x transits transit times, with
// dt scaled by dt_scale; writes the centre's history to curves (case `name`) if `write`.
StretchResult run_stretch(const Params& p, sph::CsvWriter& curves, double nu, double slow, double dt_scale,
                          const std::string& name, bool write) {
  const double L = p.L, stretch = p.stretch;
  const sph::Lame m = sph::lame_from_young_poisson(p.E, nu);
  const double c = sph::longitudinal_wave_speed(m, p.rho), T_load = slow * p.transits * L / c;
  const double ps = L / (p.particles - 1);
  sph::TlConfig1D cfg = neo_hookean_bar(L, ps, p.h_over_ps, m, p.rho);
  cfg.left.kind = cfg.right.kind = sph::EndCondition1D::Kind::Displacement;
  cfg.right.value = [=](double t) { return (stretch - 1.0) * L * std::min(t / T_load, 1.0); };
  sph::TlSolver1D bar(cfg);
  const double dt = dt_scale * p.dt_factor * bar.h() / c;
  const double l_peak = peak_stretch_P11(m);
  auto T_static = [&](double l) { return bar.law(l); };
  const int centre = bar.n_real() / 2, n = static_cast<int>(std::ceil(T_load / dt));
  const int every = std::max(1, n / 2000);
  StretchResult res;
  double s2 = 0;
  int ns = 0;
  double t = 0;  // the time before the step just taken
  auto imposed = [&](double tt) { return 1.0 + (stretch - 1.0) * std::min(tt / T_load, 1.0); };
  auto observe = [&](const sph::TlSolver1D& b) {
    const long s = b.steps() - 1;  // index of the step just taken
    if (s >= 0) {
      const double l = imposed(t);
      double dev = 0;
      bool bad = false;
      for (int i = 0; i < b.n_real() && !bad; ++i) {
        if (!(b.stretch(i) > 0)) bad = true;
        if (i > 0) dev = std::max(dev, std::abs(b.stretch(i) - b.stretch(i - 1)) / l);
        // The mechanism of the loss (header): a particle on the falling branch of P11. Recorded before the
        // loss test, which it does not enter, so that a loss of another cause would come before it.
        if (std::isnan(res.peak_crossed_at) && b.stretch(i) > l_peak) res.peak_crossed_at = l;
      }
      if (bad || dev > p.tol) { res.lost_at = l; return true; }
      const double Tc = b.stress(centre);
      if (t > 0.5 * T_load) { s2 += std::pow((Tc - T_static(l)) / T_static(stretch), 2); ++ns; }
      if (write && s % every == 0) curves.row(name, nu, t, l, b.stretch(centre), Tc, T_static(l));
      res.final_T_over_static = Tc / T_static(l);
    }
    t = b.time();
    return false;
  };
  if (sph::run(bar, {dt, n}, observe).blew_up()) res.lost_at = imposed(t);  // non-finite: lost at that step
  res.oscillation = ns ? std::sqrt(s2 / ns) : NAN;
  return res;
}

// Figs 5.5-5.6 for nu = 0.3 and 0.49: the loss of stability and the oscillation, with slower loading and dt / 2.
void stretch_tests(sph::Driver& d, const Params& p) {
  auto curves = d.csv("curves.csv", {"case", "nu", "t", "stretch_imposed", "F_centre", "T11_centre", "T11_static"});
  for (double nu : {0.3, 0.49}) {
    const std::string tag = nu < 0.4 ? "nu0.3" : "nu0.49";
    const auto base = run_stretch(p, curves, nu, 1.0, 1.0, tag, true);
    const auto slow2 = run_stretch(p, curves, nu, 2.0, 1.0, tag + "_slow2", true);
    const auto slow4 = run_stretch(p, curves, nu, 4.0, 1.0, tag + "_slow4", !d.quick());
    const auto half = run_stretch(p, curves, nu, 1.0, 0.5, tag + "_dt_half", false);
    auto lost = [](const StretchResult& r) { return std::isnan(r.lost_at) ? 0.0 : r.lost_at; };
    d.value("stability_lost_at_stretch_" + tag, lost(base), "imposed stretch at the loss of stability (0 = never)");
    d.value("stability_lost_at_stretch_" + tag + "_slow2", lost(slow2), "loading time x2");
    d.value("stability_lost_at_stretch_" + tag + "_slow4", lost(slow4), "loading time x4");
    d.value("stability_lost_at_stretch_" + tag + "_dt_half", lost(half), "dt / 2");
    d.value("peak_first_crossed_at_stretch_" + tag, std::isnan(base.peak_crossed_at) ? 0.0 : base.peak_crossed_at,
            "imposed stretch when a particle's F first passed the peak of P11 (0 = never): the loss's lower bound");
    if (nu < 0.4) {
      d.value("oscillation_" + tag, base.oscillation, "RMS (T11 - static)/T11_static(6), centre, 2nd half");
      d.value("oscillation_ratio_slow2_over_base_" + tag, slow2.oscillation / base.oscillation, "Section 5.3.2: slower loading, smaller oscillation");
      d.value("oscillation_ratio_slow4_over_base_" + tag, slow4.oscillation / base.oscillation, "loading time x4");
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  sph::Driver d("ismail2009_fig5_4to5_6_neohookean_1d", "I-nh1d", "1D neo-Hookean bar: wave and large stretch");
  Params p;
  declare(d, p);
  return d.run(argc, argv, [&] {
    small_strain_wave(d, p);
    stretch_tests(d, p);
    // The analysis: the stretch at which the 1D-strain P11(l) peaks for nu = 0.49 (dP11/dl = 0).
    d.value("peak_stretch_P11_nu0.49", peak_stretch_P11(sph::lame_from_young_poisson(p.E, 0.49)), "dP11/dl = 0 for l2 = l3 = 1 (eq 5.4)");
  });
}
