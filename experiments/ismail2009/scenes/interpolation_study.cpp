#include "ismail2009/scenes/interpolation_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/kernels.hpp"
#include "frame/driver.hpp"
#include "total_lagrangian/interpolation_1d.hpp"

namespace scenes::interpolation {

namespace {

const char* kQuantity[3] = {"f", "df", "d2f"};

/// 1 for x < x1, 0 for x > x2, linear in between; x1 = x2 is a step. Corners lie midway between particles.
Exact falling_edge(double x1, double x2) {
  return {[=](double x) { return x <= x1 ? 1.0 : x >= x2 ? 0.0 : (x2 - x) / (x2 - x1); },
          [=](double x) { return (x > x1 && x < x2) ? -1.0 / (x2 - x1) : 0.0; },
          [](double) { return 0.0; }};
}

template <class K>
Curve interpolate(const K& kernel, const Panel& P, double cover, bool discrete_norm) {
  const double radius = cover * P.ps, h = radius / kernel.support();
  const auto line = sph::uniform_line(P.a, P.b, P.ps, P.ghosts ? 2.0 * radius : 0.0);
  const double scale = discrete_norm ? 1.0 / sph::lattice_sum_of_weights(kernel, h, P.ps) : 1.0;
  std::vector<double> f(line.size());
  for (std::size_t i = 0; i < line.size(); ++i) f[i] = P.exact.f(line.x[i]);
  const auto sf = sph::sph_value(kernel, h, line, f, scale);
  const auto sdf = sph::sph_gradient(kernel, h, line, f, scale);
  const auto sd2f = sph::sph_gradient(kernel, h, line, sdf, scale);  // gradient of the SPH gradient
  const auto sw = sph::sum_of_weights(kernel, h, line, scale);

  Curve c;
  double sq[3] = {0, 0, 0};
  for (std::size_t i = line.first_real; i < line.first_real + line.n_real; ++i) {
    const double x = line.x[i];
    c.x.push_back(x);
    c.f.push_back(f[i]);
    c.df.push_back(P.exact.df(x));
    c.d2f.push_back(P.exact.d2f(x));
    c.sf.push_back(sf[i]);
    c.sdf.push_back(sdf[i]);
    c.sd2f.push_back(sd2f[i]);
    const double e[3] = {sf[i] - f[i], sdf[i] - c.df.back(), sd2f[i] - c.d2f.back()};
    for (int k = 0; k < 3; ++k) {
      c.err.max[k] = std::max(c.err.max[k], std::abs(e[k]));
      sq[k] += e[k] * e[k];
    }
  }
  for (int k = 0; k < 3; ++k) c.err.rms[k] = std::sqrt(sq[k] / static_cast<double>(line.n_real));
  const std::size_t end = line.first_real;
  c.end_weight_deficit = 1.0 - sw[end];
  c.end_relerr_f = std::abs(sf[end] - f[end]) / std::abs(f[end]);
  return c;
}

}  // namespace

std::string cover_label(double cover) { return "c" + sph::format_number(cover); }

Exact quartic() {
  return {[](double x) { return std::pow(x - 0.5, 4); }, [](double x) { return 4 * std::pow(x - 0.5, 3); },
          [](double x) { return 12 * std::pow(x - 0.5, 2); }};
}
Exact sine() {
  return {[](double x) { return std::sin(x); }, [](double x) { return std::cos(x); },
          [](double x) { return -std::sin(x); }};
}

Panel edge_panel(const std::string& id, const std::string& description, double ps, double width) {
  const double x1 = 0.5 + 0.5 * ps - std::floor(width / 2) * ps, x2 = x1 + width * ps;
  return {id, description, falling_edge(x1, x2), 0, 1, ps, true, width};
}

Study run_study(const std::string& kernel_name, const std::vector<Panel>& panels, const std::vector<double>& covers,
                double edge_ps, int sweep_max_width) {
  Study s;
  auto& res = s.results;
  auto& sweep = s.sweep;
  sph::with_kernel(kernel_name, 1, [&](const auto& kernel) {
    for (const std::string norm : {"integral", "discrete"}) {
      for (const auto& P : panels)
        for (double c : covers) res[norm][P.id][c] = interpolate(kernel, P, c, norm == "discrete");
      for (int w = 0; w <= sweep_max_width; ++w) {
        const Panel P = edge_panel("sweep", "", edge_ps, w);
        for (double c : covers) sweep[norm][w][c] = interpolate(kernel, P, c, norm == "discrete").err;
      }
    }
    return 0;
  });
  return s;
}

void write_panels(sph::Driver& d, const std::vector<Panel>& panels) {
  auto panel_csv = d.csv("panels.csv", {"panel", "description", "a", "b", "ps", "n_particles", "ghosts",
                                        "edge_width_ps"});
  for (const auto& P : panels)
    panel_csv.row(P.id, P.description, P.a, P.b, P.ps, std::lround((P.b - P.a) / P.ps) + 1, P.ghosts ? 1 : 0,
                  P.edge_width_ps);
}

void write_curves(sph::Driver& d, const std::vector<Panel>& panels, const std::vector<double>& covers,
                  const Study& study, const std::string& normalisation) {
  const auto& res = study.results;
  auto sweep_csv = d.csv("edge_width_sweep.csv", {"normalisation", "width_ps", "cover", "rms_f", "rms_df"});
  for (const auto& [norm, by_w] : study.sweep)
    for (const auto& [w, by_c] : by_w)
      for (const auto& [c, e] : by_c) sweep_csv.row(norm, w, c, e.rms[0], e.rms[1]);

  // Curves and errors (main reading) for the plots.
  const auto& main = res.at(normalisation);
  auto err_csv = d.csv("errors.csv", {"panel", "normalisation", "cover", "quantity", "max_abs", "rms"});
  for (const auto& P : panels) {
    // The exact function on a fine grid, for the plots (the curves file has it at the particles).
    auto ex = d.csv("exact_" + P.id + ".csv", {"x", "f", "df", "d2f"});
    for (int i = 0; i <= 2000; ++i) {
      const double x = P.a + (P.b - P.a) * i / 2000.0;
      ex.row(x, P.exact.f(x), P.exact.df(x), P.exact.d2f(x));
    }
    auto out = d.csv("curves_" + P.id + ".csv", {"cover", "x", "f", "df", "d2f", "sph_f", "sph_df", "sph_d2f"});
    for (double c : covers) {
      const Curve& cv = main.at(P.id).at(c);
      for (std::size_t i = 0; i < cv.x.size(); ++i)
        out.row(c, cv.x[i], cv.f[i], cv.df[i], cv.d2f[i], cv.sf[i], cv.sdf[i], cv.sd2f[i]);
    }
    for (const std::string norm : {"integral", "discrete"})
      for (double c : covers)
        for (int k = 0; k < 3; ++k) {
          const auto& e = res.at(norm).at(P.id).at(c).err;
          err_csv.row(P.id, norm, c, kQuantity[k], e.max[k], e.rms[k]);
        }
  }
  for (const auto& P : panels)
    for (double c : covers)
      for (int k = 0; k < 3; ++k) {
        const auto& e = main.at(P.id).at(c).err;
        const std::string q = std::string(kQuantity[k]) + "_" + cover_label(c);
        d.value(P.id + "_max_" + q, e.max[k], P.description + ": max |<g> - g| over the real particles");
        d.value(P.id + "_rms_" + q, e.rms[k], P.description + ": RMS of <g> - g over the real particles");
      }
}

}  // namespace scenes::interpolation
