// Ismail 2009's total-Lagrangian scenes for independent codes (make peers, issue 44; tools/peers/scene_tl.py), and
// our measurement of the records they return.
//
//   --scene stress_wave  the 2D strip of Section 5.4.2 (Figs 5.7-5.9; I-2d), ismail2009/scenes/wave_2d.hpp: --kind stress
//                        (free sides; the thesis expects the bar speed sqrt(E/rho), a plane-strain code the plate
//                        speed sqrt(E/(rho (1 - nu^2)))) or strain (sides held transversely: c_L)
//     --action layout    layout.csv: our real particles (x, y, m, rho), the components our body holds (held_x,
//                        held_y: Dirichlet with zero value), the loaded edge (load: the particles on x = 0, where
//                        our traction T11 = p(t) acts), the gauges (gauge = g * rows + r, else -1: the particles our
//                        driver records); settings.csv (every parameter, our step and run length); pulse.csv (our
//                        SmoothedPulse p(t) tabulated finely for a peer to interpolate).
//     --action measure   reads a peer's gauge records (--trace: columns t, T11_<g>_<r> for gauge g, row r) and
//                        measures them with scenes::measure_wave, the function our driver uses: values_peer_tl.csv.
//     --action ours      runs our strip (scenes::run_wave_2d, as the driver) and writes its values and records
//                        (trace_ours.csv, the peer's format) with the run's particles, steps and wall time.
//   --scene hole         the quarter sheet with a hole of Section 5.4.4 (Figs 5.13-5.15; I-hole), ismail2009/scenes/hole.hpp: run
//                        to rest under the ramped traction on x = a, symmetry planes x = 0 (u1 = 0) and y = 0 (u2 = 0)
//     --action layout    layout.csv: our real particles, held_x / held_y (the symmetry planes), load (the edge x = a),
//                        gauge (0: the particle nearest (0, R), else -1); settings.csv; load.csv (our traction
//                        history, scenes::hole_load, over the ramp; held after it).
//     --action measure   reads the peer's stress field on our particles (--trace: columns t, id, T11, T22, T12, id =
//                        our layout row; two frames: 1/omega before the end and at the end) and its speed history
//                        (--history: t, vmax) and reads them out with scenes::hole_stress, as run_hole does ours.
//     --action ours      runs our sheet (scenes::run_hole; --hooke: the linear law) and writes the same values.
// Parameters (source): Ismail 2009 Section 5.3.1 material (rho 8000, E 200 GPa, nu 0.3), the pulse and gauges of
// I-bar (5 us, smoothing 0.5 us, 100 kPa; x = L/3, 2L/3), L = 0.15 m, six rows (Section 5.4.2); CHOSEN as our
// driver: ps 0.5 mm, h = 3.5 ps (support radius). The sheet: scenes::HoleParams (its sources there: 21 x 21,
// E = 70 MPa, nu = 0.49, 5 MPa from Section 5.4.4; a, R, rho, ramp, damping, settling CHOSEN).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include "core/materials.hpp"
#include "frame/driver.hpp"
#include "ismail2009/scenes/hole.hpp"
#include "ismail2009/scenes/wave_2d.hpp"
#include "total_lagrangian/solver_2d.hpp"

namespace {

std::string gauge_column(int g, int r) { return "T11_" + std::to_string(g) + "_" + std::to_string(r); }

/// A number of a peer's file: strtod, which (unlike std::stod) reads subnormal values such as a stress of 1e-310
/// ahead of the pulse; anything that is not entirely a number is an error naming the file.
double number(const std::string& cell, const std::string& file) {
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  if (cell.empty() || end != cell.c_str() + cell.size()) throw std::runtime_error(file + ": not a number: '" + cell + "'");
  return v;
}

}  // namespace

/// The hole scene (--scene hole): layout, measure, ours.
void hole_scene(sph::Driver& d, const std::string& action, const std::string& trace, const std::string& history,
                const scenes::HoleParams& p, int load_points) {
  const scenes::HoleTimes times = scenes::hole_times(p);
  auto write_values = [&](const scenes::HoleStress& st, double settle_change) {
    d.value("peak_sigma1_MPa", st.peak_sigma1 / 1e6, "final max principal Cauchy stress over all particles");
    d.value("sigma1_hole_top_MPa", st.sigma1_hole_top / 1e6, "at the particle nearest (0, R)");
    d.value("smoothed_sigma1_hole_top_MPa", st.smoothed_sigma1_hole_top / 1e6, "SPH-smoothed stress (W T / W 1) at (0, R)");
    d.value("smoothed_peak_sigma1_MPa", st.smoothed_peak_sigma1 / 1e6, "max over the sheet of the smoothed stress");
    d.value("settle_change", settle_change, "change of the smoothed (0, R) stress over the last 1/omega, relative");
    d.value("kirsch_MPa", 3 * p.traction / 1e6, "3 sigma, infinite sheet");
  };
  if (action == "ours") {
    const scenes::HoleResult r = scenes::run_hole(p);
    if (!r.finite) throw std::runtime_error("our sheet run became non-finite");
    scenes::HoleStress st;
    st.peak_sigma1 = r.peak_sigma1;
    st.sigma1_hole_top = r.sigma1_hole_top;
    st.smoothed_peak_sigma1 = r.smoothed_peak_sigma1;
    st.smoothed_sigma1_hole_top = r.smoothed_sigma1_hole_top;
    write_values(st, r.settle_change);
    d.value("rest_speed_ratio", r.rest_speed_ratio, "largest particle speed at the end over its peak during the run");
    d.value("speed_rise", r.speed_rise, "largest particle speed at the end / its smallest after the ramp");
    d.value("particles", r.particles, "real particles");
    d.value("steps", r.steps, "steps of the run");
    d.value("wall_s", r.wall_s, "wall time of the time loop");
    d.value("dt", p.dt_factor * p.h_over_ps * p.a / (p.n - 1) / times.cL, "our step, dt_factor h / c_L");
    return;
  }
  const sph::TlSolver2D body(scenes::hole_config(p));
  const int n = body.n_real();
  if (action == "measure") {
    if (trace.empty() || history.empty()) throw std::invalid_argument("--scene hole --action measure needs --trace and --history");
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
    const auto& before = frames.begin()->second;
    const auto& end = frames.rbegin()->second;
    const scenes::HoleStress st = scenes::hole_stress(p, body, [&](int i) { return end[i]; });
    const scenes::HoleStress sb = scenes::hole_stress(p, body, [&](int i) { return before[i]; });
    write_values(st, std::abs(st.smoothed_sigma1_hole_top - sb.smoothed_sigma1_hole_top) / st.smoothed_sigma1_hole_top);
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
    return;
  }
  // action layout
  const sph::TlConfig2D cfg = scenes::hole_config(p);
  std::vector<int> held_x(n, 0), held_y(n, 0);
  for (const auto& [i, c] : cfg.real_on_dirichlet) {
    const auto& bc = cfg.conditions.at(c);
    for (int k = 0; k < 2; ++k)
      if (bc.dirichlet[k] && bc.value[k](cfg.real[i], 1e-6) != 0.0) throw std::logic_error("peer_tl: a non-zero Dirichlet value");
    held_x[i] = held_x[i] || bc.dirichlet[0];
    held_y[i] = held_y[i] || bc.dirichlet[1];
  }
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

int main(int argc, char** argv) {
  sph::Driver d("peer_tl", "peers", "Ismail 2009's total-Lagrangian scenes written for independent codes, and their records measured");
  std::string scene = "stress_wave", action = "layout", trace, history;
  scenes::Wave2DSpec w;
  scenes::HoleParams hole;
  int pulse_points = 20001;
  d.param("scene", scene, "stress_wave (I-2d, Figs 5.7-5.9) or hole (I-hole, Figs 5.13-5.15)").one_of({"stress_wave", "hole"});
  d.param("action", action, "layout: our particles and settings; measure: a peer's records; ours: our run").one_of({"layout", "measure", "ours"});
  d.param("trace", trace, "the peer's records (action measure): CSV with columns t, T11_<g>_<r>");
  d.param("kind", w.kind, "stress: free sides (Figs 5.8-5.9); strain: sides held transversely (Fig 5.7)").one_of({"stress", "strain"});
  d.param("ps", w.ps, "particle spacing, m (CHOSEN as I-2d's driver)").positive();
  d.param("rows", w.rows, "particles across the thickness (Section 5.4.2: six)").at_least(3);
  d.param("h-over-ps", w.h_over_ps, "support radius in spacings (CHOSEN as I-2d's driver)").positive();
  d.param("pulse-points", pulse_points, "points of pulse.csv / load.csv over the pulse / the ramp").at_least(101);
  d.param("history", history, "the peer's speed history (hole, action measure): CSV with columns t, vmax");
  d.param("n", hole.n, "hole: particles along a side (Section 5.4.4: 21)").at_least(5);
  d.param("hooke", hole.hooke, "hole, action ours: the linear law (Hooke) instead of neo-Hookean");


  return d.run(argc, argv, [&] {
    if (scene == "hole") {
      hole_scene(d, action, trace, history, hole, pulse_points);
      return;
    }
    const sph::Lame lame = sph::lame_from_young_poisson(w.E, w.nu);
    const double cL = sph::longitudinal_wave_speed(lame, w.rho);
    auto theory = [&] {
      d.value("c_L", cL, "sqrt((lambda + 2 mu) / rho): the strain wave (plane strain)");
      d.value("c_plate", std::sqrt(w.E / (w.rho * (1 - w.nu * w.nu))), "sqrt(E / (rho (1 - nu^2))): free sides, plane strain");
      d.value("c_bar", std::sqrt(w.E / w.rho), "sqrt(E / rho): free sides, plane stress (the thesis's c_b)");
    };
    if (action == "measure") {
      if (trace.empty()) throw std::invalid_argument("--action measure needs --trace <file>");
      const sph::CsvTable t = sph::read_csv(trace);
      const std::size_t ct = t.column("t");
      const auto gx = w.gauge_x();
      std::vector<double> ts;
      std::vector<std::vector<std::vector<double>>> T(gx.size(), std::vector<std::vector<double>>(w.rows));
      std::vector<std::vector<std::size_t>> col(gx.size());
      for (std::size_t g = 0; g < gx.size(); ++g)
        for (int r = 0; r < w.rows; ++r) col[g].push_back(t.column(gauge_column(static_cast<int>(g), r)));
      for (const auto& row : t.rows) {
        const double ti = number(row.at(ct), trace);
        if (!std::isfinite(ti)) throw std::runtime_error(trace + ": a non-finite time");
        if (!ts.empty() && !(ti > ts.back())) throw std::runtime_error(trace + ": times not increasing at t = " + row.at(ct));
        ts.push_back(ti);
        for (std::size_t g = 0; g < gx.size(); ++g)
          for (int r = 0; r < w.rows; ++r) {
            const double v = number(row.at(col[g][r]), trace);
            if (!std::isfinite(v)) throw std::runtime_error(trace + ": a non-finite T11 at t = " + row.at(ct));
            T[g][r].push_back(v);
          }
      }
      if (ts.size() < 10) throw std::runtime_error(trace + ": fewer than 10 records");
      const scenes::WaveMeasures m = scenes::measure_wave(w, ts, T);
      d.value("wave_speed", m.speed, "pulse centroids at x = L/3, 2L/3, mid-thickness (scenes::measure_wave)");
      d.value("plateau_over_p0", m.plateau_over_p0, "mean T11 mid-pulse at x = L/3, mid-thickness / p0");
      d.value("thickness_spread_over_p0", m.spread_over_p0, "max over rows of |plateau - mid-row plateau| / p0");
      d.value("t_last", ts.back(), "the records' last time");
      theory();
      return;
    }
    if (action == "ours") {
      const scenes::WaveRecord rec = scenes::run_wave_2d(w);
      const scenes::WaveMeasures m = scenes::measure_wave(w, rec.t, rec.T);
      std::vector<std::string> cols{"t"};
      for (std::size_t g = 0; g < rec.T.size(); ++g)
        for (int r = 0; r < w.rows; ++r) cols.push_back(gauge_column(static_cast<int>(g), r));
      auto out = d.csv("trace_ours.csv", cols);
      for (std::size_t k = 0; k < rec.t.size(); ++k) {
        std::vector<std::string> cells{sph::format_number(rec.t[k])};
        for (const auto& g : rec.T)
          for (const auto& v : g) cells.push_back(sph::format_number(v[k]));
        out.write_cells(cells);
      }
      d.value("wave_speed", m.speed, "pulse centroids at x = L/3, 2L/3, mid-thickness (scenes::measure_wave)");
      d.value("plateau_over_p0", m.plateau_over_p0, "mean T11 mid-pulse at x = L/3, mid-thickness / p0");
      d.value("thickness_spread_over_p0", m.spread_over_p0, "max over rows of |plateau - mid-row plateau| / p0");
      d.value("particles", rec.particles, "real particles");
      d.value("steps", static_cast<double>(rec.steps), "steps of the run");
      d.value("wall_s", rec.wall_s, "wall time of the time loop");
      d.value("dt", scenes::wave_dt(w, w.h_over_ps * w.ps), "our step, 0.3 h / c_L");
      theory();
      return;
    }
    // action layout
    const sph::TlConfig2D cfg = scenes::wave_body(w);
    const int n = static_cast<int>(cfg.real.size());
    std::vector<int> held_x(n, 0), held_y(n, 0), gauge(n, -1);
    for (const auto& [i, c] : cfg.real_on_dirichlet) {
      const auto& bc = cfg.conditions.at(c);
      // A peer holds a component at zero: every Dirichlet value of this scene is zero (check it).
      for (int k = 0; k < 2; ++k)
        if (bc.dirichlet[k] && bc.value[k](cfg.real[i], 1e-6) != 0.0) throw std::logic_error("peer_tl: a non-zero Dirichlet value");
      held_x[i] = held_x[i] || bc.dirichlet[0];
      held_y[i] = held_y[i] || bc.dirichlet[1];
    }
    // The gauges as our run picks them (TlSolver2D::nearest over the real particles).
    {
      sph::TlSolver2D body(scenes::wave_body(w));
      const auto gx = w.gauge_x();
      for (std::size_t g = 0; g < gx.size(); ++g)
        for (int r = 0; r < w.rows; ++r) {
          const int i = body.nearest({gx[g], r * w.ps});
          if (gauge[i] >= 0) throw std::logic_error("peer_tl: two gauges on one particle");
          gauge[i] = static_cast<int>(g) * w.rows + r;
        }
      if (std::abs(body.h() - w.h_over_ps * w.ps) > 1e-12 * body.h()) throw std::logic_error("peer_tl: support radius is not h_over_ps ps");
    }
    const double m = w.rho * w.ps * w.ps;  // our particle's mass (TlSolver2D::mass) per unit thickness
    auto layout = d.csv("layout.csv", {"x", "y", "m", "rho", "held_x", "held_y", "load", "gauge"});
    int loaded = 0;
    for (int i = 0; i < n; ++i) {
      const bool load = std::abs(cfg.real[i].x()) < 1e-9 * w.ps;  // the left edge, where T11 = p(t) acts
      loaded += load;
      layout.row(cfg.real[i].x(), cfg.real[i].y(), m, w.rho, held_x[i], held_y[i], load ? 1 : 0, gauge[i]);
    }
    if (loaded != w.rows) throw std::logic_error("peer_tl: the loaded edge has " + std::to_string(loaded) + " particles, not rows");
    const scenes::SmoothedPulse p(w.p0, w.pulse, w.smooth);
    const double t_pulse = w.pulse + 2 * w.smooth;
    auto pulse = d.csv("pulse.csv", {"t", "p"});
    for (int k = 0; k < pulse_points; ++k) {
      const double t = t_pulse * k / (pulse_points - 1);
      pulse.row(t, p(t));
    }
    const double h = w.h_over_ps * w.ps;
    auto settings = d.csv("settings.csv", {"name", "value"});
    const std::pair<const char*, double> rows[] = {
        {"ps", w.ps}, {"support_radius", h}, {"rows", static_cast<double>(w.rows)}, {"L", w.L}, {"rho", w.rho},
        {"E", w.E}, {"nu", w.nu}, {"lambda", lame.lambda}, {"mu", lame.mu}, {"c_L", cL}, {"p0", w.p0},
        {"pulse", w.pulse}, {"smooth", w.smooth}, {"t_pulse_end", t_pulse}, {"dt", scenes::wave_dt(w, h)},
        {"t_end", scenes::wave_t_end(w)}, {"gauge_x_0", w.gauge_x()[0]}, {"gauge_x_1", w.gauge_x()[1]},
        {"strain_sides", w.kind == "strain" ? 1.0 : 0.0}, {"particles", static_cast<double>(n)}};
    for (const auto& [name, value] : rows) settings.row(name, value);
    d.value("particles", n, "real particles of our strip");
    d.value("dt", scenes::wave_dt(w, h), "our step");
    theory();
  });
}
