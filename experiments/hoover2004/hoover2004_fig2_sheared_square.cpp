// Hoover, Hoover & Merritt 2004, Fig. 2 (Sec. V): a square of the triangular lattice deformed by the simple
// shear u_x = y/4 and released from rest with the matching stress sigma_xy = eta/4 (SPAM; MD needs no stress:
// its springs carry it). Claim: it oscillates symmetrically with no rotation about the centre of mass, L = 0.
// Measured: max |L| relative to the largest angular momentum the motion could carry, sqrt(2 K I), for MD,
// standard SPAM and SPAM with pair torque scaling; and the inversion-symmetry error max |r_i + r_inv(i)|.
// CHOSEN (paper silent): the "unit square" is a square of side 16 lattice spacings centred on a lattice point
// (so it is inversion symmetric), continuity densities from sqrt(4/3), dt = 0.05, t_end = 150 (about two
// periods of the shear oscillation).
#include <cmath>

#include "frame/driver.hpp"
#include "core/lattices.hpp"
#include "core/diagnostics.hpp"
#include "core/run_loop.hpp"
#include "spam/molecular_dynamics.hpp"
#include "spam/spam_solver.hpp"

using namespace sph;

int main(int argc, char** argv) {
  Driver d("hoover2004_fig2_sheared_square", "H-fig2", "sheared square released: L = 0 throughout");
  double side = 16, shear = 0.25, dt = 0.05, t_end = 150;
  d.param("side", side, "square side in lattice spacings").positive().quick(8);
  d.param("shear", shear, "simple shear u_x = shear * y");
  d.param("dt", dt, "RK4 time step").positive();
  d.param("t-end", t_end, "duration").positive().quick(40);
  return d.run(argc, argv, [&] {
    // Lattice points with |x|, |y| <= side/2 of the triangular lattice through the origin.
    std::vector<Vec2> x0;
    const double rs = std::sqrt(3.0) / 2;
    const int jmax = static_cast<int>(std::floor(side / 2 / rs)), imax = static_cast<int>(std::ceil(side / 2)) + 1;
    for (int j = -jmax; j <= jmax; ++j)
      for (int i = -imax; i <= imax; ++i) {
        const Vec2 p(i + 0.5 * (((j % 2) + 2) % 2), j * rs);
        if (std::abs(p.x()) <= side / 2 + 1e-9) x0.push_back(p);
      }
    // Inversion partners.
    std::vector<std::size_t> inv(x0.size());
    for (std::size_t i = 0; i < x0.size(); ++i)
      for (std::size_t j = 0; j < x0.size(); ++j)
        if ((x0[i] + x0[j]).norm() < 1e-9) inv[i] = j;
    std::vector<Vec2> xs = x0;
    for (Vec2& p : xs) p.x() += shear * p.y();
    auto out = d.csv("series.csv", {"variant", "t", "L", "K", "L_over_sqrt2KI", "symmetry_error", "xy_moment"});
    auto snaps = d.csv("snapshots.csv", {"variant", "t", "i", "x", "y"});
    // The same measurements of MD and of SPAM: any solver of the contract of core/run_loop.hpp.
    auto record = [&](const std::string& name, auto& solver) {
      using Solver = std::decay_t<decltype(solver)>;
      const long steps = std::lround(t_end / dt);
      double lmax = 0, sym = 0, lrel = 0, scale = 0;
      auto observe = [&](const Solver& sv) {
        const long s = sv.steps();
        const auto b = centre_of_mass_frame(sv);
        double e = 0, xy = 0;
        for (std::size_t i = 0; i < x0.size(); ++i) {
          e = std::max(e, (sv.position(i) - b.centre + sv.position(inv[i]) - b.centre).norm());
          xy += (sv.position(i) - b.centre).x() * (sv.position(i) - b.centre).y();
        }
        sym = std::max(sym, e);
        lmax = std::max(lmax, std::abs(b.angular_momentum));
        scale = std::max(scale, std::sqrt(2 * b.kinetic * b.inertia));
        if (s % 10 == 0) out.row(name, s * dt, b.angular_momentum, b.kinetic, scale > 0 ? b.angular_momentum / scale : 0.0, e, xy / x0.size());
        if (s == 0 || s == steps / 2 || s == steps)
          for (std::size_t i = 0; i < x0.size(); ++i) snaps.row(name, s * dt, double(i), sv.position(i).x(), sv.position(i).y());
        return false;
      };
      const auto outcome = run(solver, {dt, steps}, observe);
      if (outcome.blew_up()) throw std::runtime_error(name + ": " + outcome.blow_up);
      lrel = lmax / scale;
      d.value("max_L_relative_" + name, lrel, "max |L| / max sqrt(2 K I) over the run");
      d.value("symmetry_error_" + name, sym, "max |r_i + r_inv(i)| about the centre of mass");
    };
    {
      MdSolver md(x0, MdState{xs, std::vector<Vec2>(xs.size(), Vec2::Zero())}, MdParams{});
      record("md", md);
    }
    for (auto torque : {SpamTorque::None, SpamTorque::PairScaling}) {
      SpamParams p;
      const double a = side + 2 * p.h;
      p.box = Box2{-a, -a, a, a, false, false};
      SpamState y(xs.size());
      y.x = xs;
      for (std::size_t i = 0; i < xs.size(); ++i) { y.sxy[i] = p.eta * shear; y.rho[i] = std::sqrt(4.0 / 3.0); }
      SpamOptions o;
      o.torque = torque;
      auto sim = make_spam(o, p, y);
      record(torque == SpamTorque::None ? "spam" : "spam_pair_torque", *sim);
    }
  });
}
