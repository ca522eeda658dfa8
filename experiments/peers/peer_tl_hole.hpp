// The sheet with a hole of peer_tl (--scene hole; peer_tl.cpp documents the scenes and their actions): our layout
// written for independent codes, their records measured, and our own run measured the same way. Included by
// peer_tl.cpp only (a tool of make peers is one source file: CMakeLists.txt builds experiments/peers/peer_*.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "frame/driver.hpp"
#include "io/csv.hpp"
#include "ismail2009/scenes/hole.hpp"
#include "total_lagrangian/solver_2d.hpp"

namespace peers {

/// A number of a peer's file: strtod, which (unlike std::stod) reads subnormal values such as a stress of 1e-310
/// ahead of the pulse; anything that is not entirely a number is an error naming the file.
inline double number(const std::string& cell, const std::string& file) {
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  if (cell.empty() || end != cell.c_str() + cell.size()) throw std::runtime_error(file + ": not a number: '" + cell + "'");
  return v;
}

/// The values read from the sheet's stress field, ours and a peer's alike.
inline void write_hole_values(sph::Driver& d, const scenes::HoleParams& p, const scenes::HoleStress& st, double settle_change) {
  d.value("peak_sigma1_MPa", st.peak_sigma1 / 1e6, "final max principal Cauchy stress over all particles");
  d.value("sigma1_hole_top_MPa", st.sigma1_hole_top / 1e6, "at the particle nearest (0, R)");
  d.value("smoothed_sigma1_hole_top_MPa", st.smoothed_sigma1_hole_top / 1e6, "SPH-smoothed stress (W T / W 1) at (0, R)");
  d.value("smoothed_peak_sigma1_MPa", st.smoothed_peak_sigma1 / 1e6, "max over the sheet of the smoothed stress");
  d.value("settle_change", settle_change, "change of the smoothed (0, R) stress over the last 1/omega, relative");
  d.value("kirsch_MPa", 3 * p.traction / 1e6, "3 sigma, infinite sheet");
}

/// --action ours: our sheet's run and its values.
inline void hole_ours(sph::Driver& d, const scenes::HoleParams& p, const scenes::HoleTimes& times) {
  const scenes::HoleResult r = scenes::run_hole(p);
  if (!r.finite) throw std::runtime_error("our sheet run became non-finite");
  scenes::HoleStress st;
  st.peak_sigma1 = r.peak_sigma1;
  st.sigma1_hole_top = r.sigma1_hole_top;
  st.smoothed_peak_sigma1 = r.smoothed_peak_sigma1;
  st.smoothed_sigma1_hole_top = r.smoothed_sigma1_hole_top;
  write_hole_values(d, p, st, r.settle_change);
  d.value("rest_speed_ratio", r.rest_speed_ratio, "largest particle speed at the end over its peak during the run");
  d.value("speed_rise", r.speed_rise, "largest particle speed at the end / its smallest after the ramp");
  d.value("particles", r.particles, "real particles");
  d.value("steps", r.steps, "steps of the run");
  d.value("wall_s", r.wall_s, "wall time of the time loop");
  d.value("dt", p.dt_factor * p.h_over_ps * p.a / (p.n - 1) / times.cL, "our step, dt_factor h / c_L");
}

/// The peer's stress frames on our particles by time (--trace: columns t, id, T11, T22, T12), each particle
/// exactly once in each; `n` our real particles.
inline std::map<double, std::vector<sph::Tensor2>> read_stress_frames(const std::string& trace, int n) {
  const sph::CsvTable t = sph::read_csv(trace);
  const std::size_t ct = t.column("t"), ci = t.column("id"), c11 = t.column("T11"), c22 = t.column("T22"), c12 = t.column("T12");
  std::map<double, std::vector<sph::Tensor2>> frames;
  std::map<double, std::vector<int>> seen;
  for (const auto& row : t.rows) {
    const double ti = number(row.at(ct), trace);
    const double idd = number(row.at(ci), trace);
    const int id = static_cast<int>(idd);
    if (idd != id || id < 0 || id >= n) throw std::runtime_error(trace + ": id " + row.at(ci) + " is not a particle of our layout");
    auto& f = frames[ti];
    if (f.empty()) { f.assign(n, sph::Tensor2::Zero()); seen[ti].assign(n, 0); }
    sph::Tensor2 T;
    T << number(row.at(c11), trace), number(row.at(c12), trace), number(row.at(c12), trace), number(row.at(c22), trace);
    if (!T.allFinite()) throw std::runtime_error(trace + ": a non-finite stress at t = " + row.at(ct));
    f[id] = T;
    ++seen[ti][id];
  }
  if (frames.size() != 2) throw std::runtime_error(trace + ": needs two frames (1/omega before the end, the end), has " + std::to_string(frames.size()));
  for (const auto& [ti, c] : seen)
    for (int i = 0; i < n; ++i)
      if (c[i] != 1) throw std::runtime_error(trace + ": particle " + std::to_string(i) + " not exactly once in the frame at t = " + std::to_string(ti));
  return frames;
}

/// --action measure: the peer's stress field and speed history read out as run_hole reads ours.
inline void hole_measure(sph::Driver& d, const scenes::HoleParams& p, const scenes::HoleTimes& times,
                         const sph::TlSolver2D& body, const std::string& trace, const std::string& history) {
  if (trace.empty() || history.empty()) throw std::invalid_argument("--scene hole --action measure needs --trace and --history");
  const auto frames = read_stress_frames(trace, body.n_real());
  const auto& before = frames.begin()->second;
  const auto& end = frames.rbegin()->second;
  const scenes::HoleStress st = scenes::hole_stress(p, body, [&](int i) { return end[i]; });
  const scenes::HoleStress sb = scenes::hole_stress(p, body, [&](int i) { return before[i]; });
  write_hole_values(d, p, st, std::abs(st.smoothed_sigma1_hole_top - sb.smoothed_sigma1_hole_top) / st.smoothed_sigma1_hole_top);
  // The speed history: run_hole's at-rest measures (its samples every 20 steps; the peer's likewise).
  const sph::CsvTable h = sph::read_csv(history);
  const std::size_t ht = h.column("t"), hv = h.column("vmax");
  double vpeak = 0, vmin_after = std::numeric_limits<double>::infinity(), vend = NAN;
  for (const auto& row : h.rows) {
    const double ti = number(row.at(ht), history), v = number(row.at(hv), history);
    vpeak = std::max(vpeak, v);
    if (ti > times.t_ramp) vmin_after = std::min(vmin_after, v);
    vend = v;
  }
  d.value("rest_speed_ratio", vend / vpeak, "largest particle speed at the end over its peak during the run");
  d.value("speed_rise", vend / vmin_after, "largest particle speed at the end / its smallest after the ramp");
  d.value("t_end_frame", frames.rbegin()->first, "time of the last frame");
  d.value("t_before_frame", frames.begin()->first, "time of the frame 1/omega before the end");
}

/// Which components of each real particle a peer holds at zero (its fixed flags in x and y). A peer holds a
/// component at zero only: every Dirichlet value of our scenes is zero, checked here.
inline void held_components(const sph::TlConfig2D& cfg, std::vector<int>& held_x, std::vector<int>& held_y) {
  held_x.assign(cfg.real.size(), 0);
  held_y.assign(cfg.real.size(), 0);
  for (const auto& [i, c] : cfg.real_on_dirichlet) {
    const auto& bc = cfg.conditions.at(c);
    for (int k = 0; k < 2; ++k)
      if (bc.dirichlet[k] && bc.value[k](cfg.real[i], 1e-6) != 0.0) throw std::logic_error("peer_tl: a non-zero Dirichlet value");
    held_x[i] = held_x[i] || bc.dirichlet[0];
    held_y[i] = held_y[i] || bc.dirichlet[1];
  }
}

/// --action layout: layout.csv, load.csv (`load_points` over the ramp) and settings.csv.
inline void hole_layout(sph::Driver& d, const scenes::HoleParams& p, const scenes::HoleTimes& times,
                        const sph::TlSolver2D& body, int load_points) {
  const int n = body.n_real();
  const sph::TlConfig2D cfg = scenes::hole_config(p);
  std::vector<int> held_x, held_y;
  held_components(cfg, held_x, held_y);
  const double ps = p.a / (p.n - 1);
  const int top = body.nearest({0.0, p.R});
  auto layout = d.csv("layout.csv", {"x", "y", "m", "rho", "held_x", "held_y", "load", "gauge"});
  int loaded = 0;
  for (int i = 0; i < n; ++i) {
    const bool load = std::abs(cfg.real[i].x() - p.a) < 1e-9 * ps;  // the loaded edge x = a
    loaded += load;
    layout.row(cfg.real[i].x(), cfg.real[i].y(), body.mass(i), p.rho, held_x[i], held_y[i], load ? 1 : 0, i == top ? 0 : -1);
  }
  if (loaded != p.n) throw std::logic_error("peer_tl: the loaded edge has " + std::to_string(loaded) + " particles, not n");
  auto load = d.csv("load.csv", {"t", "traction"});
  for (int k = 0; k < load_points; ++k) {
    const double t = times.t_ramp * k / (load_points - 1);
    load.row(t, scenes::hole_load(p, times, t));
  }
  auto settings = d.csv("settings.csv", {"name", "value"});
  const std::pair<const char*, double> rows[] = {
      {"n", static_cast<double>(p.n)}, {"a", p.a}, {"R", p.R}, {"ps", ps}, {"support_radius", body.h()}, {"rho", p.rho},
      {"E", p.E}, {"nu", p.nu}, {"traction", p.traction}, {"c_L", times.cL}, {"c_T", times.cT}, {"omega", times.omega},
      {"t_ramp", times.t_ramp}, {"t_end", times.t_end}, {"t_before", times.t_end - 1.0 / times.omega},
      {"damping", p.damping * times.omega}, {"dt", p.dt_factor * body.h() / times.cL}, {"particles", static_cast<double>(n)}};
  for (const auto& [name, value] : rows) settings.row(name, value);
  d.value("particles", n, "real particles of our sheet");
  d.value("kirsch_MPa", 3 * p.traction / 1e6, "3 sigma, infinite sheet");
}

/// The hole scene (--scene hole): layout, measure, ours.
inline void hole_scene(sph::Driver& d, const std::string& action, const std::string& trace, const std::string& history,
                       const scenes::HoleParams& p, int load_points) {
  const scenes::HoleTimes times = scenes::hole_times(p);
  if (action == "ours") return hole_ours(d, p, times);
  const sph::TlSolver2D body(scenes::hole_config(p));
  if (action == "measure") return hole_measure(d, p, times, body, trace, history);
  hole_layout(d, p, times, body, load_points);
}

}  // namespace peers
