// Total Lagrangian SPH in 2D (plane strain), Ismail 2009 Section 5.4 and Algorithm 5.2.
//
// Per step (t_n):
//   1. ghost displacements: at a boundary point X_b with outward normal n (the nearest boundary point of
//      the ghost), each component is either Dirichlet or traction. Traction components: the Taylor
//      extension u_g = u(X_m) + (F_b - I)(X_g - X_m), X_m = 2 X_b - X_g the mirror point, where the normal
//      column of F_b solves P(F_b) n = tbar (the 2D analogue of the 1D ghost with the prescribed strain) and
//      its tangential column is the last step's (values at X_b, X_m interpolated over the real particles,
//      exact at lattice points). Dirichlet components: the boundary
//      particles take ubar, the ghosts 2 ubar(X_b) - u(X_m), then the corrective factors of all boundary
//      particles, solved together (CorrectiveFactorSet: eqs 2.39-2.42 with the coupling of Section 2.9, i.e.
//      the modified SPH matrix 2.46 on the boundary rows; factorised once), make W u = ubar exactly there;
//   2. F = I + [X u, Y u] (eq 5.9); P = P(F) (neo-Hookean 3.64 or Hooke, plane strain, src/materials.hpp);
//   3. ghost stresses: rows of P of a traction component reflected oddly about the prescribed traction,
//      P_g = 2 Pbar(X_b) - P(X_m) with Pbar = P - (P n - tbar) n^T; rows of a Dirichlet component evenly,
//      P_g = P(X_m) (no acceleration normal to a held boundary);
//   4. a = Div P / rho_0 = (X P_.1 + Y P_.2) / rho_0 (5.6); 5. central differences (4.4) on the real particles.
// CHOSEN where the thesis differs or is silent: Algorithm 5.2 replaces u by its interpolant W u every step
// (lines 8-9) and sets displacement GRADIENTS equal to the traction (lines 14-17, a strain set to a stress);
// we keep u and impose the traction on P itself. Neumann conditions on P by reflection (step 3) rather than
// by the secondary SPH approximation of Section 2.9.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "total_lagrangian/boundary_correction.hpp"
#include "core/materials.hpp"
#include "total_lagrangian/sph_matrices.hpp"

namespace sph {

/// The boundary condition at a boundary point: per component, Dirichlet (value = displacement) or traction
/// (value = traction component t_c = (P n)_c in the reference configuration).
struct BoundaryCondition2D {
  bool dirichlet[2] = {false, false};
  std::function<double(const Vec2& X, double t)> value[2] = {[](const Vec2&, double) { return 0.0; },
                                                              [](const Vec2&, double) { return 0.0; }};
};

/// Where a ghost (or a real boundary particle) meets the boundary: nearest boundary point, outward normal,
/// index into BodyConfig2D::conditions.
struct BoundaryPoint2D {
  Vec2 Xb, n;
  int condition = 0;
};

struct BodyConfig2D {
  std::vector<Vec2> real;                 ///< real particles (reference positions)
  std::vector<Vec2> ghosts;               ///< ghost particles (within a cover of the real ones)
  double ps = 1.0;                        ///< lattice spacing; dV = ps^2
  double h_over_ps = 2.5;
  std::string kernel = "modified_mollifier";
  double rho = 1.0;
  enum class Law { Hooke, NeoHookean } law = Law::NeoHookean;
  Lame lame{1.0, 1.0};
  std::vector<BoundaryCondition2D> conditions;
  std::function<BoundaryPoint2D(const Vec2& Xg)> ghost_boundary;  ///< for every ghost
  /// Real particles that carry Dirichlet components: (index into real, condition index).
  std::vector<std::pair<int, int>> real_on_dirichlet;
  double damping = 0.0;                   ///< optional mass-proportional damping a -= damping v (1/s)
  /// Zero-energy-mode ("hourglass") control, dimensionless gamma (0 = off, the thesis's scheme). The plain
  /// SPH gradient does not see a particle-scale sawtooth (sum_q (-1)^q grad W = 0 on a lattice), so nothing
  /// resists it and boundary closures can feed it. The control adds, on real particle i,
  ///   a_i += gamma (E / rho) sum_j K_ij [ (u_j - u_i) - (G_i + G_j)/2 (X_j - X_i) ],  K_ij = W_ij dV / |X_ij|^2,
  /// G = F - I the SPH displacement gradient (G_j := G_i for a ghost j, whose own gradient is truncated):
  /// the misfit of each pair against the field the two gradients predict (after Ganzenmueller 2015,
  /// linearised). It is zero for any linear field (between real particles also quadratic), pairwise
  /// antisymmetric between real particles (momentum kept), and stiffens exactly the modes the gradient
  /// cannot see. Kept away from ghosts (real pairs only) it does not hold the edge mode of the hole
  /// sheet down: the ghost pairs are what tie the boundary layer's sawtooth to the closure. It does not cure
  /// the closure's weak instability at loaded edges and their corners (see
  /// experiments/ismail2009_fig5_13to5_15_hole_resolution.cpp: damping holds it down there).
  double hourglass = 0.0;
  /// Real particles on a piece with a traction component: (index into real, condition, boundary length).
  std::vector<std::tuple<int, int, double>> real_on_traction;
  /// Energy-consistent ("variational") boundary: traction components of the ghosts extend u linearly,
  /// u_g = 2 u(X_b) - u(X_m) (a linear map E of the real values), stresses are zero at the ghosts, the ghost
  /// rows of Div P are returned to the real particles by E^T and tractions enter as boundary forces
  /// tbar dA. Then the semi-discrete force is minus the gradient of sum psi(F) dV: no mode can gain energy
  /// from the boundary (the reflection scheme above feeds a particle-scale sawtooth at free edges that grows
  /// over thousands of steps; see `hourglass`). It is less accurate near boundaries (the boundary forces and
  /// the ghost rows land on the first layers of particles: the sheet with a hole's stress comes out 30% low
  /// at 201 per side), so every scene uses the reflection scheme; this one is kept for that comparison.
  bool variational = false;
};

class Body2D {
 public:
  explicit Body2D(BodyConfig2D cfg);
  Body2D(const Body2D&) = delete;
  Body2D& operator=(const Body2D&) = delete;

  /// u_0 = u_{-1} = u0(X) on the real particles.
  void set_initial_displacement(const std::function<Vec2(const Vec2&)>& u0);
  void step(double dt);

  double time() const { return t_; }
  long steps() const { return steps_; }
  int n_real() const { return nr_; }
  const Vec2& X(int i) const { return cfg_.real[i]; }
  Vec2 u(int i) const { return {u_[0][i], u_[1][i]}; }
  /// (u_n - u_{n-1}) / dt of the last step (zero before the first); Dirichlet components as prescribed.
  Vec2 velocity(int i) const;
  double rho0() const { return cfg_.rho; }
  /// F and P at real particle i, from the last step (time t - dt).
  Tensor2 F(int i) const;
  Tensor2 P(int i) const;
  /// Cauchy stress T = J^-1 P F^T (3.33), in-plane.
  Tensor2 cauchy(int i) const { return cauchy_from_P<2>(P(i), F(i)); }
  /// The Shepard-normalised SPH interpolant of the Cauchy stress over the real particles at real particle i,
  /// sum_q W_iq T_q / sum_q W_iq: the 'secondary SPH approximation' of Section 2.9, which filters the
  /// particle-scale (zero-energy) modes that the plain SPH gradient cannot see.
  Tensor2 smoothed_cauchy(int i) const;
  double h() const { return kern_.radius; }
  bool finite() const;
  double build_seconds() const { return build_s_; }  ///< SPH matrices, interpolation rows, LU factorisations
  int nearest(const Vec2& Xq) const;

 private:
  Tensor2 law(const Tensor2& F) const;
  void pin_dirichlet(double t);  // Dirichlet components of the boundary particles at their values at t
  void set_ghost_displacements(double t);
  void set_ghost_stresses(double t);
  Vec2 traction_normal_column(const Tensor2& Fb, const Vec2& n, const BoundaryCondition2D& bc, const Vec2& Xb,
                              double t) const;
  BodyConfig2D cfg_;
  KernelFn kern_;
  int nr_ = 0, ng_ = 0;
  std::vector<Vec2> all_;
  SphMatrices2D m_;
  SparseMatrix Ib_, Im_;                    // ghost rows: interpolation at X_b and X_m over real particles
  std::vector<BoundaryPoint2D> gb_;         // per ghost
  std::unique_ptr<CorrectiveFactorSet> dir_[2];
  std::vector<int> dir_cond_[2];              // condition of each boundary particle of dir_[c]
  Eigen::VectorXd dir_target_[2];
  Eigen::VectorXd u_[2], up_[2], g_[4], P_[4], a_[2], tmp_, tb_, tm_;
  Eigen::Matrix<double, Eigen::Dynamic, 4> Pb_, Pm_;
  Eigen::Matrix<double, Eigen::Dynamic, 2> Um_, Ub_;  // u interpolated at X_m and X_b, per ghost
  SparseMatrix K_;                                 // hourglass pair weights, real rows x all columns
  void add_hourglass(int c, Eigen::VectorXd& a) const;
  SparseMatrix Et_[2];                            // variational: E^T (real x ghost) per component
  Eigen::VectorXd ag_;  // P interpolated at X_b and X_m, per ghost
  double t_ = 0.0, build_s_ = 0.0, dt_last_ = 0.0;
  long steps_ = 0;
};

}  // namespace sph
