// Ismail 2009 thesis, Figs 5.1-5.2 (Section 5.1.1): Cauchy stress T11 of the compressible neo-Hookean
// material against the stretch l1 for a family of fixed l2, plane strain (l3 = 1), nu = 0.3 (Fig 5.1)
// and nu = 0.49 (Fig 5.2). A consistency check of the material code (src/core/materials.hpp) and the analytic
// curves the SPH runs of Sections 5.3-5.4 (targets I-nh1d, I-2d) are compared with.
//
// T11 is computed two independent ways: the closed form (5.5) coded below, and the library's P(F) (3.64)
// pushed to Cauchy stress with (3.33); also through the 2D plane-strain library functions.
//
// Parameters (the thesis states no E, stretch range or l2 values for Figs 5.1-5.2):
//   nu = 0.3, 0.49               Fig 5.1 and 5.2 captions; Section 5.3.2 (Figs 5.5, 5.6)
//   E = 200 GPa, rho = 8000      CHOSEN: the material of Section 5.3.1, used by the Section 5.3-5.4
//                                validations of these curves; nu is varied at fixed E as in Section 5.3.2.
//                                Every check below is a ratio independent of E except c_L.
//   l1 in [0.5, 6]               CHOSEN: l1 = 6 is the largest stretch validated (15 mm bar to 90 mm,
//                                Section 5.3.2; 2D block to l1 = 6, Section 5.4.3); down to 0.5 to show
//                                compression and the zero crossings of the pre-stretched curves.
//   l2 in {0.5, 1, 1.5, 2}       CHOSEN: l2 = 1 and 2 are the curves of Section 5.4.3 (Figs 5.10-5.12);
//                                0.5 and 1.5 fill the family, 0.5 gives a pre-compressed curve.
//   path l2 = 1 + (l1 - 1)/5     Section 5.4.3 (Fig 5.12): l2 raised linearly to 2 while l1 goes to 6.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "frame/driver.hpp"
#include "core/materials.hpp"

namespace {

using sph::Lame;

/// Principal Cauchy stresses of F = diag(l1, l2, l3), Ismail 2009 eq (5.5):
/// T_ii = mu (l_i^2 - 1) / J + lambda ln J / J, J = l1 l2 l3.
Eigen::Vector3d cauchy_closed_form(const Lame& m, double l1, double l2, double l3) {
  const double J = l1 * l2 * l3;
  return (m.mu * Eigen::Vector3d(l1 * l1 - 1, l2 * l2 - 1, l3 * l3 - 1) +
          Eigen::Vector3d::Constant(m.lambda * std::log(J))) / J;
}

/// Principal first Piola-Kirchhoff stresses, Ismail 2009 eq (5.4): P_ii = mu (l_i - 1/l_i) + lambda ln J / l_i.
Eigen::Vector3d piola_closed_form(const Lame& m, double l1, double l2, double l3) {
  const Eigen::Vector3d l(l1, l2, l3);
  const double lnJ = std::log(l1 * l2 * l3);
  return m.mu * (l - l.cwiseInverse()) + m.lambda * lnJ * l.cwiseInverse();
}

/// dT11/dl1 of (5.5) in plane strain: [mu (1 + 1/l1^2) + lambda (1 - ln J) / l1^2] / l2, J = l1 l2.
double dT11_dl1_closed_form(const Lame& m, double l1, double l2) {
  return (m.mu * (1 + 1 / (l1 * l1)) + m.lambda * (1 - std::log(l1 * l2)) / (l1 * l1)) / l2;
}

/// The library route: F = diag(l1, l2, 1), P from (3.64), T = J^-1 P F^T (3.33).
sph::Tensor3 library_F(double l1, double l2) { return Eigen::Vector3d(l1, l2, 1.0).asDiagonal(); }
sph::Tensor3 library_cauchy(const Lame& m, double l1, double l2) {
  const sph::Tensor3 F = library_F(l1, l2);
  return sph::cauchy_from_P<3>(sph::neo_hookean_P<3>(m, F), F);
}
double library_T11(const Lame& m, double l1, double l2) { return library_cauchy(m, l1, l2)(0, 0); }

/// Root of f in [a, b] (f(a) f(b) <= 0) by bisection to machine precision.
double bisect(const std::function<double(double)>& f, double a, double b) {
  double fa = f(a);
  if (fa * f(b) > 0) throw std::runtime_error("bisect: root not bracketed");
  for (int i = 0; i < 200 && b - a > 4 * std::numeric_limits<double>::epsilon() * std::abs(b); ++i) {
    const double c = 0.5 * (a + b), fc = f(c);
    if ((fc <= 0) == (fa <= 0)) { a = c; fa = fc; } else { b = c; }
  }
  return 0.5 * (a + b);
}

/// Maximum of a unimodal f on [a, b] by golden-section search (works at a kink): {argmax, max}.
std::pair<double, double> golden_max(const std::function<double(double)>& f, double a, double b) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a), fc = f(c), fd = f(d);
  while (b - a > 1e-13) {
    if (fc > fd) { b = d; d = c; fd = fc; c = b - g * (b - a); fc = f(c); }
    else { a = c; c = d; fc = fd; d = a + g * (b - a); fd = f(d); }
  }
  const double x = 0.5 * (a + b);
  return {x, f(x)};
}

std::string tag(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

struct Params {
  double E = 200.0;                          // GPa, CHOSEN (Section 5.3.1)
  double rho = 8000.0;                       // kg/m^3, Section 5.3.1 (only for c_L)
  std::vector<double> nus{0.3, 0.49};        // Figs 5.1, 5.2
  std::vector<double> l2s{0.5, 1.0, 1.5, 2.0};  // CHOSEN (1 and 2 from Section 5.4.3)
  double l1_min = 0.5, l1_max = 6.0;         // CHOSEN (6 from Sections 5.3.2, 5.4.3)
  int n = 5501;                              // grid points in l1 (spacing 1e-3); quick: 551
  double path_l2_end = 2.0;                  // Section 5.4.3: l2 reaches 2 when l1 reaches l1_max
  double fd_step = 1e-5;                     // central-difference step for the small-strain slope
};

void declare(sph::Driver& d, Params& p) {
  d.param("E", p.E, "Young's modulus [GPa]");
  d.param("rho", p.rho, "density [kg/m^3], for the wave speed only").positive();
  d.param("nu", p.nus, "Poisson's ratios, one panel each").above(-1).below(0.5);
  d.param("l2", p.l2s, "fixed transverse stretches, one curve each");
  d.param("l1-min", p.l1_min, "smallest stretch l1").positive();
  d.param("l1-max", p.l1_max, "largest stretch l1").positive();
  d.param("n", p.n, "grid points in l1").positive().quick(551);
  d.param("path-l2-end", p.path_l2_end, "l2 at l1 = l1-max on the linear path of Fig 5.12").positive();
  d.param("fd-step", p.fd_step, "central-difference step in l1 for dT11/dl1 at l1 = 1").positive();
}

// Largest differences between the closed forms and the library over the grid.
struct RouteDiffs {
  double T = 0, P = 0, plane_strain = 0, offdiag = 0;
};

// One curve T11(l1) at fixed l2 by both routes, closed forms (5.4)/(5.5) and the library (3.64)+(3.33), 3D and
// 2D plane strain: writes curves.csv, widens the differences, returns the library's T11 on the grid.
std::vector<double> curve_two_routes(const Lame& m, double nu, double l2, const std::vector<double>& l1s,
                                     sph::CsvWriter& curves, RouteDiffs& diff) {
  const int n = static_cast<int>(l1s.size());
  std::vector<double> T11(n);
  for (int i = 0; i < n; ++i) {
    const double l1 = l1s[i];
    const sph::Tensor3 F = library_F(l1, l2);
    const sph::Tensor3 P = sph::neo_hookean_P<3>(m, F), T = sph::cauchy_from_P<3>(P, F);
    const Eigen::Vector3d Tcf = cauchy_closed_form(m, l1, l2, 1.0), Pcf = piola_closed_form(m, l1, l2, 1.0);
    // Relative to the larger of the stress and mu, so the zero crossings do not divide by zero.
    diff.T = std::max(diff.T, (T.diagonal() - Tcf).cwiseAbs().maxCoeff() / std::max(Tcf.cwiseAbs().maxCoeff(), m.mu));
    diff.P = std::max(diff.P, (P.diagonal() - Pcf).cwiseAbs().maxCoeff() / std::max(Pcf.cwiseAbs().maxCoeff(), m.mu));
    diff.offdiag = std::max(diff.offdiag, (T - sph::Tensor3(T.diagonal().asDiagonal())).cwiseAbs().maxCoeff());
    const sph::Tensor2 F2 = Eigen::Vector2d(l1, l2).asDiagonal();
    const sph::Tensor2 T2 = sph::neo_hookean_cauchy<2>(m, F2);
    const Eigen::Vector3d T2d(T2(0, 0), T2(1, 1), sph::neo_hookean_plane_strain_T33(m, F2));
    diff.plane_strain = std::max(diff.plane_strain, (T2d - Tcf).cwiseAbs().maxCoeff() / std::max(Tcf.cwiseAbs().maxCoeff(), m.mu));
    T11[i] = T(0, 0);
    curves.row(nu, l2, l1, T(0, 0), Tcf(0), T(1, 1), T(2, 2), P(0, 0));
  }
  return T11;
}

// Features of one curve: pre-stress at l1 = 1, the zero of T11, the first maximum (if any).
void curve_features(sph::Driver& d, const Params& p, const Lame& m, double nu, double l2, const std::vector<double>& l1s,
                    const std::vector<double>& T11, sph::CsvWriter& features, const std::string& s) {
  const int n = p.n;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto f = [&](double l1) { return library_T11(m, l1, l2); };
  double l1_zero = nan, l1_peak = nan, T_peak = nan;
  for (int i = 1; i < n && std::isnan(l1_zero); ++i)
    if ((T11[i - 1] <= 0) != (T11[i] <= 0)) l1_zero = bisect(f, l1s[i - 1], l1s[i]);
  for (int i = 1; i + 1 < n && std::isnan(l1_peak); ++i)
    if (T11[i] >= T11[i - 1] && T11[i] > T11[i + 1])
      l1_peak = bisect([&](double x) { return dT11_dl1_closed_form(m, x, l2); }, l1s[i - 1], l1s[i + 1]);
  if (!std::isnan(l1_peak)) T_peak = f(l1_peak);
  features.row(nu, l2, f(1.0), l1_zero, l1_peak, T_peak);
  if (l2 != 1.0) {
    d.value("l1_zero_T11_l2_" + tag(l2) + s, l1_zero, "stretch where T11 = 0 on the l2 curve (bisection)");
    d.value("T11_over_mu_at_l1_1_l2_" + tag(l2) + s, f(1.0) / m.mu, "pre-stress lambda ln(l2)/l2/mu at l1 = 1");
  }
  if (l2 == 1.0) {
    d.value("l1_peak_T11_l2_1" + s, std::isnan(l1_peak) ? p.l1_max : l1_peak,
            "first maximum of T11(l1) for l2 = l3 = 1 (1D strain): dP11/dl1 = 0; l1-max if none");
    double min_slope = std::numeric_limits<double>::infinity();
    for (double l1 : l1s) if (l1 >= 1) min_slope = std::min(min_slope, dT11_dl1_closed_form(m, l1, 1.0));
    d.value("min_slope_T11_l2_1_over_M" + s, min_slope / sph::p_wave_modulus(m),
            "min over 1 <= l1 <= l1-max of dT11/dl1 (= dP11/dl1 in 1D strain) / (lambda + 2 mu)");
  }
}

// Reference state and small-strain limit (Hooke, 3.54 / 4.16), and the wave speeds.
void small_strain_limit(sph::Driver& d, const Params& p, const Lame& m, double nu, const std::string& s) {
  const double E = p.E, rho = p.rho;
  d.value("max_abs_T_at_identity" + s, library_cauchy(m, 1.0, 1.0).cwiseAbs().maxCoeff(), "stress-free F = I [GPa]");
  const double h = p.fd_step;
  const sph::Tensor3 Tp = library_cauchy(m, 1 + h, 1.0), Tm = library_cauchy(m, 1 - h, 1.0);
  const sph::Tensor3 dT = (Tp - Tm) / (2 * h);
  d.value("slope_T11_at_identity_over_lambda_plus_2mu" + s, dT(0, 0) / sph::p_wave_modulus(m),
          "central difference of library T11 at l1 = l2 = 1");
  d.value("slope_T22_at_identity_over_lambda" + s, dT(1, 1) / m.lambda, "Hooke: T22 = lambda eps11");
  const sph::Tensor3 eps = Eigen::Vector3d(h, 0, 0).asDiagonal();
  d.value("hooke_vs_neohookean_rel_dev_over_strain" + s,
          (library_cauchy(m, 1 + h, 1.0) - sph::hooke_stress<3>(m, eps)).norm() /
              (sph::hooke_stress<3>(m, eps).norm() * h),
          "|T_nh - T_hooke| / |T_hooke| / eps11 at eps11 = fd-step: O(1) means second order");
  const sph::Tensor3 dP = (sph::neo_hookean_P<3>(m, library_F(1 + h, 1.0)) - sph::neo_hookean_P<3>(m, library_F(1 - h, 1.0))) / (2 * h);
  // E in GPa -> Pa for the wave speed in m/s.
  d.value("c_L_from_tangent" + s, std::sqrt(dP(0, 0) * 1e9 / rho), "sqrt(dP11/dl1(1) / rho) [m/s], eq 4.38");
  d.value("c_L" + s, sph::longitudinal_wave_speed(sph::lame_from_young_poisson(E * 1e9, nu), rho), "eq 4.38 [m/s]");
  d.value("c_b" + s, sph::bar_wave_speed(E * 1e9, rho), "eq 4.39 [m/s]");
  d.value("c_T" + s, sph::transverse_wave_speed(sph::lame_from_young_poisson(E * 1e9, nu), rho), "[m/s]");
}

// Fig 5.12 path: l2 = 1 + (path_l2_end - 1)(l1 - 1)/(l1_max - 1). The exact quasi-static solution is
// the hyperelastic stress at the current F (path independent); the thesis says it "should be bounded
// by the analytical curves for l2 = 1 and l2 = 2". Measure the largest excess above the upper curve.
void path_between_bounds(sph::Driver& d, const Params& prm, const Lame& m, double nu, const std::vector<double>& l1s,
                         sph::CsvWriter& path, const std::string& s) {
  const int n = prm.n;
  const double l1_max = prm.l1_max, path_l2_end = prm.path_l2_end;
  const auto path_l2 = [&](double l1) { return 1 + (path_l2_end - 1) * (l1 - 1) / (l1_max - 1); };
  const auto excess = [&](double l1) {
    const double p = library_T11(m, l1, path_l2(l1));
    return p - std::max(library_T11(m, l1, 1.0), library_T11(m, l1, path_l2_end));
  };
  const auto below = [&](double l1) {
    return std::min(library_T11(m, l1, 1.0), library_T11(m, l1, path_l2_end)) - library_T11(m, l1, path_l2(l1));
  };
  int i_best = -1;
  double worst_below = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const double l1 = l1s[i];
    if (l1 < 1) continue;
    path.row(nu, l1, path_l2(l1), library_T11(m, l1, path_l2(l1)), library_T11(m, l1, 1.0),
             library_T11(m, l1, path_l2_end));
    if (i_best < 0 || excess(l1) > excess(l1s[i_best])) i_best = i;
    worst_below = std::max(worst_below, below(l1));
  }
  const double a = std::max(1.0, l1s[std::max(i_best - 1, 0)]), b = l1s[std::min(i_best + 1, n - 1)];
  const auto [l1_ex, ex] = golden_max(excess, a, b);
  d.value("path_excess_over_bounds_over_mu" + s, ex / m.mu,
          "max over 1 <= l1 <= l1-max of [T11(path) - max(T11(l2=1), T11(l2=end))] / mu");
  d.value("path_excess_l1" + s, l1_ex, "stretch of the largest excess");
  d.value("path_excess_over_upper_bound_rel" + s, ex / std::max(library_T11(m, l1_ex, 1.0), library_T11(m, l1_ex, path_l2_end)),
          "the excess relative to the upper curve there");
  d.value("path_below_lower_bound_over_mu" + s, worst_below / m.mu, "max of [lower curve - path] / mu (grid)");
  // The l2 = 1 and l2 = k curves cross where the l2 = 1/k curve vanishes: mu (l1^2 - 1) + lambda ln(l1/k) = 0.
  d.value("crossing_l1_of_l2_1_and_l2_end" + s,
          bisect([&](double x) { return library_T11(m, x, 1.0) - library_T11(m, x, path_l2_end); }, 1.0 + 1e-9, l1_max),
          "l1 where the l2 = 1 and l2 = path-l2-end curves cross");
}

}  // namespace

int main(int argc, char** argv) {
  sph::Driver d("ismail2009_fig5_1to5_2_neohookean_curves", "I-nh",
                "Ismail 2009 Figs 5.1-5.2: neo-Hookean plane-strain T11(l1) for fixed l2, two routes");
  Params p;
  declare(d, p);
  return d.run(argc, argv, [&] {
    const int n = p.n;
    if (!(p.l1_min > 0 && p.l1_min < 1 && p.l1_max > 1)) throw std::invalid_argument("need 0 < l1-min < 1 < l1-max");
    if (n < 11) throw std::invalid_argument("n must be >= 11");
    for (double l2 : p.l2s) if (!(l2 > 0)) throw std::invalid_argument("l2 must be > 0");
    if (std::find(p.l2s.begin(), p.l2s.end(), 1.0) == p.l2s.end()) throw std::invalid_argument("the l2 family must include 1");

    auto curves = d.csv("curves.csv", {"nu", "l2", "l1", "T11", "T11_closed_form", "T22", "T33", "P11"});
    auto path = d.csv("path.csv", {"nu", "l1", "l2", "T11", "T11_l2_1", "T11_l2_end"});
    auto features = d.csv("features.csv", {"nu", "l2", "T11_at_l1_1", "l1_zero", "l1_peak", "T11_peak"});
    std::vector<double> l1s(n);
    for (int i = 0; i < n; ++i) l1s[i] = p.l1_min + (p.l1_max - p.l1_min) * i / (n - 1);

    for (double nu : p.nus) {
      const Lame m = sph::lame_from_young_poisson(p.E, nu);
      const std::string s = "_nu" + tag(nu);
      RouteDiffs diff;
      for (double l2 : p.l2s) {
        const std::vector<double> T11 = curve_two_routes(m, nu, l2, l1s, curves, diff);
        curve_features(d, p, m, nu, l2, l1s, T11, features, s);
      }
      d.value("max_rel_diff_T_closed_form_vs_library" + s, diff.T, "eq 5.5 vs 3.64+3.33, all principal T, whole grid");
      d.value("max_rel_diff_P_closed_form_vs_library" + s, diff.P, "eq 5.4 vs 3.64, all principal P, whole grid");
      d.value("max_rel_diff_T_plane_strain_2d_vs_closed_form" + s, diff.plane_strain, "2x2 library + T33 vs eq 5.5");
      d.value("max_abs_offdiagonal_T" + s, diff.offdiag, "principal axes stay principal [GPa]");
      small_strain_limit(d, p, m, nu, s);
      path_between_bounds(d, p, m, nu, l1s, path, s);
    }
  });
}
