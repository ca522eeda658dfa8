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
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/materials.hpp"
#include "frame/driver.hpp"
#include "ismail2009/scenes/hole.hpp"
#include "ismail2009/scenes/wave_2d.hpp"
#include "peers/peer_tl_hole.hpp"
#include "total_lagrangian/solver_2d.hpp"

namespace {

using peers::number;

std::string gauge_column(int g, int r) { return "T11_" + std::to_string(g) + "_" + std::to_string(r); }

/// The wave speeds the strip's records are read against (every action of the stress wave writes them).
void write_wave_theory(sph::Driver& d, const scenes::Wave2DSpec& w, double cL) {
  d.value("c_L", cL, "sqrt((lambda + 2 mu) / rho): the strain wave (plane strain)");
  d.value("c_plate", std::sqrt(w.E / (w.rho * (1 - w.nu * w.nu))), "sqrt(E / (rho (1 - nu^2))): free sides, plane strain");
  d.value("c_bar", std::sqrt(w.E / w.rho), "sqrt(E / rho): free sides, plane stress (the thesis's c_b)");
}

/// --action measure: the peer's gauge records (--trace) measured with scenes::measure_wave.
void wave_measure(sph::Driver& d, const scenes::Wave2DSpec& w, const std::string& trace) {
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
}

/// --action ours: our strip's run, its records in the peer's format (trace_ours.csv) and its values.
void wave_ours(sph::Driver& d, const scenes::Wave2DSpec& w) {
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
}

/// --action layout: layout.csv, pulse.csv (`pulse_points` over the pulse) and settings.csv.
void wave_layout(sph::Driver& d, const scenes::Wave2DSpec& w, const sph::Lame& lame, double cL, int pulse_points) {
  const sph::TlConfig2D cfg = scenes::wave_body(w);
  const int n = static_cast<int>(cfg.real.size());
  std::vector<int> held_x, held_y, gauge(n, -1);
  peers::held_components(cfg, held_x, held_y);
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
}

}  // namespace

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
    if (scene == "hole") return peers::hole_scene(d, action, trace, history, hole, pulse_points);
    const sph::Lame lame = sph::lame_from_young_poisson(w.E, w.nu);
    const double cL = sph::longitudinal_wave_speed(lame, w.rho);
    if (action == "measure") wave_measure(d, w, trace);
    else if (action == "ours") wave_ours(d, w);
    else wave_layout(d, w, lame, cL, pulse_points);  // action layout
    write_wave_theory(d, w, cL);
  });
}
