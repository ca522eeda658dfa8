#include "updated_lagrangian/gray_solver.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/fields.hpp"
#include "core/materials.hpp"
#include "core/predictor_corrector.hpp"

namespace sph {

GraySolver::GraySolver(ElasticBody& body, const GrayParameters& params, const GrayOptions& options)
    : body_(body), p_(params), o_(options), kernel_(2), h_(params.h_over_dp * body.dp), W_dp_(kernel_.W(body.dp, h_)),
      cells_(body.box, kernel_.support() * h_ + params.skin_over_h * h_) {
  if (!(h_ > 0) || !(body_.dp > 0) || !(p_.rho0 > 0) || !(p_.c0 > 0) || p_.mu < 0 || p_.skin_over_h < 0)
    throw std::invalid_argument("GraySolver: need h, dp, rho0, c0 > 0 and mu, skin >= 0");
  if (o_.artificial_stress && (p_.n_artificial < 0 || !(W_dp_ > 0)))
    throw std::invalid_argument("GraySolver: artificial stress needs n >= 0 and W(dp) > 0 (h/dp > 0.5)");
  if (body_.size() == 0) throw std::invalid_argument("GraySolver: empty body");
  if (o_.plasticity && !(p_.yield_stress > 0))
    throw std::invalid_argument("GraySolver: plasticity needs a yield stress > 0");
  if (body_.drive.size() != body_.size() || body_.motion.size() != body_.size())
    throw std::invalid_argument("GraySolver: body arrays of different lengths (add particles with ElasticBody::add)");
  evaluate_ = select_terms(o_, [](auto terms) -> Evaluate { return &evaluate_gray_rates<decltype(terms)>; });
  const std::size_t n = body_.size();
  resize_fields(r0_, n);
  resize_fields(r1_, n);
  pairs_.half = true;  // every pair once: pair_loop.hpp adds it to both particles
  rebuild_pairs();
}

void GraySolver::rebuild_pairs() {
  const double h = h_;
  pairs_.update(cells_, body_.x, kernel_.support() * h, p_.skin_over_h * h, kernel_.at(h));
}

const GraySolver::Rates& GraySolver::evaluate_now() {
  evaluate_(body_, p_, kernel_, h_, W_dp_, pairs_, scratch_, r0_);
  return r0_;
}

void GraySolver::step(double dt) {
  if (!(dt > 0)) throw std::invalid_argument("time step must be positive");
  check_state();  // catches a state corrupted from outside, naming its particle
  auto rates = [this](ElasticBody& body, Rates& r) { evaluate_(body, p_, kernel_, h_, W_dp_, pairs_, scratch_, r); };
  auto after_predict = [this](ElasticBody&) {
    if (o_.plasticity) return_to_yield_surface();
    check_state();  // before the cell list sees the predicted positions
    rebuild_pairs();
  };
  auto after_correct = [this](ElasticBody&) {
    if (o_.plasticity) return_to_yield_surface();
  };
  PredictorCorrector<ElasticBody, Rates>::step(body_, dt, r0_, r1_, rates, after_predict, after_correct);
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
  // Branch-free on plain arrays, so that the OR over the particles (first_bad_particle) vectorises (three checks a
  // step were 3% of a plate run): a value times zero is zero exactly when the value is finite (inf * 0 and
  // NaN * 0 are NaN), a NaN fails every comparison, and |v| > v_max is tested as |v|^2 > v_max^2 (the same
  // decision up to the rounding of the square root).
  const double* x = body_.x.data()->data();
  const double* v = body_.v.data()->data();
  const double* rho = body_.rho.data();
  const double* S = body_.S.data()->data();
  const double rho_min = 0.05 * p_.rho0, v_max = 100.0 * p_.c0, v_max2 = v_max * v_max;
  const std::size_t bad = first_bad_particle(body_.size(), [=](std::size_t a) {
    const double zero = 0.0 * x[2 * a] + 0.0 * x[2 * a + 1] + 0.0 * v[2 * a] + 0.0 * v[2 * a + 1] + 0.0 * rho[a] +
                        0.0 * S[4 * a] + 0.0 * S[4 * a + 1] + 0.0 * S[4 * a + 2] + 0.0 * S[4 * a + 3];
    const double v2 = v[2 * a] * v[2 * a] + v[2 * a + 1] * v[2 * a + 1];
    return !(zero == 0.0) | (rho[a] < rho_min) | (v2 > v_max2);
  });
  if (bad == body_.size()) return;
  std::ostringstream what;
  what << "|v| = " << body_.v[bad].norm() << ", rho = " << body_.rho[bad];
  throw_blow_up(steps_, time_, bad, body_.x[bad], what.str());
}

Tensor2 GraySolver::stress(std::size_t a) const {
  return body_.S[a] - linear_eos_pressure(body_.rho[a], p_.rho0, p_.c0) * Tensor2::Identity();
}

double GraySolver::elastic_energy() const {
  double e = 0;
  const double c2 = p_.c0 * p_.c0;
  for (std::size_t a = 0; a < body_.size(); ++a) {
    const double r = body_.rho[a];
    if (p_.mu > 0) e += body_.m[a] / r * shear_energy_density(p_.mu, body_.S[a]);
    e += body_.m[a] * c2 * (std::log(r / p_.rho0) + p_.rho0 / r - 1.0);
  }
  return e;
}

GraySolver::PowerBudget GraySolver::power_budget() const {
  const long n = static_cast<long>(body_.size());
  const auto& v = body_.v;
  const auto& m = body_.m;
  const auto& rho = body_.rho;
  std::vector<Tensor2> R(o_.artificial_stress ? n : 0), A(o_.xsph ? n : 0);
  for (std::size_t a = 0; a < R.size(); ++a) R[a] = artificial_stress(stress(a), rho[a], p_.eps_artificial);
  for (std::size_t a = 0; a < A.size(); ++a) A[a] = stress(a) / (rho[a] * rho[a]);
  // w = v - vhat = -eps_xsph (the XSPH sum (3.6)) at this state (zero without XSPH).
  std::vector<Vec2> w(o_.xsph ? n : 0, Vec2::Zero());
  if (o_.xsph) {
    for (long a = 0; a < n; ++a)
      for (std::uint32_t k = pairs_.first(a); k < pairs_.last(a); ++k) {
        const std::uint32_t b = pairs_.b[k];
        const Vec2 t = xsph_pair_term(v[a], v[b], pairs_.W[k], rho[a], rho[b]);
        w[a] += m[b] * t;
        w[b] -= m[a] * t;
      }
    for (auto& wa : w) wa *= -p_.eps_xsph;
  }
  const double eta2 = 0.01 * h_ * h_, inv_Wdp = 1.0 / W_dp_;
  double p_art = 0, p_visc = 0, p_xsph = 0;
#pragma omp parallel for reduction(+ : p_art, p_visc, p_xsph) schedule(static)
  for (long a = 0; a < n; ++a)
    for (std::uint32_t k = pairs_.first(a); k < pairs_.last(a); ++k) {  // every pair once: b > a
      const std::uint32_t b = pairs_.b[k];
      const Vec2 gW = pairs_.dx[k] * pairs_.F[k];
      const Vec2 vab = v[a] - v[b];
      const double mm = m[a] * m[b];  // the pair adds m_b M gW to a and -m_a M gW to b
      if (o_.artificial_stress) {
        const double fn = artificial_stress_fn(pairs_.W[k] * inv_Wdp, p_.n_artificial);
        p_art += mm * fn * vab.dot((R[a] + R[b]) * gW);
      }
      if (o_.viscosity) {
        const double vr = vab.dot(pairs_.dx[k]);
        if (vr < 0.0) {
          const double Pi = monaghan_pi(vr, pairs_.dx[k].squaredNorm(), h_, eta2, p_.alpha, p_.beta, p_.c0, rho[a], rho[b]);
          p_visc -= mm * Pi * vab.dot(gW);
        }
      }
      if (o_.xsph) p_xsph += mm * (w[a] - w[b]).dot((A[a] + A[b]) * gW);
    }
  return {p_art, p_visc, p_xsph};
}

}  // namespace sph
