// Cover functions (SPH kernels) in 1, 2 and 3 dimensions.
//
// A kernel is W(r, h) = sigma_d / h^d * w(q), q = r / h, with w the dimensionless shape and sigma_d
// the normalisation in d dimensions. Each shape gives w, dw/dq and d2w/dq2; Kernel<Shape> turns them
// into W, dW/dr and d2W/dr2. The normalisation is a member computed once when the kernel is built
// (closed form where the papers give one, GSL quadrature otherwise): no static state.
//
// Support radii are in units of h: 2 for the cubic B-spline (Monaghan's convention, Gray et al. 2001
// eqs 3.3-3.4, Ismail 2009 eq 2.14), 1 for Lucy and the mollifiers (Ismail 2009 eqs 2.13, 2.17, 2.19).
#pragma once

#include <cmath>
#include <stdexcept>
#if defined(__AVX512F__) && defined(__AVX512VL__)
#include <immintrin.h>
#endif
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace sph {

/// Surface measure of the unit sphere in d dimensions: 2, 2 pi, 4 pi.
double unit_sphere_measure(int dim);

/// sigma_d = 1 / (S_d * integral_0^R w(q) q^(d-1) dq), by adaptive GSL quadrature (QAG, 1e-13).
/// Used for the kernels without a closed-form integral, and by the tests to check the closed forms.
template <class Shape>
double numerical_normalisation(int dim);

/// Monaghan's cubic B-spline. Ismail 2009 eq (2.14); Gray et al. 2001 eqs (3.3)-(3.4) in 2D.
/// Closed-form sigma: 2/3 (1D), 10/(7 pi) (2D), 1/pi (3D).
struct CubicSplineShape {
  static constexpr const char* name = "cubic_spline";
  static constexpr double support = 2.0;
  static double w(double q) {
    if (q < 1.0) return 1.0 - 1.5 * q * q + 0.75 * q * q * q;
    if (q < 2.0) { const double t = 2.0 - q; return 0.25 * t * t * t; }
    return 0.0;
  }
  static double dw(double q) {
    if (q < 1.0) return -3.0 * q + 2.25 * q * q;
    if (q < 2.0) { const double t = 2.0 - q; return -0.75 * t * t; }
    return 0.0;
  }
  /// dw(q) / q without the division where the polynomial allows (q < 1); the pair-list refreshes' F.
  static double dw_over_q(double q) {
    if (q < 1.0) return -3.0 + 2.25 * q;
    if (q < 2.0) { const double t = 2.0 - q; return -0.75 * t * t / q; }
    return 0.0;
  }
  static double d2w(double q) {
    if (q < 1.0) return -3.0 + 4.5 * q;
    if (q < 2.0) return 1.5 * (2.0 - q);
    return 0.0;
  }
#if defined(__AVX512F__) && defined(__AVX512VL__)
  /// w(q) and dw_over_q(q) for eight q at once, the same bits as the scalar forms: the same operations in
  /// the same order, with a multiply and an add fused exactly where GCC fuses them in the scalar forms
  /// (-ffp-contract=fast; tests/test_kernels.cpp compares the two bit for bit).
  static void w_and_dw_over_q8(__m512d q, __m512d& w, __m512d& dw_over_q) {
    const __mmask8 inner = _mm512_cmp_pd_mask(q, _mm512_set1_pd(1.0), _CMP_LT_OQ);
    const __mmask8 outer = _mm512_cmp_pd_mask(q, _mm512_set1_pd(2.0), _CMP_LT_OQ) & ~inner;
    // q < 1: 1 - 1.5 q q + 0.75 q q q and -3 + 2.25 q
    const __m512d w1 = _mm512_fmadd_pd(_mm512_mul_pd(_mm512_mul_pd(q, _mm512_set1_pd(0.75)), q), q,
                                       _mm512_fnmadd_pd(_mm512_mul_pd(q, _mm512_set1_pd(1.5)), q, _mm512_set1_pd(1.0)));
    const __m512d d1 = _mm512_fmadd_pd(q, _mm512_set1_pd(2.25), _mm512_set1_pd(-3.0));
    // 1 <= q < 2: t = 2 - q, 0.25 t t t and -0.75 t t / q
    const __m512d t = _mm512_sub_pd(_mm512_set1_pd(2.0), q);
    const __m512d w2 = _mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(t, _mm512_set1_pd(0.25)), t), t);
    const __m512d d2 = _mm512_maskz_div_pd(outer, _mm512_mul_pd(_mm512_mul_pd(t, _mm512_set1_pd(-0.75)), t), q);
    w = _mm512_mask_blend_pd(inner, _mm512_maskz_mov_pd(outer, w2), w1);  // beyond: +0, as the scalar 0.0
    dw_over_q = _mm512_mask_blend_pd(inner, d2, d1);
  }
#endif
  static double normalisation(int dim);
};

/// Lucy's quartic, w = (1 + 3q)(1 - q)^3. Ismail 2009 eq (2.13); Hoover et al. 2004 (h = 3).
/// Closed-form sigma: 5/4 (1D), 5/pi (2D), 105/(16 pi) (3D).
struct LucyShape {
  static constexpr const char* name = "lucy";
  static constexpr double support = 1.0;
  static double w(double q) {
    if (q >= 1.0) return 0.0;
    const double t = 1.0 - q;
    return (1.0 + 3.0 * q) * t * t * t;
  }
  static double dw(double q) {  // -12 q (1 - q)^2
    if (q >= 1.0) return 0.0;
    const double t = 1.0 - q;
    return -12.0 * q * t * t;
  }
  static double dw_over_q(double q) {  // -12 (1 - q)^2: no division
    if (q >= 1.0) return 0.0;
    const double t = 1.0 - q;
    return -12.0 * t * t;
  }
  static double d2w(double q) {  // -12 (1 - q)(1 - 3q)
    if (q >= 1.0) return 0.0;
    return -12.0 * (1.0 - q) * (1.0 - 3.0 * q);
  }
#if defined(__AVX512F__) && defined(__AVX512VL__)
  /// w(q) and dw_over_q(q) for eight q at once, the same bits as the scalar forms (see CubicSplineShape):
  /// 1 + 3q fused as GCC fuses it.
  static void w_and_dw_over_q8(__m512d q, __m512d& w, __m512d& dw_over_q) {
    const __mmask8 inside = _mm512_cmp_pd_mask(q, _mm512_set1_pd(1.0), _CMP_LT_OQ);
    const __m512d t = _mm512_sub_pd(_mm512_set1_pd(1.0), q);
    const __m512d a = _mm512_fmadd_pd(q, _mm512_set1_pd(3.0), _mm512_set1_pd(1.0));
    w = _mm512_maskz_mov_pd(inside, _mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(a, t), t), t));
    dw_over_q = _mm512_maskz_mov_pd(inside, _mm512_mul_pd(_mm512_mul_pd(t, _mm512_set1_pd(-12.0)), t));
  }
#endif
  static double normalisation(int dim);
};

/// Gaussian exp(-q^2), Ismail 2009 eq (2.15), TRUNCATED at q = 3 so that it has compact support.
/// The missing tail (a mass fraction of about 1e-4 in 1D) is restored by normalising the truncated
/// function numerically, so sum-to-one holds exactly; the function is discontinuous at q = 3 by
/// exp(-9) ~ 1.2e-4 of its peak. The thesis's closed-form constants (1/sqrt(3) in 1D as printed,
/// 1/pi, pi^(-3/2)) refer to the untruncated function and are checked separately (I-kern).
/// The jump also puts a delta in w'': avoid h/dp such that a neighbour sits exactly at q = 3.
struct GaussianShape {
  static constexpr const char* name = "gaussian";
  static constexpr double support = 3.0;
  static double w(double q) { return q < support ? std::exp(-q * q) : 0.0; }
  static double dw(double q) { return q < support ? -2.0 * q * std::exp(-q * q) : 0.0; }
  static double d2w(double q) { return q < support ? (4.0 * q * q - 2.0) * std::exp(-q * q) : 0.0; }
  static double normalisation(int dim) { return numerical_normalisation<GaussianShape>(dim); }
};

/// Classical mollifier exp(-1/(1 - q^2)), Ismail 2009 eq (2.17); C-infinity with support 1.
/// No closed-form integral: normalised numerically. Both mollifiers underflow to exactly 0 in double
/// precision for q > ~0.9993 (exp(-1/(1-q^2)) < 1e-308), so w, w', w'' are 0 there: a sign scan of w''
/// must treat exact zeros as "no sign", not as a sign change.
struct MollifierShape {
  static constexpr const char* name = "mollifier";
  static constexpr double support = 1.0;
  static double w(double q) {
    if (q >= 1.0) return 0.0;
    return std::exp(-1.0 / (1.0 - q * q));
  }
  // With s = 1 - q^2: w = exp(-1/s), dw/dq = w * (-2q/s^2),
  // d2w/dq2 = w * [4q^2/s^4 - 2/s^2 - 8q^2/s^3].
  static double dw(double q) {
    if (q >= 1.0) return 0.0;
    const double s = 1.0 - q * q;
    return w(q) * (-2.0 * q / (s * s));
  }
  static double d2w(double q) {
    if (q >= 1.0) return 0.0;
    const double s = 1.0 - q * q, s2 = s * s;
    return w(q) * (4.0 * q * q / (s2 * s2) - 2.0 / s2 - 8.0 * q * q / (s2 * s));
  }
  static double normalisation(int dim) { return numerical_normalisation<MollifierShape>(dim); }
};

/// Ismail's modified mollifier exp(-1/(1 - q^2)) (1 - q^2)^8, Ismail 2009 eq (2.19); C-infinity,
/// support 1, close in shape to a Gaussian (Fig 2.7). Normalised numerically.
struct ModifiedMollifierShape {
  static constexpr const char* name = "modified_mollifier";
  static constexpr double support = 1.0;
  // ln w = -1/s + 8 ln s with s = 1 - q^2, so w' = w * g, w'' = w * (g^2 + g') with
  // g = d(ln w)/dq = -2q/s^2 - 16q/s.
  static double w(double q) {
    if (q >= 1.0) return 0.0;
    const double s = 1.0 - q * q, s2 = s * s, s4 = s2 * s2;
    return std::exp(-1.0 / s) * s4 * s4;
  }
  static double dw(double q) {
    if (q >= 1.0) return 0.0;
    const double s = 1.0 - q * q;
    return w(q) * (-2.0 * q / (s * s) - 16.0 * q / s);
  }
  static double d2w(double q) {
    if (q >= 1.0) return 0.0;
    const double s = 1.0 - q * q, s2 = s * s;
    const double g = -2.0 * q / s2 - 16.0 * q / s;
    // g' = -2/s^2 - 8q^2/s^3 - 16/s - 32q^2/s^2
    const double gp = -2.0 / s2 - 8.0 * q * q / (s2 * s) - 16.0 / s - 32.0 * q * q / s2;
    return w(q) * (g * g + gp);
  }
  static double normalisation(int dim) { return numerical_normalisation<ModifiedMollifierShape>(dim); }
};

/// The sign changes of the shape's w'' on (0, support), ascending: a scan with `scan` steps, then bisection
/// to machine precision (where W'' changes sign, the Swegle tensile-instability criterion changes side).
/// Points where w'' is exactly 0 are skipped: near q = 1 the mollifiers' e^{-1/(1-q^2)} underflows to 0 (for
/// q > 0.9993), which is not a sign change (mathematically W'' > 0 there).
template <class Shape>
std::vector<double> second_derivative_sign_changes(int scan) {
  auto sign = [](double v) { return v > 0 ? 1 : v < 0 ? -1 : 0; };
  std::vector<double> roots;
  const double R = Shape::support, step = R / scan;
  double last_q = 1e-9 * step;
  int last = sign(Shape::d2w(last_q));
  for (int i = 1; i <= scan; ++i) {
    const double q = i * step - 1e-12;
    const int s = sign(Shape::d2w(q));
    if (s == 0) continue;
    if (last != 0 && s != last) {
      double lo = last_q, hi = q;
      for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
        const double mid = 0.5 * (lo + hi);
        (sign(Shape::d2w(mid)) == last ? lo : hi) = mid;
      }
      roots.push_back(0.5 * (lo + hi));
    }
    last = s;
    last_q = q;
  }
  return roots;
}

/// A cover function in `dim` dimensions: W, dW/dr, d2W/dr2 as functions of distance r and h.
template <class Shape>
class Kernel {
 public:
  using shape = Shape;
  explicit Kernel(int dim) : dim_(dim), sigma_(checked_normalisation(dim)) {}

  int dim() const { return dim_; }
  double sigma() const { return sigma_; }
  /// Support radius in units of h.
  static constexpr double support() { return Shape::support; }
  static constexpr const char* name() { return Shape::name; }

  double W(double r, double h) const { return sigma_ / hpow(h) * Shape::w(r / h); }
  double dWdr(double r, double h) const { return sigma_ / (hpow(h) * h) * Shape::dw(r / h); }
  double d2Wdr2(double r, double h) const { return sigma_ / (hpow(h) * h * h) * Shape::d2w(r / h); }
  /// A shape may give dw(q)/q in closed form (dw_over_q: no division, finite at q = 0); quotient() uses it if so.
  template <class S, class = void>
  struct has_dw_over_q : std::false_type {};
  template <class S>
  struct has_dw_over_q<S, std::void_t<decltype(S::dw_over_q(0.0))>> : std::true_type {};
#if defined(__AVX512F__) && defined(__AVX512VL__)
  template <class S, class = void>
  struct has_w_and_dw_over_q8 : std::false_type {};
  template <class S>
  struct has_w_and_dw_over_q8<S, std::void_t<decltype(S::w_and_dw_over_q8(std::declval<__m512d>(), std::declval<__m512d&>(), std::declval<__m512d&>()))>> : std::true_type {};
#endif
  /// W and F together at one smoothing length, its constants (1/h, sigma/h^dim, sigma/h^(dim+2)) computed
  /// once: the pair-list refreshes call it for every candidate pair.
  struct AtH {
    double inv_h, c, cF;
    void operator()(double r, double& W, double& F) const {
      const double q = r * inv_h;
      W = c * Shape::w(q);
      F = cF * quotient(q);
    }
#if defined(__AVX512F__) && defined(__AVX512VL__)
    /// The same for eight distances at once, bit for bit, where the shape has an eight-wide form (batch8).
    static constexpr bool batch8 = has_w_and_dw_over_q8<Shape>::value;
    void operator()(__m512d r, __m512d& W, __m512d& F) const {
      __m512d w, d;
      Shape::w_and_dw_over_q8(_mm512_mul_pd(r, _mm512_set1_pd(inv_h)), w, d);
      W = _mm512_mul_pd(_mm512_set1_pd(c), w);
      F = _mm512_mul_pd(_mm512_set1_pd(cF), d);
    }
#endif
  };
  /// dw(q)/q: the shape's closed form if it has one, else the quotient (its limit d2w(0) at q -> 0).
  static double quotient(double q) {
    if constexpr (has_dw_over_q<Shape>::value) return Shape::dw_over_q(q);
    else return q < 1e-12 ? Shape::d2w(0.0) : Shape::dw(q) / q;
  }
  AtH at(double h) const {
    const double inv_h = 1.0 / h, c = sigma_ / hpow(h);
    return {inv_h, c, c * inv_h * inv_h};
  }
  void W_and_F(double r, double h, double& W, double& F) const { at(h)(r, W, F); }
  /// F with grad_a W_ab = r_ab F_ab (Gray et al. 2001 eq 3.2): dW/dr / r, finite at r -> 0.
  double F(double r, double h) const { return sigma_ / (hpow(h) * h * h) * quotient(r / h); }

 private:
  static double checked_normalisation(int dim) {
    if (dim < 1 || dim > 3) throw std::invalid_argument("kernel dimension must be 1, 2 or 3, got " + std::to_string(dim));
    return Shape::normalisation(dim);
  }
  double hpow(double h) const { return dim_ == 1 ? h : dim_ == 2 ? h * h : h * h * h; }
  int dim_;
  double sigma_;
};

using CubicSpline = Kernel<CubicSplineShape>;
using Lucy = Kernel<LucyShape>;
using Gaussian = Kernel<GaussianShape>;
using Mollifier = Kernel<MollifierShape>;
using ModifiedMollifier = Kernel<ModifiedMollifierShape>;

/// Calls f(Kernel<Shape>) with the kernel named `name` (cubic_spline, lucy, gaussian, mollifier,
/// modified_mollifier): the one place a run-time kernel choice becomes a compile-time type.
template <class F>
decltype(auto) with_kernel(const std::string& name, int dim, F&& f) {
  if (name == CubicSplineShape::name) return f(CubicSpline(dim));
  if (name == LucyShape::name) return f(Lucy(dim));
  if (name == GaussianShape::name) return f(Gaussian(dim));
  if (name == MollifierShape::name) return f(Mollifier(dim));
  if (name == ModifiedMollifierShape::name) return f(ModifiedMollifier(dim));
  throw std::invalid_argument("unknown kernel '" + name +
                              "' (cubic_spline, lucy, gaussian, mollifier, modified_mollifier)");
}

}  // namespace sph
