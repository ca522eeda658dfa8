// Work-precision and time-step stability of SPAM on the rotating hexagon (target H-wp, beyond the paper; issue 43
// item 6): the quantities H-fig4 checks, the loss of angular momentum by 60 and 120 degrees of standard SPAM with
// continuity densities (the 217-particle hexagon of Sec. VI, Lucy h = 3, RK4), under time steps from 1 down to
// 0.0125, with each run's wall time; and the largest stable step, against the default 0.05 (a margin row).
// The error of a step is its value's difference from the finest step's (the paper's scheme has no closed form
// for the loss). Every step of the accuracy sweep divides the sampling interval of H-fig4 (1 time unit: its 20
// steps of 0.05), so each run reads L at the same instant (t = 84 for 60 degrees): the error is the step's alone.
// The accuracy runs go to 0.34 revolutions, past the sample at 120 degrees (t = 168), so that it is never the
// run's last step (whose time depends on the step). Stability: the step doubled from the default until a run
// of one revolution (the figures' longest but H-72's) fails (blows up, or flies apart: shape rms > n), then
// bisected between the last stable and the first failing step to 1%. A step far above the default takes few
// steps to a revolution (~120 at dt = 4), so a slow growth can pass: the limit is that of the run as the
// figures run it, an upper estimate of the integrator's; the margin row needs only its order.
#include <algorithm>
#include <cmath>
#include <vector>

#include "frame/driver.hpp"
#include "frame/stability_limit.hpp"
#include "hoover2004/scenes/hexagon.hpp"
#include "spam/spam_solver.hpp"

using namespace sph;

int main(int argc, char** argv) {
  Driver d("hoover2004_hexagon_work_precision", "H-wp", "SPAM hexagon: loss of L against wall time over the time step, and its stability limit");
  scenes::HexagonSetup s;
  s.revolutions = 0.34;  // past 120 degrees (t = 168 at the sample interval 1): the L rows of H-fig4
  double stability_revolutions = 1.0;
  std::vector<double> dts{1.0, 0.5, 0.25, 0.2, 0.1, 0.05, 0.025, 0.0125};  // each divides the sampling interval 1
  double sample_interval = 1.0;  // H-fig4's: 20 steps of its dt = 0.05
  double bisect_to = 0.01;
  d.param("dts", dts, "time steps of the accuracy sweep (the smallest is the reference)").positive().quick({0.2, 0.1, 0.05, 0.025});
  d.param("default-dt", s.dt, "the figures' time step (H-fig4 to H-fig7, scenes/hexagon.hpp)").positive();
  d.param("sample-interval", sample_interval, "time between samples (each step must divide it)").positive();
  d.param("stability-revolutions", stability_revolutions, "length of each stability run, in revolutions").positive();
  d.param("bisect-to", bisect_to, "relative width to which the stability limit is bisected").positive();
  return d.run(argc, argv, [&] {
    const double pi = std::acos(-1.0), omega = s.omega();
    SpamOptions o;
    o.density = SpamDensity::Continuity;  // standard SPAM with continuity: H-fig4's L-loss rows
    auto steps_per_sample = [&](double dt) {  // refused before any run when a step does not divide the interval
      const double k = sample_interval / dt;
      const long every = std::lround(k);
      if (every < 1 || std::abs(k - every) > 1e-9 * k)
        throw std::invalid_argument("--dts: the step " + std::to_string(dt) + " does not divide --sample-interval " +
                                    std::to_string(sample_interval));
      return static_cast<int>(every);
    };
    if (dts.size() < 2) throw std::invalid_argument("--dts: a work-precision sweep needs at least two steps");
    for (double dt : dts) steps_per_sample(dt);
    if (std::count(dts.begin(), dts.end(), s.dt) != 1 || *std::min_element(dts.begin(), dts.end()) >= s.dt)
      throw std::invalid_argument("--dts: needs --default-dt once and a smaller step (the reference)");
    auto run_at = [&](double dt) {
      scenes::HexagonSetup q = s;
      q.dt = dt;
      q.sample_every = steps_per_sample(dt);
      return scenes::run_hexagon_spam(q, o, "spam_cont");
    };
    struct Point { double dt; scenes::HexagonRun r; };
    std::vector<Point> sweep;
    for (double dt : dts) sweep.push_back({dt, run_at(dt)});
    const Point* finest = &sweep.front();
    for (const auto& p : sweep) if (p.dt < finest->dt) finest = &p;
    if (finest->r.failed) throw std::runtime_error("the finest step's run failed: no reference");
    auto loss = [&](const scenes::HexagonRun& r, double deg) { return 1 - r.L_ratio_at_angle(deg * pi / 180, omega); };
    const double ref60 = loss(finest->r, 60), ref120 = loss(finest->r, 120);
    auto wp = d.csv("work_precision.csv", {"dt", "steps", "wall_s", "failed", "L_loss_60deg", "L_loss_120deg",
                                           "error_60deg", "error_120deg"});
    for (const auto& p : sweep) {
      const double l60 = p.r.failed ? NAN : loss(p.r, 60), l120 = p.r.failed ? NAN : loss(p.r, 120);
      wp.row(p.dt, p.r.steps, p.r.wall_s, p.r.failed ? 1 : 0, l60, l120, std::abs(l60 - ref60), std::abs(l120 - ref120));
      if (p.dt == s.dt) {
        d.value("L_loss_60deg_default_dt_error", std::abs(l60 - ref60), "|loss(default dt) - loss(finest dt)| at 60 degrees");
        d.value("L_loss_120deg_default_dt_error", std::abs(l120 - ref120), "|loss(default dt) - loss(finest dt)| at 120 degrees");
      }
    }
    d.value("finest_dt", finest->dt, "the reference step of the accuracy sweep");
    d.value("L_loss_60deg_finest", ref60, "1 - L/L0 at 60 degrees, finest step");
    d.value("L_loss_120deg_finest", ref120, "1 - L/L0 at 120 degrees, finest step");

    // Stability: doubling, then bisection.
    const StabilityLimit limit = largest_stable_step(s.dt, bisect_to, [&](double dt) {
      scenes::HexagonSetup q = s;
      q.dt = dt;
      q.revolutions = stability_revolutions;
      q.sample_every = 1;
      return !scenes::run_hexagon_spam(q, o, "spam_cont").failed;
    });
    const double lo = limit.stable, hi = limit.failing;
    d.value("largest_stable_dt", lo, "largest step of the bisection whose run of stability-revolutions survives");
    d.value("smallest_failing_dt", hi, "smallest failing step of the bisection");
    d.value("stability_margin_spam_cont", lo / s.dt, "largest stable step / the figures' step");
  });
}
