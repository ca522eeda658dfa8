// Gray, Monaghan & Swift 2001, Fig. 1 (Section 5.3.1): a periodic square array under positive pressure
// with zero initial deviatoric stress, run for 10 000 steps with h = dp and h = 1.5 dp. The text: with
// h = dp the transverse mode (B_y < 0, eq 5.24) moves the array to a face-centred-like configuration
// (adjacent columns, or rows, shifted by dp/2); with h = 1.5 dp the final configuration is "less regular".
//
// Parameters (source):
//   10 000 steps, h/dp = 1 and 1.5, square cells, zero initial S            (Section 5.3.1, Fig. 1)
//   rho0 = c0 = 1, mu = 0.22, XSPH eps = 0.5, artificial stress eps = 0.3, n = 4 (Sections 3, 5, 7)
//   CHOSEN: 20 x 20 particles in the periodic cell (the figure's cell is not given), pressure
//     P = 0.05 rho0 c0^2 (rho = 1.05: "positive pressure" without a value), dt = cfl h / c_L (cfl = 0.5, the scheme's default),
//     artificial viscosity alpha = beta = 1, an initial random displacement of 1e-4 dp to seed the
//     instability (round-off alone seeds it too, but more slowly and less reproducibly).
// Order parameters (CHOSEN to make the claims checkable):
//   shift  = < |wrap(y_a - y_b)| > / (dp/2) over the pairs of initially adjacent columns (and the same
//            for rows, x offsets); the larger of the two: 0 for the square array, 1 for face-centred
//   disorder = standard deviation of the nearest-neighbour distance / dp
#include <cmath>
#include <random>

#include "frame/driver.hpp"
#include "updated_lagrangian/gray_solver.hpp"
#include "core/run_loop.hpp"
#include "io/snapshot.hpp"

namespace {

double wrap(double d, double period) { return d - period * std::nearbyint(d / period); }

struct Order { double shift_columns, shift_rows, disorder; };

Order order_parameters(const std::vector<sph::Vec2>& x, int n, double dp, const sph::Box2& box) {
  // Particle (i, j) is index j * n + i (lattice_block order); neighbours by initial adjacency.
  double sc = 0, sr = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto& a = x[j * n + i];
      const auto& right = x[j * n + (i + 1) % n];
      const auto& up = x[((j + 1) % n) * n + i];
      sc += std::abs(wrap(wrap(a.y() - right.y(), box.Ly()), dp));
      sr += std::abs(wrap(wrap(a.x() - up.x(), box.Lx()), dp));
    }
  // Nearest-neighbour distances.
  sph::CellList2D cells(box, 1.6 * dp);
  cells.build(x);
  double s1 = 0, s2 = 0;
  for (std::size_t a = 0; a < x.size(); ++a) {
    double rmin = 1e300;
    cells.for_each_neighbour(x, a, 1.6 * dp, [&](std::size_t, const sph::Vec2&, double r) { rmin = std::min(rmin, r); });
    s1 += rmin / dp;
    s2 += (rmin / dp) * (rmin / dp);
  }
  const double N = static_cast<double>(x.size());
  return {sc / N / (0.5 * dp), sr / N / (0.5 * dp), std::sqrt(std::max(0.0, s2 / N - (s1 / N) * (s1 / N)))};
}

}  // namespace

int main(int argc, char** argv) {
  sph::Driver d("gray2001_fig1_periodic_array", "G-fig1", "Gray et al. 2001 Fig 1: periodic square array under pressure");
  int n = 20, steps = 10000, every = 500;
  double pressure = 0.05, seed_amp = 1e-4;
  sph::GrayParameters scheme;  // the scheme's defaults (parameters.hpp): mu = 0.22, cfl = 0.5
  std::vector<double> h_over_dp{1.0, 1.5};
  d.param("n", n, "particles per side of the periodic cell").positive();
  d.param("steps", steps, "time steps (Gray 2001: 10 000)").positive().quick(2000);
  d.param("pressure", pressure, "initial pressure P / (rho0 c0^2), positive");
  d.param("mu", scheme.mu, "shear modulus").non_negative();
  d.param("cfl", scheme.cfl, "time-step factor").positive();
  d.param("seed-amplitude", seed_amp, "random initial displacement / dp").non_negative();
  d.param("h-over-dp", h_over_dp, "smoothing lengths to run").positive();
  d.param("sample-every", every, "steps between recorded order parameters").positive();

  return d.run(argc, argv, [&] {
    if (n < 4 || steps < 1 || !(pressure > 0)) throw std::invalid_argument("need n >= 4, steps >= 1, pressure > 0");
    const double dp = 1.0 / n;
    auto series = d.csv("order.csv", {"h_over_dp", "step", "t", "shift_columns", "shift_rows", "shift", "disorder"});
    auto finals = d.csv("final_positions.csv", {"h_over_dp", "i", "x", "y"});
    std::vector<double> disorder;
    for (double hr : h_over_dp) {
      sph::ElasticBody body;
      std::mt19937 rng(42);
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      for (const auto& p : sph::lattice_block(sph::LatticeKind::Square, n, n, dp, sph::Vec2(0.5 * dp, 0.5 * dp)))
        body.add(p + seed_amp * dp * sph::Vec2(u(rng), u(rng)), sph::Vec2::Zero(), dp * dp, 1.0 + pressure);
      body.dp = dp;
      body.box = {0, 0, 1, 1, true, true};
      sph::GrayParameters p = scheme;
      p.h_over_dp = hr;
      sph::GraySolver solver(body, p, sph::GrayOptions{});
      const double dt = solver.time_step(0.0);
      sph::SnapshotSeries snaps(d.out_dir() / ("snapshots_h" + sph::format_number(hr) + ".h5"), d.info());
      Order o{};
      auto record = [&](const sph::GraySolver& sv) {
        const long k = sv.steps();
        if (!(k == 0 || k % every == 0 || k == steps)) return false;
        o = order_parameters(body.x, n, dp, body.box);
        series.row(hr, sv.steps(), sv.time(), o.shift_columns, o.shift_rows, std::max(o.shift_columns, o.shift_rows), o.disorder);
        snaps.write(sph::snapshot_of(sv));
        return false;
      };
      const auto outcome = sph::run(solver, {dt, steps}, record);
      if (outcome.blew_up()) throw std::runtime_error(outcome.blow_up);
      for (std::size_t a = 0; a < body.size(); ++a) finals.row(hr, a, body.x[a].x(), body.x[a].y());
      const std::string tag = hr == 1.0 ? "h1" : hr == 1.5 ? "h1p5" : "h" + sph::format_number(hr);
      d.value("shift_order_" + tag, std::max(o.shift_columns, o.shift_rows), "0 square, 1 face-centred (after the run)");
      d.value("disorder_" + tag, o.disorder, "std of nearest-neighbour distance / dp (after the run)");
      disorder.push_back(o.disorder);
    }
    if (h_over_dp.size() == 2 && h_over_dp[0] == 1.0 && h_over_dp[1] == 1.5)
      d.value("disorder_ratio_h1p5_over_h1", disorder[1] / disorder[0], "> 1: h = 1.5 dp ends less regular");
  });
}
