// Review excerpt, Section 5.9 (eq 5.59), with Ismail 2009 Section 4.7.1 (eq 4.48): Swegle's criterion
// W'' sigma > 0 as a stability map of each cover function of src/core/kernels.hpp: the sign of W'' against
// r/h, hence which stress sign (tension sigma > 0, compression sigma < 0) makes a neighbour at that
// distance unstable; typical neighbour distances marked.
//
// Sign convention. Both texts take sigma > 0 in tension. Ismail (4.48) calls W'' sigma > 0 "the criterion
// for onset of the instability" and W'' > 0 "the tensile instability range". The excerpt prints "the
// criterion for STABILITY was that W'' sigma > 0" -- literally the opposite. This driver settles the sign
// without either text: the 1D SPH momentum equation with a uniform, constant stress sigma (Ismail's
// total-Lagrangian form; rho, m fixed),
//     dv_i/dt = sum_j m (2 sigma / rho^2) dW(|x_i - x_j|)/dx_i,
// gives for one pair at separation r the relative acceleration  r'' = (4 m sigma / rho^2) W'(r), so a
// small change of r grows like exp(lambda t) with lambda^2 = (4 m sigma / rho^2) W''(r): unstable iff
// W'' sigma > 0. lambda^2 is measured here by central differences of the NONLINEAR force (W' only, never
// W''), for both stress signs at every sample: Ismail's reading holds, the excerpt's wording does not.
// For the alternating (k = pi/dp) mode of an infinite chain the same gives
//     lambda^2 = (8 m sigma / rho^2) sum_{n odd} W''(n dp)
// (only odd separations move relative to each other); measured the same way on a periodic chain.
//
// Parameters (source):
//   kernels       src/core/kernels.hpp, 1D, h = 1 (the map is in r/h)
//   h/dp cubic    1.0 (Gray et al. 2001 Section 5.3, the dispersion analysis) and 1.5 (Section 6, "We take
//                 h/dp to be 1.5"): support 2h
//   h/dp Ismail   1.5 and 5.5 (thesis Section 2.7: 1.5 is best for square waves, 5.5 "a good compromise"):
//                 support h; used for every support-1 function (Lucy, mollifiers)
//   sigma, rho, m CHOSEN 1, 1, rho dp (units; only signs matter)
//   delta         CHOSEN 1e-6 (finite-difference step of the linearisation, relative O(delta^2) error)
//   samples       CHOSEN 2001 points per map (the plot; the inflections are found by bisection)
#include <cmath>
#include <string>
#include <vector>

#include "frame/driver.hpp"
#include "core/kernels.hpp"

namespace {

// First sign change of d2w on (0, support) (NaN: none).
template <class Shape>
double inflection(int scan) {
  const auto roots = sph::second_derivative_sign_changes<Shape>(scan);
  return roots.empty() ? NAN : roots.front();
}

const char* unstable_under(double w2) { return w2 > 0 ? "tension" : w2 < 0 ? "compression" : "marginal"; }

// Units of the map (only signs matter): rho = dp = 1, m = rho dp.
constexpr double rho = 1.0, dp = 1.0, m = rho * dp;

struct Params {
  int samples = 2001, scan = 4000, chain = 64;
  double delta = 1e-6, sigma = 1.0;
  std::vector<double> gray_h{1.0, 1.5}, ismail_h{1.5, 5.5};
};

void declare(sph::Driver& d, Params& p) {
  d.param("samples", p.samples, "points of each map over the support (plot)").positive().quick(201);
  d.param("scan", p.scan, "scan steps before bisecting the inflection of W''").positive().quick(400);
  d.param("delta", p.delta, "finite-difference displacement (units of dp) of the linearisation").positive();
  d.param("sigma", p.sigma, "magnitude of the uniform stress (units of rho c^2; only the sign matters)");
  d.param("chain", p.chain, "particles of the periodic chain for the alternating-mode check (even)").positive();
  d.param("gray-h-over-dp", p.gray_h, "h/dp marked for the cubic spline (Gray et al. 2001: 1 and 1.5)").expected(1, 20).positive();
  d.param("ismail-h-over-dp", p.ismail_h, "h/dp marked for the support-1 functions (Ismail 2009: 1.5 and 5.5)").expected(1, 20).positive();
}

void check(const Params& p) {
  if (p.samples < 3 || p.scan < 10 || !(p.delta > 0 && p.delta < 1e-2) || !(p.sigma > 0) || p.chain < 8 || p.chain % 2)
    throw std::invalid_argument("need samples >= 3, scan >= 10, 0 < delta < 1e-2, sigma > 0, even chain >= 8");
  for (double x : p.gray_h) if (!(x > 0)) throw std::invalid_argument("h/dp must be positive");
  for (double x : p.ismail_h) if (!(x > 0)) throw std::invalid_argument("h/dp must be positive");
}

// The three tables, and the tallies over every kernel for the verdict.
struct Tables {
  sph::CsvWriter map, nbr, chains;
  int agree = 0, disagree = 0;
  double max_rel = 0.0, chain_max_rel = 0.0;
};

Tables open_tables(const sph::Driver& d) {
  return {d.csv("map.csv", {"kernel", "q", "W", "dWdr", "d2Wdr2", "unstable_under", "lambda2_pair_tension",
                            "lambda2_pair_compression"}),
          d.csv("neighbours.csv", {"kernel", "source", "h_over_dp", "n", "q", "d2Wdr2", "d2Wdr2_h3", "unstable_under"}),
          d.csv("chain_alternating_mode.csv",
                {"kernel", "source", "h_over_dp", "sum_odd_d2W", "lambda2_tension_predicted",
                 "lambda2_tension_measured", "lambda2_compression_measured", "unstable_under"})};
}

// The map of one kernel against r/h (h = 1), each sample's W'' sign checked against the measured pair growth.
template <class Shape>
void map_kernel(sph::Driver& d, const Params& p, Tables& t) {
  const std::string name = Shape::name;
  const double R = Shape::support;
  const sph::Kernel<Shape> K(1);
  const double h = 1.0;
  // Pair growth rate from the nonlinear pair force r'' = (4 m s / rho^2) W'(r), central differences.
  auto lambda2_pair = [&](double r, double s) {
    auto acc = [&](double rr) { return 4.0 * m * s / (rho * rho) * K.dWdr(rr, h); };
    return (acc(r + p.delta) - acc(r - p.delta)) / (2.0 * p.delta);
  };
  for (int i = 1; i < p.samples - 1; ++i) {
    const double q = R * i / (p.samples - 1);
    const double w2 = K.d2Wdr2(q, h);
    const double lt = lambda2_pair(q, p.sigma), lc = lambda2_pair(q, -p.sigma);
    t.map.row(name, q, K.W(q, h), K.dWdr(q, h), w2, unstable_under(w2), lt, lc);
    // Stay clear of kinks (cubic at q = 1) and of the inflection itself for the sign comparison.
    const double pred = 4.0 * m * p.sigma / (rho * rho) * w2;
    if (std::abs(q - 1.0) < 10 * p.delta || std::abs(pred) < 1e-6 * 4.0 * m * p.sigma) continue;
    t.max_rel = std::max(t.max_rel, std::abs(lt - pred) / std::abs(pred));
    // Criterion "W'' sigma > 0 is unstable": tension grows iff W'' > 0, compression grows iff W'' < 0.
    const bool ok = ((lt > 0) == (w2 > 0)) && ((lc > 0) == (w2 < 0));
    (ok ? t.agree : t.disagree) += 1;
  }
  const double qi = inflection<Shape>(p.scan);
  d.value("q_inflection_" + name, qi, "r/h where W'' changes sign: tension-unstable beyond, compression-unstable inside");
  d.value("tension_unstable_share_1d_" + name, (R - qi) / R, "1D share of the support where tension is unstable");
}

// Alternating mode on a periodic chain: displacements u_i = (-1)^i eps, the acceleration a_0 of particle 0 from
// the full nonlinear constant-stress momentum equation (minimum-image distances) under stress s.
template <class Shape>
double chain_accel0(const sph::Kernel<Shape>& K, const Params& p, double hh, double hdp, double eps, double s) {
  const double R = Shape::support;
  const int N = p.chain;
  const double L = N * dp;
  if (R * hh >= 0.5 * L) throw std::invalid_argument("chain too short for h/dp = " + sph::format_number(hdp));
  double a = 0.0;
  const double x0 = eps;
  for (int j = 1; j < N; ++j) {
    double dx = x0 - (j * dp + ((j % 2) ? -eps : eps));
    dx -= L * std::round(dx / L);
    const double r = std::abs(dx);
    a += m * 2.0 * s / (rho * rho) * K.dWdr(r, hh) * (dx > 0 ? 1.0 : -1.0);
  }
  return a;
}

// The lattice neighbours n dp of one kernel at h/dp = hdp, and the growth of the chain's alternating mode.
template <class Shape>
void mark_neighbours(sph::Driver& d, const Params& p, Tables& t, double hdp, const std::string& source) {
  const std::string name = Shape::name;
  const double R = Shape::support;
  const sph::Kernel<Shape> K(1);
  const double hh = hdp * dp;  // h in units of dp
  const std::string tagh = name + "_h" + sph::format_number(hdp);
  double sum_odd = 0.0, sum_abs = 0.0;  // sum_abs over all neighbours: the error scale
  int n_tension = 0, n_total = 0;
  for (int n = 1; n * dp < R * hh; ++n) {
    const double q = n * dp / hh, w2 = K.d2Wdr2(n * dp, hh);
    t.nbr.row(name, source, hdp, n, q, w2, w2 * hh * hh * hh, unstable_under(w2));
    if (n % 2) sum_odd += w2;
    sum_abs += std::abs(w2);
    ++n_total;
    n_tension += (w2 > 0);
    if (n == 1) {
      d.value("nn_q_" + tagh, q, "nearest neighbour's r/h = dp/h");
      d.value("nn_d2W_" + tagh, w2 * hh * hh * hh, "W''(dp) h^3 (dimensionless, 1D sigma included): its sign says which stress is unstable");
    }
  }
  d.value("tension_unstable_neighbour_share_" + tagh, n_total ? double(n_tension) / n_total : NAN,
          "share of the lattice neighbours n dp < support with W'' > 0");
  // The alternating mode's growth measured as a_0 / u_0 by central differences.
  const double eps = p.delta * dp, sigma = p.sigma;
  const double lt = (chain_accel0(K, p, hh, hdp, eps, sigma) - chain_accel0(K, p, hh, hdp, -eps, sigma)) / (2.0 * eps);
  const double lc = (chain_accel0(K, p, hh, hdp, eps, -sigma) - chain_accel0(K, p, hh, hdp, -eps, -sigma)) / (2.0 * eps);
  const double pred = 8.0 * m * sigma / (rho * rho) * sum_odd;
  t.chain_max_rel = std::max(t.chain_max_rel, std::abs(lt - pred) / (8.0 * m * sigma / (rho * rho) * sum_abs));
  t.chains.row(name, source, hdp, sum_odd, pred, lt, lc, unstable_under(sum_odd));
  d.value("chain_lambda2_tension_" + tagh, lt, "alternating-mode lambda^2 under tension, measured (m = rho = dp = sigma = 1)");
  d.value("chain_lambda2_tension_predicted_" + tagh, pred, "8 m sigma / rho^2 sum_{n odd} W''(n dp)");
}

template <class Shape>
void one_kernel(sph::Driver& d, const Params& p, Tables& t, const std::vector<double>& hs, const std::string& source) {
  map_kernel<Shape>(d, p, t);
  for (double hdp : hs) mark_neighbours<Shape>(d, p, t, hdp, source);
}

}  // namespace

int main(int argc, char** argv) {
  sph::Driver d("review_swegle_stability_map", "R",
                "Swegle's criterion W'' sigma > 0 (review eq 5.59, Ismail eq 4.48): stability map of each cover "
                "function against r/h, verified by linearising the 1D SPH constant-stress momentum equation");
  Params p;
  declare(d, p);

  return d.run(argc, argv, [&] {
    check(p);
    Tables t = open_tables(d);
    one_kernel<sph::CubicSplineShape>(d, p, t, p.gray_h, "Gray2001");
    one_kernel<sph::LucyShape>(d, p, t, p.ismail_h, "Ismail2009");
    // The Gaussian is marked at Ismail's h/dp: at h = dp its third neighbour would sit exactly on the
    // truncation radius 3h, where the truncated kernel's W' jumps (a spurious, delta-like W'').
    one_kernel<sph::GaussianShape>(d, p, t, p.ismail_h, "Ismail2009");
    one_kernel<sph::MollifierShape>(d, p, t, p.ismail_h, "Ismail2009");
    one_kernel<sph::ModifiedMollifierShape>(d, p, t, p.ismail_h, "Ismail2009");

    // 1 when every sample agrees that W'' sigma > 0 grows (Ismail 4.48), 0 when every sample says it is
    // stable (the excerpt's wording read literally), in between when mixed.
    const double unstable = double(t.agree) / (t.agree + t.disagree);
    d.value("W2sigma_positive_is_unstable", unstable, "share of map samples where the measured pair growth agrees with 'W'' sigma > 0 unstable'");
    d.value("W2sigma_positive_is_stable", 1.0 - unstable, "the same for the literal reading 'W'' sigma > 0 is the stability criterion'");
    d.value("chain_lambda2_max_rel_error", t.chain_max_rel,
            "alternating mode: |measured - 8 m sigma/rho^2 sum_odd W''| / (8 m sigma/rho^2 sum_n |W''|), all cases");
    d.value("pair_lambda2_max_rel_error", t.max_rel, "finite-difference pair lambda^2 against (4 m sigma / rho^2) W'' (library d2W)");
  });
}
