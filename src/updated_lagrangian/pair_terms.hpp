// The pair terms of the scheme of Gray, Monaghan & Swift 2001 (Sections 2, 3, 6), one type each with the
// equation it implements, composed by the fused pair loop of pair_loop.hpp. A scheme is one list of named terms,
//   GrayTerms<ArtificialStress, Xsph, MonaghanViscosity, ContinuityDensity>
// each slot holding a term or its named alternative (NoArtificialStress, NoXsph, NoViscosity, SummationDensity).
// A term that is off is a type whose functions do nothing and which asks for no fields and no partial sums:
// the loop has none of its work, the neighbour record none of its slots. select_terms is the one place where
// the run-time GrayOptions become such a list.
//
// A pass-2 pair function is a template over the value type V (core/lanes.hpp): a double for one pair, a SIMD
// batch for a block of pairs, one per lane, so every build runs this one source. It says which products it
// fuses (fma) and which it rounds before adding (rounded): those of the scalar loop it replaced, whose bits
// every width keeps (tests/test_gray_solver.cpp holds each width to a plain scalar reference, bit for bit).
#pragma once

#include <cstdint>
#include <type_traits>

#include "core/lanes.hpp"
#include "core/types.hpp"
#include "updated_lagrangian/artificial_stress.hpp"
#include "updated_lagrangian/parameters.hpp"

namespace sph {

/// What a pass-2 pair function reads: the pair's geometry and the two particles' neighbour records
/// (pair_loop.hpp), a's the same in every lane, b's one per lane.
template <class V>
struct PairView {
  V dx, dy;          ///< x_a - x_b
  V W;               ///< W_ab
  V gWx, gWy;        ///< grad_a W_ab = (x_a - x_b) F_ab (3.2)
  const double* ra;  ///< a's record
  const V* rb;       ///< b's record, field by field
  V a(int f) const { return V(ra[f]); }
  const V& b(int f) const { return rb[f]; }
};

/// The constants of the pair terms.
struct PairConstants {
  double h, eta2;          ///< smoothing length; eta^2 = 0.01 h^2 of the viscosity
  double alpha, beta, c0;  ///< Monaghan's viscosity
  double inv_Wdp;          ///< 1 / W(dp): f = W / W(dp) (3.13)
  int n;                   ///< the exponent of f^n (3.12)
};

// ---- The terms every scheme has -----------------------------------------------------------------------------

/// The stress term of the acceleration (3.1), with the pair's tensor M of the optional terms below:
///   dv_a/dt = sum_b m_b M_ab grad_a W_ab, M_ab = sigma_a / rho_a^2 + sigma_b / rho_b^2 (+ Pi_ab I + R_ab f^n)
/// sigma / rho^2 (sigma = S - P(rho) I, (2.2), (2.7)) is in the records at `at`, column-major.
struct StressAcceleration {
  template <int at, class V>
  static void tensor(const PairView<V>& p, V (&M)[4]) {
    for (int c = 0; c < 4; ++c) M[c] = p.a(at + c) + p.b(at + c);
  }
  /// M grad_a W_ab: a gains m_b times it, b loses m_a times it.
  template <class V>
  static void pair(const PairView<V>& p, const V (&M)[4], V& tx, V& ty) {
    tx = lanes::fma(M[2], p.gWy, M[0] * p.gWx);
    ty = lanes::fma(M[3], p.gWy, M[1] * p.gWx);
  }
};

/// The velocity gradient (3.10) of the velocity the particles move with (vhat with XSPH, else v):
///   (d vhat^i / d x^j)_a = -sum_b V_b (vhat_a - vhat_b)^i (grad_a W_ab)^j, V_b = m_b / rho_b
/// t = vhat_ab grad_a W_ab^T by components (column-major); a gains -V_b t, b gains -V_a t.
struct VelocityGradient {
  template <class V>
  static void pair(const PairView<V>& p, const V& vx, const V& vy, V* t) {
    t[0] = vx * p.gWx;
    t[1] = vy * p.gWx;
    t[2] = vx * p.gWy;
    t[3] = vy * p.gWy;
  }
};

// ---- Slot 1: the artificial stress ----------------------------------------------------------------------------

/// f^n of the artificial stress (3.12), f = W_ab / W(dp) (3.13): the paper's n = 4 by three multiplications
/// (the loop's product order: the same bits) instead of the loop, whose branch a pair loop then loses.
template <class V>
V artificial_stress_fn(V f, int n) {
  if (n == 4) return ((f * f) * f) * f;
  V r(1.0);
  for (int i = 0; i < n; ++i) r = r * f;
  return r;
}

/// Monaghan's artificial stress (3.12)-(3.14): M_ab += R_ab f_ab^n, R_ab = R_a + R_b (3.14), f_ab = W_ab / W(dp)
/// (3.13), R_a from the principal stresses (6.1)-(6.7) (artificial_stress.hpp), in the records at `at`.
struct ArtificialStress {
  static constexpr int fields = 4;
  static void particle(double* r, const Tensor2& sigma, double rho, double eps) {
    const Tensor2 R = artificial_stress(sigma, rho, eps);
    for (int c = 0; c < 4; ++c) r[c] = R.data()[c];
  }
  template <int at, class V>
  static void pair(const PairView<V>& p, const PairConstants& k, V (&M)[4]) {
    const V fn = artificial_stress_fn(p.W * V(k.inv_Wdp), k.n);
    for (int c = 0; c < 4; ++c) M[c] = lanes::fma(p.a(at + c) + p.b(at + c), fn, M[c]);
  }
};
struct NoArtificialStress {
  static constexpr int fields = 0;
  static void particle(double*, const Tensor2&, double, double) {}
  template <int at, class V>
  static void pair(const PairView<V>&, const PairConstants&, V (&)[4]) {}
};

// ---- Slot 2: XSPH ---------------------------------------------------------------------------------------------

/// The pair's term of the XSPH sum (3.6), (v_b - v_a) W_ab / rho_ab with rho_ab = (rho_a + rho_b) / 2.
inline Vec2 xsph_pair_term(const Vec2& va, const Vec2& vb, double W, double rho_a, double rho_b) {
  return (vb - va) * (W / (0.5 * (rho_a + rho_b)));
}

/// XSPH (3.6): vhat_a = v_a + eps sum_b m_b (v_b - v_a) W_ab / rho_ab, summed in pass 1 (a gains m_b times the
/// pair's term, b loses m_a times it); the particles move with vhat, and the density (3.8) and the velocity
/// gradient (3.10) difference it (Section 3).
struct Xsph {
  static constexpr bool pass1 = true;
  static void pass1_pair(const Vec2& va, const Vec2& vb, double W, double rho_a, double rho_b, double ma, double mb,
                         Vec2& sum_a, Vec2* sum, std::uint32_t b) {
    const Vec2 w = xsph_pair_term(va, vb, W, rho_a, rho_b);
    sum_a += mb * w;
    sum[b] -= ma * w;
  }
  static Vec2 velocity(const Vec2& v, double eps, const Vec2& sum) { return v + eps * sum; }
};
/// The particles move with v, and everything differences v.
struct NoXsph {
  static constexpr bool pass1 = false;
  static void pass1_pair(const Vec2&, const Vec2&, double, double, double, double, double, Vec2&, Vec2*, std::uint32_t) {}
};

// ---- Slot 3: the viscosity ------------------------------------------------------------------------------------

/// Monaghan's Pi_ab >= 0 of an approaching pair (vr = v_ab . x_ab < 0; r2 = |x_ab|^2, eta2 = 0.01 h^2):
///   Pi_ab = (-alpha c0 mu_ab + beta mu_ab^2) / rho_ab, mu_ab = h vr / (r2 + eta2), rho_ab = (rho_a + rho_b) / 2
template <class V>
V monaghan_pi(V vr, V r2, double h, double eta2, double alpha, double beta, double c0, V rho_a, V rho_b) {
  const V mu = V(h) * vr / (r2 + V(eta2));
  return lanes::fma(V(-alpha * c0), mu, V(beta) * mu * mu) / (V(0.5) * (rho_a + rho_b));
}

/// Monaghan's viscosity, the Pi_ab delta^ij of (3.1) (Gray's refs [11, 13]): Pi_ab >= 0 acts as a pressure,
/// so M_ab -= Pi_ab I for an approaching pair. v and rho in the records at `at`.
struct MonaghanViscosity {
  static constexpr int fields = 3;
  static void particle(double* r, const Vec2& v, double rho) {
    r[0] = v.x();
    r[1] = v.y();
    r[2] = rho;
  }
  template <int at, class V>
  static void pair(const PairView<V>& p, const PairConstants& k, V (&M)[4]) {
    const V vx = p.a(at) - p.b(at), vy = p.a(at + 1) - p.b(at + 1);
    const V vr = lanes::rounded(vx * p.dx) + lanes::rounded(vy * p.dy);
    const auto approaching = vr < V(0.0);
    // Only if a pair of the block approaches: the two divisions cost as much for a block as for one pair.
    if (lanes::any(approaching)) {
      const V r2 = lanes::rounded(p.dx * p.dx) + lanes::rounded(p.dy * p.dy);
      const V Pi = monaghan_pi(vr, r2, k.h, k.eta2, k.alpha, k.beta, k.c0, p.a(at + 2), p.b(at + 2));
      M[0] = lanes::select(approaching, M[0] - Pi, M[0]);
      M[3] = lanes::select(approaching, M[3] - Pi, M[3]);
    }
  }
};
struct NoViscosity {
  static constexpr int fields = 0;
  static void particle(double*, const Vec2&, double) {}
  template <int at, class V>
  static void pair(const PairView<V>&, const PairConstants&, V (&)[4]) {}
};

// ---- Slot 4: the density --------------------------------------------------------------------------------------

/// The continuity equation (3.8): d rho_a / dt = sum_b m_b vhat_ab . grad_a W_ab; a gains m_b t, b gains m_a t.
struct ContinuityDensity {
  static constexpr bool pass1 = false;
  static void pass1_pair(double, double, double, double&, double*, std::uint32_t) {}
  template <class V>
  static V pair(const PairView<V>& p, const V& vx, const V& vy) {
    return lanes::rounded(vx * p.gWx) + lanes::rounded(vy * p.gWy);
  }
};
/// The density by summation instead (Section 3: "in principle, the density could be calculated by a summation
/// over the particles"): rho_a = m_a W(0) + sum_b m_b W_ab, in pass 1; no density rate.
struct SummationDensity {
  static constexpr bool pass1 = true;
  static void pass1_pair(double W, double ma, double mb, double& sum_a, double* sum, std::uint32_t b) {
    sum_a += mb * W;
    sum[b] += ma * W;
  }
  template <class V>
  static V pair(const PairView<V>&, const V&, const V&) {
    return V(0.0);
  }
};

// ---- The scheme: one list of named terms ----------------------------------------------------------------------

template <class T, class... Choices>
constexpr bool one_of = (std::is_same_v<T, Choices> || ...);

/// The terms of a scheme, one per slot: GrayTerms<ArtificialStress, Xsph, MonaghanViscosity, ContinuityDensity>.
template <class Tensile, class Smoothing, class Viscosity, class Density>
struct GrayTerms {
  static_assert(one_of<Tensile, ArtificialStress, NoArtificialStress>, "GrayTerms slot 1: ArtificialStress or NoArtificialStress");
  static_assert(one_of<Smoothing, Xsph, NoXsph>, "GrayTerms slot 2: Xsph or NoXsph");
  static_assert(one_of<Viscosity, MonaghanViscosity, NoViscosity>, "GrayTerms slot 3: MonaghanViscosity or NoViscosity");
  static_assert(one_of<Density, ContinuityDensity, SummationDensity>, "GrayTerms slot 4: ContinuityDensity or SummationDensity");
  using tensile = Tensile;
  using xsph = Smoothing;
  using viscosity = Viscosity;
  using density = Density;
};

/// Calls f(On{}) if `on`, else f(Off{}).
template <class On, class Off, class F>
auto choose(bool on, F&& f) {
  return on ? f(On{}) : f(Off{});
}

/// The one place where the run-time options become a scheme: calls f(GrayTerms<...>{}) with the terms `o` names.
template <class F>
auto select_terms(const GrayOptions& o, F&& f) {
  return choose<ArtificialStress, NoArtificialStress>(o.artificial_stress, [&](auto tensile) {
    return choose<Xsph, NoXsph>(o.xsph, [&](auto xsph) {
      return choose<MonaghanViscosity, NoViscosity>(o.viscosity, [&](auto viscosity) {
        return choose<SummationDensity, ContinuityDensity>(o.summation_density, [&](auto density) {
          return f(GrayTerms<decltype(tensile), decltype(xsph), decltype(viscosity), decltype(density)>{});
        });
      });
    });
  });
}

}  // namespace sph
