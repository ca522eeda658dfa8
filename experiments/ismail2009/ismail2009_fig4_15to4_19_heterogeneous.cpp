// Ismail 2009 (thesis), Figs 4.15-4.19: the validation bar of Section 4.6.3 with a density change at
// mid-span (Section 4.6.3.6). Reflected and transmitted stress amplitudes against the coefficients
// C_r = (Z - 1)/(Z + 1), C_t = 2Z/(Z + 1), Z = rho_B c_B / (rho_A c_A) (eqs 4.45-4.46).
//   Fig 4.16 decrease, Fig 4.17 increase, Fig 4.18 very large increase, Fig 4.19 very large decrease.
// Parameters as I-bar (ismail2009_fig4_6to4_14_bar.cpp: rho_A = 8000, E = 200 GPa, nu = 0.3, p-wave modulus,
// ps = 0.15 mm, h = 5.5 ps, intermediate pulse 5 us smoothed over 0.5 us).
// CHOSEN (the text gives no factors): rho_B / rho_A = 0.5, 2, 1e4 ("a very large number": Z = 100, the bar
// behaves as if truncated) and 0.01 ("very small": c_B = 10 c_A). The particle at the interface gets the
// mean density. dt = 0.5 h / max(c_A, c_B); Fig 4.19 is also run with the step of material A, which the
// thesis says is too large ("the required time step becomes prohibitively small").
// Measurements: mean T11 over the middle 20% of the pulse at the times eqs (4.43)-(4.44) predict: the
// reflection at x = 0.05 m (gauge 2), the transmission at x = 0.1 m (gauge 3).
#include <cmath>
#include <string>
#include <vector>

#include "frame/driver.hpp"
#include "core/materials.hpp"
#include "ismail2009/scenes/bar.hpp"

int main(int argc, char** argv) {
  sph::Driver d("ismail2009_fig4_15to4_19_heterogeneous", "I-het", "1D bar with a density change at mid-span");
  double rho = 8000, E = 200e9, nu = 0.3, L = 0.15, p0 = 1e5, ps = 0.15e-3, h_over_ps = 5.5, pulse = 5e-6,
         smooth = 0.5e-6, t_end = 60e-6;
  std::vector<double> factors{0.5, 2.0, 1e4, 0.01};
  d.param("rho", rho, "density of the left half, kg/m^3").positive();
  d.param("E", E, "Young's modulus, Pa");
  d.param("nu", nu, "Poisson's ratio").above(-1).below(0.5);
  d.param("ps", ps, "particle spacing, m (CHOSEN as I-bar)").positive().quick(0.3e-3);
  d.param("h-over-ps", h_over_ps, "cover radius in spacings").positive();
  d.param("pulse", pulse, "pulse duration, s (CHOSEN)").positive();
  d.param("smoothing", smooth, "pulse smoothing, s (CHOSEN: intermediate)").non_negative();
  d.param("factors", factors, "rho_B / rho_A for Figs 4.16-4.19 (CHOSEN)").positive();
  return d.run(argc, argv, [&] {
    if (factors.size() != 4) throw std::invalid_argument("--factors needs four values (Figs 4.16-4.19)");
    const double C = sph::p_wave_modulus(sph::lame_from_young_poisson(E, nu)), cA = std::sqrt(C / rho), h = h_over_ps * ps;
    const scenes::SmoothedPulse p(p0, pulse, smooth);
    const std::vector<double> gauges{0.0, L / 3, 2 * L / 3, L, L / 2};  // the four of Fig 4.15 + the interface
    const std::vector<std::string> names{"decrease", "increase", "very_large_increase", "very_large_decrease"};
    auto g = d.csv("gauges.csv", {"case", "t", "gauge", "x", "T11", "u"});
    for (std::size_t k = 0; k < factors.size(); ++k) {
      const double f = factors[k], rhoB = f * rho, cB = std::sqrt(C / rhoB), Z = rhoB * cB / (rho * cA);
      sph::TlConfig1D cfg;
      cfg.length = L;
      cfg.ps = ps;
      cfg.h_over_ps = h_over_ps;
      cfg.modulus = C;
      cfg.density = [=](double x) {
        return std::abs(x - L / 2) < 1e-3 * ps ? 0.5 * (rho + rhoB) : (x < L / 2 ? rho : rhoB);
      };
      cfg.left.value = [p](double t) { return -p(t); };
      cfg.right.kind = sph::EndCondition1D::Kind::Displacement;
      for (bool thesis_step : {false, true}) {
        if (thesis_step && cB <= cA) continue;
        sph::TlSolver1D bar(cfg);
        const double dt = 0.5 * h / (thesis_step ? cA : std::max(cA, cB));
        const double tend = thesis_step ? 20e-6 : t_end;
        const auto r = scenes::run_bar(bar, dt, tend, gauges, thesis_step ? 1 : std::max(1, static_cast<int>(std::lround(0.5 * h / cA / dt))),
                                       thesis_step ? 1e3 * p0 : 0.0);
        const std::string name = names[k] + (thesis_step ? "_dt_of_A" : "");
        for (std::size_t gi = 0; gi < gauges.size(); ++gi)
          for (std::size_t i = 0; i < r.t.size(); ++i) g.row(name, r.t[i], static_cast<int>(gi + 1), gauges[gi], r.T[gi][i], r.u[gi][i]);
        if (thesis_step) {
          d.value("max_abs_T_over_p0_" + name, std::isfinite(r.max_abs_T) ? r.max_abs_T / p0 : 1e300,
                  "with dt = 0.5 h / c_A (stops at 1000 p0)");
          continue;
        }
        // Plateau windows at the times (4.43)-(4.44) predict: the middle 20% of the pulse. When the echo from
        // the fixed end (transmitted side) or the multiple reflections inside B return within the pulse
        // (c_B >> c_A: B is shorter than the pulse), average from the end of the rise (2 h_t after the onset)
        // until 0.1 us before that echo reaches the gauge instead.
        auto window = [&](const std::vector<double>& T, double onset, double clean) {
          if (clean < pulse + 2 * smooth) return scenes::window_mean(r.t, T, onset + 2 * smooth, onset + clean - 0.1e-6);
          const double m = onset + smooth + 0.5 * pulse;
          return scenes::window_mean(r.t, T, m - 0.1 * pulse, m + 0.1 * pulse);
        };
        const double t_ref = (L / 2 - gauges[1] + L / 2) / cA;           // onset: to the interface and back
        const double t_tra = (L / 2) / cA + (gauges[2] - L / 2) / cB;    // onset: across the interface
        const double Tr = window(r.T[1], t_ref, 2 * (L / 2) / cB), Tt = window(r.T[2], t_tra, 2 * (L - gauges[2]) / cB);
        // Displacement continuity at the interface: u_interface / u_incident = 1 - C_r = 2 / (Z + 1), each
        // taken once the pulse has passed (the incident step at gauge 2 before its reflection returns).
        const double after = smooth * 2 + pulse + 0.5e-6;
        const double u_inc = scenes::window_mean(r.t, r.u[1], gauges[1] / cA + after, gauges[1] / cA + after + 0.5e-6);
        const double u_int = scenes::window_mean(r.t, r.u[4], L / 2 / cA + after, L / 2 / cA + after + 0.5e-6);
        if (2 * (L / 2) / cB > after + 0.5e-6) {  // only while no echo from inside B has returned
          d.value("u_interface_over_u_incident_" + names[k], u_int / u_inc, "displacement step at x = L/2 over that at x = 0.05 m");
          d.value("u_interface_theory_" + names[k], 2 / (Z + 1), "1 - C_r = 2/(Z+1)");
        }
        d.value("C_r_" + names[k], Tr / -p0, "reflected mean T11 at x = 0.05 m over the incident -p0");
        d.value("C_r_theory_" + names[k], (Z - 1) / (Z + 1), "eq (4.45)");
        if (t_tra < t_end) {
          d.value("C_t_" + names[k], Tt / -p0, "transmitted mean T11 at x = 0.1 m over the incident -p0");
          d.value("C_t_theory_" + names[k], 2 * Z / (Z + 1), "eq (4.46)");
        }
      }
    }
  });
}
