#include "hoover2004/scenes/hexagon.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/diagnostics.hpp"
#include "core/run_loop.hpp"
#include "spam/molecular_dynamics.hpp"
#include "spam/spam_solver.hpp"

namespace sph::scenes {

namespace {
constexpr double kPi = 3.14159265358979323846;

// The loop shared by MD and SPAM (any solver of the contract of core/run_loop.hpp): `internal()` is the
// internal energy, `density()` the particle densities of the current state, `on_sample()` runs after each
// sample. Samples every sample_every steps and after the last; a run fails when it blows up (non-finite
// state) or flies apart (shape rms > n).
template <class Solver, class Internal, class Density, class OnSample, class AfterStep>
void run_loop(const HexagonSetup& s, HexagonRun& r, Solver& solver, Internal&& internal, Density&& density,
              OnSample&& on_sample, AfterStep&& after_step) {
  const auto x0 = s.lattice();
  const double omega = s.omega(), dt = s.dt;
  const long steps = std::lround(s.revolutions * s.revolution_time() / dt);
  std::vector<long> snap_steps;
  for (double a : s.snapshot_angles) snap_steps.push_back(std::lround(a / omega / dt));
  double unwrapped = 0, last = 0;
  auto positions = [&]() -> std::vector<Vec2> {
    std::vector<Vec2> x(solver.size());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = solver.position(i);
    return x;
  };
  auto sample = [&](long n) {
    const auto x = positions();
    const auto b = centre_of_mass_frame(solver);
    const ShapeFit f = shape_fit(x0, x);
    double da = f.angle - last;
    da -= 2 * kPi * std::nearbyint(da / (2 * kPi));
    unwrapped += da;
    last = f.angle;
    const double U = internal();
    r.t.push_back(n * dt); r.L.push_back(b.angular_momentum); r.K.push_back(b.kinetic); r.U.push_back(U);
    r.shape_rms.push_back(f.rms); r.angle.push_back(unwrapped);
    r.gauss_D.push_back(b.kinetic > 0 ? 1.0 - b.angular_momentum * b.angular_momentum / (2 * b.kinetic * b.inertia) : 0.0);
    r.gauss_beta.push_back(0.0);
    if (n == 0) { r.L0 = b.angular_momentum; r.E0 = b.kinetic + U; }
    on_sample();
  };
  auto snapshots = [&](long n) {
    for (std::size_t k = 0; k < snap_steps.size(); ++k)
      if (snap_steps[k] == n) { r.snapshot_angles.push_back(s.snapshot_angles[k]); r.snapshots.push_back(positions()); r.snapshot_density.push_back(density()); }
  };
  auto observe = [&](const Solver& sv) {
    const long n = sv.steps();
    if (n > 0) after_step();
    if (n == 0 || n % s.sample_every == 0 || n == steps) {
      sample(n);
      if (n > 0 && r.shape_rms.back() > s.shells) { r.failed = true; r.failed_at = n * dt; return true; }
    }
    snapshots(n);
    return false;
  };
  const RunOutcome out = run(solver, {dt, steps}, observe);
  if (out.blew_up()) { r.failed = true; r.failed_at = solver.steps() * dt; }
  r.steps = solver.steps();
  r.wall_s = out.wall_s;
}
}  // namespace

std::size_t HexagonRun::sample_at_angle(double a, double omega) const {
  // The first sample at or after the angle, allowing half a sample interval of rounding.
  const double half = t.size() > 1 ? 0.5 * (t[1] - t[0]) : 0.0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= a / omega - half) return k;
  return t.size();
}

std::vector<Vec2> HexagonSetup::lattice() const { return hexagon(shells, 1.0); }

SpamParams HexagonSetup::spam_params() const {
  SpamParams p = params;
  const double a = shells + 2 * p.h;
  p.box = Box2{-a, -a, a, a, false, false};
  return p;
}

double HexagonRun::L_ratio_at_angle(double a, double omega) const {
  const std::size_t k = sample_at_angle(a, omega);
  if (k < t.size()) return L[k] / L0;
  return std::numeric_limits<double>::quiet_NaN();
}

HexagonRun run_hexagon_md(const HexagonSetup& s) {
  HexagonRun r;
  r.variant = "md";
  const auto x0 = s.lattice();
  MdParams mp;
  mp.mass = s.params.mass;
  MdState y{x0, std::vector<Vec2>(x0.size())};
  for (std::size_t i = 0; i < x0.size(); ++i) y.v[i] = s.omega() * Vec2(-x0[i].y(), x0[i].x());
  MdSolver md(x0, y, mp);
  const std::vector<double> rho0(x0.size(), std::sqrt(4.0 / 3.0));
  run_loop(s, r, md, [&] { return md.potential_energy(); }, [&] { return rho0; }, [] {}, [] {});
  return r;
}

HexagonRun run_hexagon_spam(const HexagonSetup& s, const SpamOptions& o, const std::string& variant) {
  HexagonRun r;
  r.variant = variant;
  const auto x0 = s.lattice();
  SpamState y(x0.size());
  for (std::size_t i = 0; i < x0.size(); ++i) {
    y.x[i] = x0[i];
    y.v[i] = s.omega() * Vec2(-x0[i].y(), x0[i].x());
    y.rho[i] = std::sqrt(4.0 / 3.0);  // rho(t = 0) = sqrt(4/3) for continuity densities (Fig. 4c, 5)
  }
  auto sim = make_spam(o, s.spam_params(), y);
  std::vector<double> rho;
  const double m = s.params.mass;
  const bool gauss = o.torque == SpamTorque::Gauss;
  // Optional: the integral of the advection torque sum m (dr/dt - <dr/dt>) x (v - <v>), trapezoidal per step.
  SpamState dy;
  double adv_prev = 0, adv_int = 0;
  auto advection_torque = [&] {
    sim->derivative(dy);
    const auto& v = sim->state().v;
    Vec2 uc = Vec2::Zero(), vc = Vec2::Zero();
    for (std::size_t i = 0; i < v.size(); ++i) { uc += dy.x[i]; vc += v[i]; }
    uc /= static_cast<double>(v.size()); vc /= static_cast<double>(v.size());
    double t = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Vec2 a = dy.x[i] - uc, b = v[i] - vc;
      t += m * (a.x() * b.y() - a.y() * b.x());
    }
    return t;
  };
  if (s.track_advection_torque) adv_prev = advection_torque();
  auto track = [&] {
    if (!s.track_advection_torque) return;
    const double now = advection_torque();
    adv_int += 0.5 * s.dt * (adv_prev + now);
    adv_prev = now;
  };
  run_loop(s, r, *sim, [&] { double u = 0; for (double e : sim->state().e) u += m * e; return u; },
           [&] { sim->density(rho); return rho; }, [&] { r.advection_torque_integral.push_back(adv_int); }, track);
  if (gauss) {  // the multiplier of the last evaluation, recorded at the last sample only (diagnostic)
    r.gauss_beta.back() = sim->work().gauss_beta;
  }
  r.gauss_floor_hits = sim->work().gauss_floor_hits;
  r.reflections = sim->reflections();
  return r;
}

}  // namespace sph::scenes

namespace sph::scenes {

SpamOptions spam_options_from_label(const std::string& label) {
  SpamOptions o;
  std::vector<std::string> parts;
  std::size_t a = 0;
  while (a <= label.size()) {
    const std::size_t b = label.find('/', a);
    parts.push_back(label.substr(a, b == std::string::npos ? std::string::npos : b - a));
    if (b == std::string::npos) break;
    a = b + 1;
  }
  if (parts.size() < 2) throw std::invalid_argument("variant '" + label + "': need density/advection[/...]");
  o.density = spam_density_from_string(parts[0]);
  o.advection = spam_advection_from_string(parts[1]);
  for (std::size_t k = 2; k < parts.size(); ++k) {
    if (parts[k] == "chain") o.chain_rule = true;
    else if (parts[k] == "visc") o.viscosity = true;
    else if (parts[k] == "approach") o.closest_approach = true;
    else o.torque = spam_torque_from_string(parts[k]);
  }
  return o;
}

}  // namespace sph::scenes
