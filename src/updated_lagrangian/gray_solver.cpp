#include "updated_lagrangian/gray_solver.hpp"

#include <cmath>
#include <sstream>

#include "updated_lagrangian/artificial_stress.hpp"
#include "core/materials.hpp"

namespace sph {

/// Compile-time selection of the terms of the pair loop.
template <bool ArtificialStress, bool Xsph, bool Viscosity, bool Summation>
struct GrayTerms {
  static constexpr bool artificial_stress = ArtificialStress;
  static constexpr bool xsph = Xsph;
  static constexpr bool viscosity = Viscosity;
  static constexpr bool summation = Summation;
};

std::string GrayOptions::describe() const {
  std::ostringstream s;
  s << (artificial_stress ? "artstress" : "noartstress") << (xsph ? "+xsph" : "") << (viscosity ? "+visc" : "")
    << (summation_density ? "+sumdensity" : "+continuity") << (plasticity ? "+vonmises" : "");
  return s.str();
}

double GrayParameters::longitudinal_speed() const { return std::sqrt(c0 * c0 + 4.0 * mu / (3.0 * rho0)); }

double gray_time_step(const GrayParameters& p, double cfl, double max_speed) {
  if (!(cfl > 0)) throw std::invalid_argument("time-step factor must be positive");
  return cfl * p.h / (p.longitudinal_speed() + max_speed);
}

namespace {

double ipow(double x, int n) {
  double r = 1.0;
  for (int i = 0; i < n; ++i) r *= x;
  return r;
}

// The one place where the run-time options become a compile-time instance of the pair loop.
template <class F>
auto select_terms(const GrayOptions& o, F&& f) {
  auto with_sum = [&](auto as, auto xs, auto av) {
    return o.summation_density ? f(GrayTerms<decltype(as)::value, decltype(xs)::value, decltype(av)::value, true>{})
                               : f(GrayTerms<decltype(as)::value, decltype(xs)::value, decltype(av)::value, false>{});
  };
  auto with_av = [&](auto as, auto xs) {
    return o.viscosity ? with_sum(as, xs, std::true_type{}) : with_sum(as, xs, std::false_type{});
  };
  auto with_xs = [&](auto as) { return o.xsph ? with_av(as, std::true_type{}) : with_av(as, std::false_type{}); };
  return o.artificial_stress ? with_xs(std::true_type{}) : with_xs(std::false_type{});
}

}  // namespace

GraySolver::GraySolver(ElasticBody& body, const GrayParameters& params, const GrayOptions& options)
    : body_(body), p_(params), o_(options), kernel_(2), W_dp_(kernel_.W(params.dp, params.h)),
      cells_(params.box, kernel_.support() * params.h + params.skin()) {
  if (!(p_.h > 0) || !(p_.dp > 0) || !(p_.rho0 > 0) || !(p_.c0 > 0) || p_.mu < 0 || p_.skin_over_h < 0)
    throw std::invalid_argument("GraySolver: need h, dp, rho0, c0 > 0 and mu, skin >= 0");
  if (o_.artificial_stress && (p_.n_artificial < 0 || !(W_dp_ > 0)))
    throw std::invalid_argument("GraySolver: artificial stress needs n >= 0 and W(dp) > 0 (h/dp > 0.5)");
  if (body_.size() == 0) throw std::invalid_argument("GraySolver: empty body");
  if (o_.plasticity && !(p_.yield_stress > 0))
    throw std::invalid_argument("GraySolver: plasticity needs a yield stress > 0");
  if (body_.drive.size() != body_.size() || body_.motion.size() != body_.size())
    throw std::invalid_argument("GraySolver: body arrays of different lengths (add particles with ElasticBody::add)");
  evaluate_ = select_terms(o_, [](auto terms) { return &GraySolver::evaluate<decltype(terms)>; });
  const std::size_t n = body_.size();
  for (Rates* r : {&r0_, &r1_}) {
    r->dv.assign(n, Vec2::Zero());
    r->vhat.assign(n, Vec2::Zero());
    r->drho.assign(n, 0.0);
    r->dS.assign(n, Tensor2::Zero());
  }
  sigma_over_rho2_.assign(n, Tensor2::Zero());
  if (o_.artificial_stress) R_.assign(n, Tensor2::Zero());
  if (o_.summation_density) rho_sum_.assign(n, 0.0);
  v0_.resize(n);
  rho0_.resize(n);
  S0_.resize(n);
  rebuild_pairs();
}

void GraySolver::rebuild_pairs() { pairs_.update(cells_, body_.x, kernel_, p_.h, p_.skin()); }

template <class Terms>
void GraySolver::evaluate(Rates& out) {
  const std::size_t n = body_.size();
  const auto& x = body_.x;
  const auto& v = body_.v;
  const auto& m = body_.m;
  auto& rho = body_.rho;
  const auto& S = body_.S;
  const auto& start = pairs_.start;
  const auto& nb = pairs_.b;
  const auto& dx = pairs_.dx;
  const auto& Wab = pairs_.W;
  const auto& Fab = pairs_.F;
  (void)x;

  // Pass 1 (only if a term needs it): XSPH velocity (3.6) and summation density, from the densities
  // of the previous evaluation.
  if constexpr (Terms::xsph || Terms::summation) {
#pragma omp parallel for schedule(static)
    for (std::size_t a = 0; a < n; ++a) {
      Vec2 dv_avg = Vec2::Zero();
      double rs = 0.0;
      for (std::uint32_t k = start[a]; k < start[a + 1]; ++k) {
        const std::uint32_t b = nb[k];
        if constexpr (Terms::xsph) dv_avg += m[b] / (0.5 * (rho[a] + rho[b])) * (v[b] - v[a]) * Wab[k];
        if constexpr (Terms::summation) rs += m[b] * Wab[k];
      }
      out.vhat[a] = Terms::xsph ? Vec2(v[a] + p_.eps_xsph * dv_avg) : v[a];
      if constexpr (Terms::summation) rho_sum_[a] = rs + m[a] * kernel_.W(0.0, p_.h);
    }
    if constexpr (Terms::summation) rho = rho_sum_;
  }
  const std::vector<Vec2>& vhat = Terms::xsph ? out.vhat : v;

  // Per-particle stress terms: sigma/rho^2 and the artificial stress R (6.1)-(6.7).
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    const Tensor2 sigma = S[a] - linear_eos_pressure(rho[a], p_.rho0, p_.c0) * Tensor2::Identity();
    sigma_over_rho2_[a] = sigma / (rho[a] * rho[a]);
    if constexpr (Terms::artificial_stress) R_[a] = artificial_stress(sigma, rho[a], p_.eps_artificial);
  }

  // Pass 2: acceleration (3.1)/(3.12), continuity (3.8), velocity gradient (3.10), stress rate (2.3).
  const double h = p_.h, eta2 = 0.01 * h * h, inv_Wdp = 1.0 / W_dp_;
  const int nart = p_.n_artificial;
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    Vec2 acc = Vec2::Zero();
    double drho = 0.0;
    Tensor2 grad_v = Tensor2::Zero();  // grad_v(i, j) = d vhat_i / d x_j
    const Tensor2 Aa = sigma_over_rho2_[a];
    for (std::uint32_t k = start[a]; k < start[a + 1]; ++k) {
      const std::uint32_t b = nb[k];
      const Vec2 gW = dx[k] * Fab[k];  // grad_a W_ab (3.2)
      Tensor2 M = Aa + sigma_over_rho2_[b];
      if constexpr (Terms::artificial_stress) M += (R_[a] + R_[b]) * ipow(Wab[k] * inv_Wdp, nart);
      if constexpr (Terms::viscosity) {
        const double vr = (v[a] - v[b]).dot(dx[k]);
        if (vr < 0.0) {
          // Monaghan's Pi_ab >= 0 acts as a pressure, so it enters the stress sum with a minus sign.
          const double mu_ab = h * vr / (dx[k].squaredNorm() + eta2);
          const double Pi = (-p_.alpha * p_.c0 * mu_ab + p_.beta * mu_ab * mu_ab) / (0.5 * (rho[a] + rho[b]));
          M.diagonal().array() -= Pi;
        }
      }
      acc += m[b] * (M * gW);
      const Vec2 vab = vhat[a] - vhat[b];
      if constexpr (!Terms::summation) drho += m[b] * vab.dot(gW);
      grad_v.noalias() -= (m[b] / rho[b]) * vab * gW.transpose();
    }
    const Motion kind = body_.motion[a];
    out.dv[a] = kind == Motion::Free ? acc : kind == Motion::Driven ? body_.drive[a] : Vec2::Zero();
    out.drho[a] = Terms::summation ? 0.0 : drho;
    out.dS[a] = hooke_deviatoric_rate(p_.mu, grad_v, S[a]);
    if constexpr (!Terms::xsph) out.vhat[a] = v[a];
  }
}

const GraySolver::Rates& GraySolver::evaluate_now() {
  (this->*evaluate_)(r0_);
  return r0_;
}

void GraySolver::step(double dt) {
  if (!(dt > 0)) throw std::invalid_argument("time step must be positive");
  auto& x = body_.x;
  auto& v = body_.v;
  auto& rho = body_.rho;
  auto& S = body_.S;
  const std::size_t n = body_.size();

  check_state();           // catches a state corrupted from outside, naming its particle
  (this->*evaluate_)(r0_);  // F^0, D^0 at the start of the step
  const double half_dt2 = 0.5 * dt * dt;
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {  // predictor (6.14)-(6.16); positions are final (6.15)
    v0_[a] = v[a];
    rho0_[a] = rho[a];
    S0_[a] = S[a];
    if (body_.motion[a] == Motion::Free) {
      x[a] += dt * r0_.vhat[a] + half_dt2 * r0_.dv[a];
      v[a] += dt * r0_.dv[a];
    } else if (body_.motion[a] == Motion::Driven) {  // exact for a constant acceleration; the corrector
      x[a] += dt * v[a] + half_dt2 * r0_.dv[a];       // adds dt/2 (drive - drive) = 0 to v
      v[a] += dt * r0_.dv[a];
    }
    rho[a] += dt * r0_.drho[a];
    S[a] += dt * r0_.dS[a];
  }
  if (o_.plasticity) return_to_yield_surface();
  check_state();  // before the cell list sees the predicted positions
  rebuild_pairs();
  (this->*evaluate_)(r1_);  // F, D at the predicted state
  const double half_dt = 0.5 * dt;
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < n; ++a) {  // corrector (6.17)-(6.18)
    v[a] += half_dt * (r1_.dv[a] - r0_.dv[a]);
    if (!o_.summation_density) rho[a] += half_dt * (r1_.drho[a] - r0_.drho[a]);
    S[a] += half_dt * (r1_.dS[a] - r0_.dS[a]);
  }
  if (o_.plasticity) return_to_yield_surface();
  time_ += dt;
  ++steps_;
  check_state();
}

void GraySolver::return_to_yield_surface() {
  auto& S = body_.S;
  const double Y = p_.yield_stress;
#pragma omp parallel for schedule(static)
  for (std::size_t a = 0; a < S.size(); ++a) S[a] = von_mises_return(S[a], Y);
}

void GraySolver::check_state() const {
  const std::size_t n = body_.size();
  std::size_t bad = n;
#pragma omp parallel for reduction(min : bad) schedule(static)
  for (std::size_t a = 0; a < n; ++a) {
    const bool finite = body_.x[a].allFinite() && body_.v[a].allFinite() && std::isfinite(body_.rho[a]) &&
                        body_.S[a].allFinite();
    if (!finite || body_.rho[a] < 0.05 * p_.rho0 || body_.v[a].norm() > 100.0 * p_.c0) bad = std::min(bad, a);
  }
  if (bad == n) return;
  std::ostringstream msg;
  msg << "blow-up at step " << steps_ << ", t = " << time_ << ", particle " << bad << " at (" << body_.x[bad].x()
      << ", " << body_.x[bad].y() << "): |v| = " << body_.v[bad].norm() << ", rho = " << body_.rho[bad];
  throw BlowUp(msg.str());
}

Tensor2 GraySolver::stress(std::size_t a) const {
  return body_.S[a] - linear_eos_pressure(body_.rho[a], p_.rho0, p_.c0) * Tensor2::Identity();
}

double GraySolver::kinetic_energy() const {
  double e = 0;
  for (std::size_t a = 0; a < body_.size(); ++a) e += 0.5 * body_.m[a] * body_.v[a].squaredNorm();
  return e;
}

double GraySolver::elastic_energy() const {
  double e = 0;
  const double c2 = p_.c0 * p_.c0;
  for (std::size_t a = 0; a < body_.size(); ++a) {
    const double r = body_.rho[a];
    if (p_.mu > 0) e += body_.m[a] / r * body_.S[a].squaredNorm() / (4.0 * p_.mu);
    e += body_.m[a] * c2 * (std::log(r / p_.rho0) + p_.rho0 / r - 1.0);
  }
  return e;
}

Vec2 GraySolver::linear_momentum() const {
  Vec2 p = Vec2::Zero();
  for (std::size_t a = 0; a < body_.size(); ++a) p += body_.m[a] * body_.v[a];
  return p;
}

double GraySolver::angular_momentum() const {
  double L = 0;
  for (std::size_t a = 0; a < body_.size(); ++a)
    L += body_.m[a] * (body_.x[a].x() * body_.v[a].y() - body_.x[a].y() * body_.v[a].x());
  return L;
}

}  // namespace sph
