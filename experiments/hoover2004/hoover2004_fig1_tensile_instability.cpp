// Hoover, Hoover & Merritt 2004, Fig. 1 (Sec. IV): tensile instability. A motionless triangular lattice under
// uniform hydrostatic tension sigma_xx = sigma_yy = 0.01 or 0.02 (sigma_xy = 0), one particle given the speed
// 1e-10; the total kinetic energy against time. Standard SPAM (dr/dt = v) grows exponentially, faster for
// 0.02; with Monaghan's <v>_M (arithmetic rho_ij) at 0.02 there is no growth over the same time.
// CHOSEN (paper silent): a periodic 24 x 24 crystal (576 particles, as in Fig. 3), so the uniform tension is
// an exact equilibrium (a free sample's surface would not be); summed densities; the kicked particle is the
// one nearest the centre, kicked along x; dt = 0.1; t_end = 240 (long enough for K of the 0.02 run to grow
// the ten decades that are the paper's five decades of speed, at ~0.057 decades per unit time).
// The growth rate of K is the least-squares slope of ln K over the part of the run where
// 1e2 K0 < K < 1e12 K0 (after the start-up transient, before saturation).
#include <cmath>

#include "frame/driver.hpp"
#include "core/lattices.hpp"
#include "core/run_loop.hpp"
#include "spam/spam_solver.hpp"

using namespace sph;

int main(int argc, char** argv) {
  Driver d("hoover2004_fig1_tensile_instability", "H-fig1", "kinetic energy growth of a kicked lattice under tension");
  int n = 24;
  double dt = 0.1, t_end = 240, kick = 1e-10;
  d.param("n", n, "particles per row and rows (periodic n x n crystal)").positive().quick(12);
  d.param("dt", dt, "RK4 time step").positive().quick(0.2);
  d.param("t-end", t_end, "duration").positive().quick(120);
  d.param("kick", kick, "initial speed of the kicked particle").non_negative();
  return d.run(argc, argv, [&] {
    const double Lx = n, Ly = n * std::sqrt(3.0) / 2;
    const auto x0 = rectangle(LatticeKind::Triangular, 0, 0, Lx, Ly, 1.0);
    SpamParams p;
    p.box = Box2{0, 0, Lx, Ly, true, true};
    std::size_t centre = 0;
    for (std::size_t i = 0; i < x0.size(); ++i)
      if ((x0[i] - Vec2(Lx / 2, Ly / 2)).norm() < (x0[centre] - Vec2(Lx / 2, Ly / 2)).norm()) centre = i;
    auto out = d.csv("kinetic_energy.csv", {"variant", "stress", "t", "K"});
    struct Case { std::string name; double stress; SpamAdvection adv; };
    std::vector<double> rates;
    for (const Case& c : {Case{"standard", 0.01, SpamAdvection::Velocity}, Case{"standard", 0.02, SpamAdvection::Velocity},
                          Case{"monaghan", 0.02, SpamAdvection::MonaghanArithmetic}}) {
      SpamState y(x0.size());
      y.x = x0;
      for (std::size_t i = 0; i < x0.size(); ++i) { y.sxx[i] = y.syy[i] = c.stress; y.rho[i] = std::sqrt(4.0 / 3.0); }
      y.v[centre] = Vec2(kick, 0.0);
      SpamOptions o;
      o.density = SpamDensity::Summation;
      o.advection = c.adv;
      auto sim = make_spam(o, p, y);
      const double K0 = 0.5 * kick * kick;
      const long steps = std::lround(t_end / dt);
      double st = 0, sk = 0, stt = 0, stk = 0, kmax = K0;
      long m = 0;
      auto observe = [&](const SpamSolver& sv) {
        const long s = sv.steps();
        double K = 0;
        for (const Vec2& v : sv.state().v) K += 0.5 * v.squaredNorm();
        if (!std::isfinite(K)) throw std::runtime_error("non-finite kinetic energy");
        kmax = std::max(kmax, K);
        const double t = s * dt;
        if (s % 2 == 0) out.row(c.name, c.stress, t, K);
        if (K > 1e2 * K0 && K < 1e12 * K0) { const double l = std::log(K); st += t; sk += l; stt += t * t; stk += t * l; ++m; }
        return false;
      };
      const auto outcome = run(*sim, {dt, steps}, observe);
      if (outcome.blew_up()) throw std::runtime_error(outcome.blow_up);
      const std::string tag = c.name + "_" + (c.stress < 0.015 ? "0.01" : "0.02");
      const double rate = m > 10 ? (m * stk - st * sk) / (m * stt - st * st) : 0.0;
      d.value("growth_rate_K_" + tag, rate, "d ln K / dt fitted where 1e2 K0 < K < 1e12 K0 (0: no such window)");
      d.value("decades_K_growth_" + tag, std::log10(kmax / K0), "log10(max K / K0) over the run");
      rates.push_back(rate);
    }
    d.value("growth_rate_ratio_0.02_over_0.01", rates[1] / rates[0], "faster growth at the larger tension");
  });
}
