#include "ismail2009/scenes/hole_study.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "frame/driver.hpp"
#include "ismail2009/scenes/fem_hole.hpp"

namespace scenes {

namespace {

std::string edge_run_name(const std::string& series, int n) { return "edge_" + series + "_n" + std::to_string(n); }

// Richardson extrapolation of the smoothed (0, R) stress S(n) from the finest three runs whose spacings halve
// ((n - 1) doubling: 41, 81, 161 of the default study): the observed order p, the converged value S_inf, and
// what the same error law C h^p predicts at 21 x 21, the thesis's resolution (not used to fit: the 21 run is
// checked against it). Written only when the study has such a triplet with a monotone, contracting sequence.
void write_richardson(sph::Driver& d, const std::vector<int>& ns, const std::vector<double>& top) {
  for (std::size_t l = ns.size(); l-- > 2;)
    for (std::size_t j = 0; j < l; ++j)
      for (std::size_t i = 0; i < j; ++i) {
        if (ns[j] - 1 != 2 * (ns[i] - 1) || ns[l] - 1 != 2 * (ns[j] - 1)) continue;
        const double d1 = top[j] - top[i], d2 = top[l] - top[j];
        if (!(d1 * d2 > 0) || !(std::abs(d2) < std::abs(d1))) return;  // not in the asymptotic range
        const double ratio = d1 / d2, p = std::log2(ratio), s_inf = top[l] + d2 / (ratio - 1);
        const double h21 = (ns[i] - 1) / 20.0;  // the 21 x 21 spacing over the triplet's coarsest
        const double s21 = s_inf - (s_inf - top[i]) * std::pow(h21, p);
        d.value("sigma1_hole_top_MPa_richardson", s_inf, "Richardson extrapolation of the smoothed (0, R) stress, n = " +
                std::to_string(ns[i]) + ", " + std::to_string(ns[j]) + ", " + std::to_string(ns[l]));
        d.value("richardson_order", p, "observed convergence order of the smoothed (0, R) stress");
        d.value("richardson_error_finest", std::abs(s_inf - top.back()) / s_inf, "|S_inf - S(finest)| / S_inf");
        d.value("richardson_predicted_sigma1_21_MPa", s21, "S_inf - C h^p at 21 x 21, from the triplet's fit");
        d.value("richardson_error_21", (s_inf - s21) / s_inf, "discretisation error of a 21 x 21 result, (S_inf - S21) / S_inf");
        return;
      }
}

}  // namespace

std::vector<std::string> HoleStudyPlan::names() const {
  std::vector<std::string> names;
  for (const auto& [name, _] : runs) names.push_back(name);
  return names;
}

const std::pair<std::string, HoleParams>& HoleStudyPlan::run(const std::string& name) const {
  const std::string& id = same_as.count(name) ? same_as.at(name) : name;
  const auto it = std::find_if(runs.begin(), runs.end(), [&](const auto& r) { return r.first == id; });
  if (it == runs.end()) throw std::logic_error("hole study: no run " + name + " in the plan");
  return *it;
}

HoleStudyPlan plan_hole_study(const HoleStudySpec& s) {
  const HoleParams& p = s.p;
  const auto linear_edge = scenes::linear_edge_run;  // issue 15 (b): Hooke at 1%, undamped, no control, 12/omega
  const HoleParams e = p;  // the edge series' base: the study's sheet, then linear_edge
  HoleStudyPlan plan;
  auto plan_run = [&](const std::string& name, const HoleParams& q) {
    for (const auto& [other, _] : plan.runs)
      if (other == name) return;  // the same run twice (e.g. edge-variants-n among edge-n)
    plan.runs.emplace_back(name, q);
  };
  for (int n : s.ns) { auto q = p; q.n = n; plan_run("controlled_n" + std::to_string(n), q); }
  for (int n : s.plain_ns) { auto q = p; q.n = n; q.hourglass = 0; plan_run("plain_n" + std::to_string(n), q); }
  auto among = [](const std::vector<int>& v, int n) { return std::find(v.begin(), v.end(), n) != v.end(); };
  for (double g : s.gammas) {
    const std::string name = "gamma_g" + sph::format_number(g);
    if (g == p.hourglass && among(s.ns, s.gamma_n)) plan.same_as[name] = "controlled_n" + std::to_string(s.gamma_n);
    else if (g == 0 && among(s.plain_ns, s.gamma_n)) plan.same_as[name] = "plain_n" + std::to_string(s.gamma_n);
    else { auto q = p; q.n = s.gamma_n; q.hourglass = g; plan_run(name, q); }
  }
  if (s.linear_n > 0) {
    auto q = p;
    q.n = s.linear_n;
    q.hooke = true;
    q.traction = 0.01 * p.traction;  // small strain: the linear-elastic concentration
    plan_run("linear_n" + std::to_string(s.linear_n), q);
  }
  if (!s.edges()) return plan;
  const int edge_n = s.edge_n;
  auto edge_variant = [&](auto&& set) { HoleParams q = linear_edge(e); q.n = edge_n; set(q); return q; };
  for (int n : s.edge_ns) { auto q = linear_edge(e); q.n = n; plan_run(edge_run_name("resolution", n), q); }
  { auto q = linear_edge(e); q.n = edge_n; plan_run(edge_run_name("resolution", edge_n), q); }
  plan_run(edge_run_name("dt0.1", edge_n), edge_variant([](auto& q) { q.dt_factor = 0.1; }));
  plan_run(edge_run_name("passes3", edge_n), edge_variant([](auto& q) { q.closure_passes = 3; }));
  plan_run(edge_run_name("nu0.3", edge_n), edge_variant([](auto& q) { q.nu = 0.3; }));
  plan_run(edge_run_name("variational", edge_n), edge_variant([](auto& q) { q.variational = true; }));
  if (s.eigen_n > 0) {
    auto q = linear_edge(e);
    q.n = s.eigen_n;
    q.closure_passes = 30;
    plan_run(edge_run_name("passes30", s.eigen_n), q);
  }
  return plan;
}

// wall_s, build_s: of the run where it was stepped (its run job, or this process).
HoleStudyOutput::HoleStudyOutput(sph::Driver& d, const HoleStudySpec& s, const HoleStudyPlan& plan,
                                 const std::map<std::string, HoleResult>& result)
    : d_(d), s_(s), plan_(plan), result_(result),
      out_(d.csv("resolution.csv", {"series", "n", "hourglass", "law", "traction_MPa", "particles", "steps", "wall_s", "build_s",
                                    "sigma1_hole_top_MPa", "peak_sigma1_MPa", "peak_sigma1_dynamic_MPa",
                                    "smoothed_sigma1_hole_top_MPa", "zigzag", "settle_change", "speed_rise", "rest_speed_ratio", "growth_rate", "fastest_X", "fastest_Y"})),
      hist_(d.csv("history.csv", {"series", "n", "hourglass", "t", "smoothed_sigma1_hole_top_MPa", "peak_sigma1_MPa", "max_speed"})) {}

HoleResult HoleStudyOutput::resolution_row(const std::string& series, const std::string& name) {
  const auto& [id, q] = plan_.run(name);
  const HoleResult& r = result_.at(id);
  if (!r.finite)
    throw std::runtime_error("the sheet run became non-finite (" + series + ", n = " + std::to_string(q.n) + ", gamma = " +
                             sph::format_number(q.hourglass) + ")");
  out_.row(series, q.n, q.hourglass, q.hooke ? "hooke" : "neo_hookean", q.traction / 1e6, r.particles, r.steps, r.wall_s, r.build_s,
           r.sigma1_hole_top / 1e6, r.peak_sigma1 / 1e6, r.peak_sigma1_dynamic / 1e6, r.smoothed_sigma1_hole_top / 1e6, r.zigzag,
           r.settle_change, r.speed_rise, r.rest_speed_ratio, r.growth_rate, r.fastest_X.x(), r.fastest_X.y());
  for (std::size_t k = 0; k < r.history.size(); k += 5) {
    const auto& h = r.history[k];
    hist_.row(series, q.n, q.hourglass, h.t, h.smoothed_top / 1e6, h.peak / 1e6, h.vmax);
  }
  return r;
}

std::vector<double> HoleStudyOutput::fem_reference(const std::vector<int>& fem_m) {
  const HoleParams& p = s_.p;
  auto fcsv = d_.csv("fem.csv", {"m", "elements", "dofs", "concentration"});
  std::vector<double> kf;
  for (int m : fem_m) {
    const auto fr = scenes::fem_hole_concentration(p.a, p.R, 2 * m, m);
    fcsv.row(m, fr.elements, fr.dofs, fr.concentration);
    kf.push_back(fr.concentration);
  }
  if (!kf.empty()) {
    d_.value("fem_concentration", kf.back(), "Q4 plane stress, finest mesh: sigma_xx(0, R) / traction of this square sheet");
    if (kf.size() > 1)
      d_.value("fem_change_last_refinement", std::abs(kf.back() - kf[kf.size() - 2]) / kf.back(), "relative change, last mesh halving");
    d_.value("fem_linear_sigma1_MPa", kf.back() * p.traction / 1e6, "the linear-elastic reference stress at (0, R) for the sheet's load");
  }
  return kf;
}

void HoleStudyOutput::series(const std::vector<double>& kf) {
  double top_at_linear_n = 0;
  const std::vector<double> top = controlled(kf, top_at_linear_n);
  plain(top);
  for (double g : s_.gammas) resolution_row("gamma", "gamma_g" + sph::format_number(g));
  linear(kf, top_at_linear_n);
}

std::vector<double> HoleStudyOutput::controlled(const std::vector<double>& kf, double& top_at_linear_n) {
  const std::vector<int>& ns = s_.ns;
  std::vector<double> top;
  for (int n : ns) {
    const auto r = resolution_row("controlled", "controlled_n" + std::to_string(n));
    top.push_back(r.smoothed_sigma1_hole_top / 1e6);
    if (n == s_.linear_n) top_at_linear_n = r.smoothed_sigma1_hole_top;
    if (n == ns.back()) {
      d_.value("raw_sigma1_hole_top_MPa_finest", r.sigma1_hole_top / 1e6, "particle stress at (0, R), finest run");
      d_.value("zigzag_finest", r.zigzag, "particle-scale disorder, finest run");
      d_.value("settle_change_finest", r.settle_change, "finest run: change of the smoothed (0, R) stress over the last 1/omega");
      d_.value("speed_rise_finest", r.speed_rise, "finest run: largest particle speed at the end over its minimum after the ramp");
      d_.value("rest_speed_ratio_finest", r.rest_speed_ratio, "finest run: largest particle speed at the end over its peak during the run");
    }
  }
  d_.value("sigma1_hole_top_MPa_finest", top.back(), "finest run, SPH-smoothed stress at (0, R)");
  if (!kf.empty()) d_.value("sigma1_over_fem_linear", top.back() / (kf.back() * s_.p.traction / 1e6), "neo-Hookean SPH over linear FEM");
  if (top.size() > 1)
    d_.value("sigma1_hole_top_change_last_refinement", std::abs(top.back() - top[top.size() - 2]) / top.back(),
             "relative change over the last refinement");
  write_richardson(d_, ns, top);
  return top;
}

void HoleStudyOutput::plain(const std::vector<double>& top) {
  double plain_last = 0;
  for (int n : s_.plain_ns) {
    const auto r = resolution_row("plain", "plain_n" + std::to_string(n));
    plain_last = r.smoothed_sigma1_hole_top / 1e6;
    if (n == s_.plain_ns.back()) {
      d_.value("plain_sigma1_hole_top_MPa_finest", plain_last, "without the control, its finest run");
      d_.value("plain_settle_change_finest", r.settle_change, "without the control: change over the last 1/omega");
      d_.value("plain_rest_speed_ratio_finest", r.rest_speed_ratio, "without the control: final over peak largest particle speed");
      for (std::size_t k = 0; k < s_.ns.size(); ++k)
        if (s_.ns[k] == n) d_.value("control_bias_at_plain_finest", (top[k] - plain_last) / plain_last, "(controlled - plain) / plain, same n");
    }
  }
}

void HoleStudyOutput::linear(const std::vector<double>& kf, double top_at_linear_n) {
  const HoleParams& p = s_.p;
  const double heywood = scenes::heywood_gross_concentration(p.R / p.a);
  if (s_.linear_n > 0) {
    const auto r = resolution_row("linear", "linear_n" + std::to_string(s_.linear_n));
    const double k_lin = r.smoothed_sigma1_hole_top / (0.01 * p.traction);
    d_.value("linear_concentration", k_lin, "Hooke at 1% of the load: smoothed (0, R) stress / traction");
    d_.value("linear_over_heywood", k_lin / heywood, "the square sheet's linear concentration over the long strip's");
    if (!kf.empty()) d_.value("linear_over_fem", k_lin / kf.back(), "linear SPH over linear finite elements, same geometry");
    if (top_at_linear_n > 0)
      d_.value("nonlinear_over_linear", top_at_linear_n / p.traction / k_lin, "neo-Hookean at 5 MPa over linear, same n");
  }
  d_.value("heywood_MPa_resolution", heywood * p.traction / 1e6, "reference");
}

// `series` names the run in edge_stability.csv; the run is the plan's edge_<run>_n<n>.
double HoleStudyOutput::edge_row(const std::string& series, int n, const std::string& run) {
  const std::string name = edge_run_name(run.empty() ? series : run, n);
  const HoleParams& q = plan_.run(name).second;
  const HoleResult& r = result_.at(name);
  edge_csv_->row(series, q.n, q.dt_factor, q.closure_passes, q.nu, q.variational ? "variational" : "ghost_reflection",
                 r.finite ? 1 : 0, r.steps, r.wall_s, r.growth_rate, r.fastest_X.x(), r.fastest_X.y());
  return r.growth_rate;
}

// Issue 15 (b): the edge instability of the ghost-reflection closure, by its growth rate (HoleResult::
// growth_rate, in omega) in the linear regime (Hooke, 1% of the load), without damping and without the
// control, run to 12/omega: against resolution, the time step (a one-step lag would fade as dt -> 0),
// the ghosts and gradient iterated within each step (towards the un-lagged closure), nu and the closure.
void HoleStudyOutput::edges() {
  if (!s_.edges()) return;
  const int edge_n = s_.edge_n;
  edge_csv_.emplace(d_.csv("edge_stability.csv", {"series", "n", "dt_factor", "closure_passes", "nu", "closure", "finite", "steps",
                                                  "wall_s", "growth_rate", "fastest_X", "fastest_Y"}));
  double rate_default = NAN, rate_finest = NAN;
  for (int n : s_.edge_ns) {
    const double g = edge_row("resolution", n);
    d_.value("edge_rate_n" + std::to_string(n), g, "growth rate / omega, undamped, dt = 0.3 h / c_L, nu = 0.49");
    if (n == edge_n) rate_default = g;
    rate_finest = g;
  }
  d_.value("edge_least_damping_finest", 2 * rate_finest,
           "mass-proportional damping (in omega) that holds the finest edge run's mode: twice its growth rate");
  d_.value("damping_over_least_finest", s_.p.damping / (2 * rate_finest),
           "the study's damping over the least that holds the finest edge run's mode (>= 1: the mode decays)");
  if (std::isnan(rate_default)) rate_default = edge_row("resolution", edge_n);
  auto variant = [&](const std::string& name, const std::string& note) {
    const double g = edge_row(name, edge_n);
    d_.value("edge_rate_" + name, g, note);
    return g;
  };
  const double g_dt = variant("dt0.1", "growth rate / omega at a third of the step");
  const double g_it = variant("passes3", "growth rate / omega, ghosts and gradient 3 times per step");
  variant("nu0.3", "growth rate / omega at nu = 0.3");
  variant("variational", "growth rate / omega, variational closure");
  d_.value("edge_rate_change_third_step", g_dt - rate_default, "rate at dt / 3 minus at dt (a lag's would be < 0)");
  d_.value("edge_rate_change_passes3", g_it - rate_default, "rate with the closure iterated minus lagged (a lag's would be < 0)");
  spectrum();
}

// The mechanism by the spectrum (scenes::edge_spectrum): the un-lagged closure's linearised operator J of
// u'' = J u, and the same step run with the closure iterated to its fixed point (30 passes), whose measured
// rate the largest Re sqrt(lambda) must predict if the growth is J's eigenmode (not the time integration).
void HoleStudyOutput::spectrum() {
  const int eigen_n = s_.eigen_n;
  if (eigen_n <= 0) return;
  HoleParams q = s_.p;
  q.n = eigen_n;
  q.closure_passes = 30;
  auto spectrum_of = [&](const std::string& name, const std::string& note, auto&& set) {
    HoleParams r = q;
    set(r);
    const auto sp = scenes::edge_spectrum(r);
    d_.value("edge_eigen_rate" + name, sp.rate, "largest Re sqrt(lambda) / omega of the linearised operator, n = " +
             std::to_string(eigen_n) + note);
    return sp;
  };
  const auto sp = spectrum_of("", ", nu = 0.49", [](auto&) {});
  spectrum_of("_nu0.3", ", nu = 0.3", [](auto& r) { r.nu = 0.3; });
  spectrum_of("_variational", ", variational closure", [](auto& r) { r.variational = true; });
  const double ps = q.a / (q.n - 1);
  d_.value("edge_eigen_growing_share", static_cast<double>(sp.growing) / sp.dof, "share of the eigenvalues with a growing root, nu = 0.49");
  d_.value("edge_eigen_lambda_re", sp.lambda_re, "the fastest mode's lambda / omega^2, real part");
  d_.value("edge_eigen_lambda_im", sp.lambda_im, "its |imaginary part| / omega^2");
  d_.value("edge_eigen_corner_distance_ps", (sp.where - sph::Vec2(q.a, q.a)).norm() / ps,
           "distance of the fastest mode's largest amplitude from the corner of the loaded and the free edge, in spacings");
  const double g30 = edge_row("passes30_n" + std::to_string(eigen_n), eigen_n, "passes30");
  d_.value("edge_rate_passes30", g30, "measured growth rate / omega, closure iterated 30 times per step, n = " + std::to_string(eigen_n));
  d_.value("edge_eigen_over_measured", sp.rate / g30, "predicted (spectrum) over measured (dynamic run) growth rate");
}

}  // namespace scenes
