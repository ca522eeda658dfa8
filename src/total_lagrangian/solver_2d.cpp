#include "total_lagrangian/solver_2d.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/central_difference.hpp"
#include "core/neighbours.hpp"

namespace sph {

namespace {

/// Interpolation rows over the real particles [0, nr) for query points Y: weight 1 on a real particle that
/// sits at the point (exact mirrors on a lattice), else Shepard weights W(|Y - X_q|) / sum W.
SparseMatrix interpolation_rows(const std::vector<Vec2>& all, int nr, const std::vector<Vec2>& Y, const KernelFn& k,
                                double ps) {
  std::vector<Vec2> pts(all.begin(), all.begin() + nr);
  pts.insert(pts.end(), Y.begin(), Y.end());
  Box2 box = bounding_box(pts);
  box.xmax += k.radius; box.ymax += k.radius;
  CellList2D cells(box, k.radius);
  cells.build(pts);
  std::vector<Eigen::Triplet<double, int>> trip;
  for (std::size_t r = 0; r < Y.size(); ++r) {
    const std::size_t qi = nr + r;
    int exact = -1;
    double sw = 0;
    std::vector<std::pair<int, double>> w;
    cells.for_each_neighbour(pts, qi, k.radius, [&](std::size_t j, const Vec2&, double dist) {
      if (static_cast<int>(j) >= nr) return;
      if (dist < 1e-6 * ps) exact = static_cast<int>(j);
      const double wj = k.W(dist);
      w.emplace_back(static_cast<int>(j), wj);
      sw += wj;
    });
    if (exact >= 0) { trip.emplace_back(static_cast<int>(r), exact, 1.0); continue; }
    if (!(sw > 0)) throw std::invalid_argument("Body2D: a ghost's mirror point has no real particle within a cover");
    for (const auto& [j, wj] : w) trip.emplace_back(static_cast<int>(r), j, wj / sw);
  }
  SparseMatrix I(static_cast<int>(Y.size()), static_cast<int>(all.size()));
  I.setFromTriplets(trip.begin(), trip.end());
  I.makeCompressed();
  return I;
}

}  // namespace

Body2D::Body2D(BodyConfig2D cfg) : cfg_(std::move(cfg)) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!(cfg_.ps > 0) || !(cfg_.rho > 0) || cfg_.real.empty()) throw std::invalid_argument("Body2D: need ps, rho > 0 and particles");
  if (cfg_.conditions.empty() && !cfg_.ghosts.empty()) throw std::invalid_argument("Body2D: ghosts need boundary conditions");
  kern_ = make_kernel_fn(cfg_.kernel, 2, cfg_.h_over_ps * cfg_.ps);
  nr_ = static_cast<int>(cfg_.real.size());
  ng_ = static_cast<int>(cfg_.ghosts.size());
  all_ = cfg_.real;
  all_.insert(all_.end(), cfg_.ghosts.begin(), cfg_.ghosts.end());
  const int n = nr_ + ng_;
  m_ = build_sph_matrices_2d(kern_, all_, std::vector<double>(n, cfg_.ps * cfg_.ps));
  std::vector<Vec2> Yb, Ym;
  for (const auto& g : cfg_.ghosts) {
    gb_.push_back(cfg_.ghost_boundary(g));
    if (gb_.back().condition < 0 || gb_.back().condition >= static_cast<int>(cfg_.conditions.size()))
      throw std::invalid_argument("Body2D: ghost boundary condition index out of range");
    Yb.push_back(gb_.back().Xb);
    Ym.push_back(2.0 * gb_.back().Xb - g);
  }
  if (ng_ > 0) {
    Ib_ = interpolation_rows(all_, nr_, Yb, kern_, cfg_.ps);
    Im_ = interpolation_rows(all_, nr_, Ym, kern_, cfg_.ps);
  }
  for (int c = 0; c < 2; ++c) {
    std::vector<int> bset, gset;
    std::vector<char> in(nr_, 0);
    for (const auto& [i, cond] : cfg_.real_on_dirichlet)
      if (cfg_.conditions.at(cond).dirichlet[c] && !in.at(i)) { bset.push_back(i); in[i] = 1; dir_cond_[c].push_back(cond); }
    for (int k = 0; k < ng_; ++k)
      if (cfg_.conditions[gb_[k].condition].dirichlet[c]) gset.push_back(nr_ + k);
    if (!bset.empty() && !gset.empty()) {
      dir_[c] = std::make_unique<CorrectiveFactorSet>(m_.W, kern_, all_, bset, gset);
      dir_target_[c].resize(static_cast<int>(bset.size()));
    }
  }
  for (int c = 0; c < 2; ++c) {
    u_[c] = Eigen::VectorXd::Zero(n);
    up_[c] = u_[c];
    a_[c] = u_[c];
  }
  for (auto& v : g_) v = Eigen::VectorXd::Zero(n);
  for (auto& v : P_) v = Eigen::VectorXd::Zero(n);
  tmp_ = Eigen::VectorXd::Zero(n);
  tb_ = Eigen::VectorXd::Zero(ng_);
  tm_ = Eigen::VectorXd::Zero(ng_);
  Pb_.resize(ng_, 4);
  Um_.resize(ng_, 2);
  Ub_.resize(ng_, 2);
  ag_ = Eigen::VectorXd::Zero(ng_);
  if (cfg_.variational && ng_ > 0) {
    for (int c = 0; c < 2; ++c) {
      // Row g of E: 2 Ib_g - Im_g (traction component) or -Im_g (Dirichlet: the prescribed part is affine).
      std::vector<Eigen::Triplet<double, int>> tr;
      for (int k = 0; k < ng_; ++k) {
        const bool dir = cfg_.conditions[gb_[k].condition].dirichlet[c];
        if (!dir)
          for (SparseMatrix::InnerIterator it(Ib_, k); it; ++it) tr.emplace_back(static_cast<int>(it.col()), k, 2.0 * it.value());
        for (SparseMatrix::InnerIterator it(Im_, k); it; ++it) tr.emplace_back(static_cast<int>(it.col()), k, -it.value());
      }
      Et_[c].resize(n, ng_);
      Et_[c].setFromTriplets(tr.begin(), tr.end());
      Et_[c].makeCompressed();
    }
  }
  Pm_.resize(ng_, 4);
  if (cfg_.hourglass < 0) throw std::invalid_argument("Body2D: hourglass >= 0");
  if (cfg_.hourglass > 0) {
    std::vector<Eigen::Triplet<double, int>> tr;
    const double dV = cfg_.ps * cfg_.ps;
    for (int i = 0; i < nr_; ++i)
      for (SparseMatrix::InnerIterator it(m_.W, i); it; ++it) {
        const int j = static_cast<int>(it.col());
        if (j == i) continue;
        const double r2 = (all_[j] - all_[i]).squaredNorm();
        if (r2 > 0 && it.value() > 0) tr.emplace_back(i, j, kern_.W(std::sqrt(r2)) * dV / r2);
      }
    K_.resize(nr_, n);
    K_.setFromTriplets(tr.begin(), tr.end());
    K_.makeCompressed();
  }
  build_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void Body2D::set_initial_displacement(const std::function<Vec2(const Vec2&)>& u0) {
  for (int i = 0; i < nr_; ++i) {
    const Vec2 v = u0(cfg_.real[i]);
    for (int c = 0; c < 2; ++c) u_[c][i] = up_[c][i] = v[c];
  }
  // The ghost rule uses the gradient of the previous step: converge it for the initial state.
  for (int it = 0; it < 20; ++it) {
    set_ghost_displacements(t_);
    spmv(m_.X, u_[0], g_[0]);
    spmv(m_.Y, u_[0], g_[1]);
    spmv(m_.X, u_[1], g_[2]);
    spmv(m_.Y, u_[1], g_[3]);
  }
}

int Body2D::nearest(const Vec2& Xq) const {
  int best = 0;
  for (int i = 1; i < nr_; ++i)
    if ((cfg_.real[i] - Xq).squaredNorm() < (cfg_.real[best] - Xq).squaredNorm()) best = i;
  return best;
}

Tensor2 Body2D::law(const Tensor2& F) const {
  if (cfg_.law == BodyConfig2D::Law::NeoHookean) return neo_hookean_P<2>(cfg_.lame, F);
  return hooke_stress<2>(cfg_.lame, small_strain<2>(Tensor2(F - Tensor2::Identity())));
}

Tensor2 Body2D::F(int i) const {
  Tensor2 F;
  F << 1.0 + g_[0][i], g_[1][i], g_[2][i], 1.0 + g_[3][i];
  return F;
}

Tensor2 Body2D::P(int i) const {
  Tensor2 P;
  P << P_[0][i], P_[1][i], P_[2][i], P_[3][i];
  return P;
}

Vec2 Body2D::traction_normal_column(const Tensor2& Fb, const Vec2& n, const BoundaryCondition2D& bc,
                                    const Vec2& Xb, double t) const {
  // Unknown: a = F n (the derivative along the normal), for the traction components only; the others keep
  // the value of the last step. Newton on (P(F(a)) n - tbar)_c = 0 with F(a) = Fb + (a - Fb n) n^T.
  Vec2 a = Fb * n;
  int free_c[2], nf = 0;
  for (int c = 0; c < 2; ++c) if (!bc.dirichlet[c]) free_c[nf++] = c;
  if (nf == 0) return a;
  const Vec2 tbar(bc.dirichlet[0] ? 0.0 : bc.value[0](Xb, t), bc.dirichlet[1] ? 0.0 : bc.value[1](Xb, t));
  const double scale = std::abs(tbar.x()) + std::abs(tbar.y()) + cfg_.lame.mu;
  auto residual = [&](const Vec2& aa) {
    const Tensor2 F = Fb + (aa - Fb * n) * n.transpose();
    return Vec2(law(F) * n - tbar);
  };
  for (int it = 0; it < 12; ++it) {
    const Vec2 r = residual(a);
    double rn = 0;
    for (int i = 0; i < nf; ++i) rn = std::max(rn, std::abs(r[free_c[i]]));
    if (!std::isfinite(rn)) return Fb * n;
    if (rn < 1e-12 * scale) break;
    Eigen::Matrix2d J = Eigen::Matrix2d::Identity();
    for (int j = 0; j < nf; ++j) {
      Vec2 ap = a;
      const double e = 1e-7 * (1.0 + std::abs(a[free_c[j]]));
      ap[free_c[j]] += e;
      const Vec2 rp = residual(ap);
      for (int i = 0; i < nf; ++i) J(i, j) = (rp[free_c[i]] - r[free_c[i]]) / e;
    }
    Vec2 rr(r[free_c[0]], nf > 1 ? r[free_c[1]] : 0.0);
    if (nf == 1) { J(0, 1) = J(1, 0) = 0; J(1, 1) = 1; }
    const Vec2 da = J.fullPivLu().solve(rr);
    for (int i = 0; i < nf; ++i) a[free_c[i]] -= da[i];
  }
  return a;
}

void Body2D::pin_dirichlet(double t) {
  // Boundary particles of a Dirichlet component hold the prescribed value.
  for (int c = 0; c < 2; ++c) {
    if (!dir_[c]) continue;
    const auto& b = dir_[c]->boundary();
    for (std::size_t s = 0; s < b.size(); ++s) {
      dir_target_[c][s] = cfg_.conditions[dir_cond_[c][s]].value[c](all_[b[s]], t);
      u_[c][b[s]] = dir_target_[c][s];
    }
  }
}

void Body2D::set_ghost_displacements(double t) {
  pin_dirichlet(t);
  if (ng_ > 0) {
    // Ghost values: Dirichlet components odd about the prescribed value, 2 ubar(X_b) - u(X_m); traction
    // components by the Taylor extension u(X_m) + (F_b - I)(X_g - X_m), where the normal column of F_b solves
    // the traction condition P(F_b) n = tbar (Newton) and the tangential column is the last step's (an
    // extension with the lagged gradient alone feeds the boundary gradient back to itself with gain ~1: a
    // neutral mode that grows at loaded edges).
    Um_.col(0).noalias() = Im_ * u_[0];
    Um_.col(1).noalias() = Im_ * u_[1];
    if (cfg_.variational) {
      Ub_.col(0).noalias() = Ib_ * u_[0];
      Ub_.col(1).noalias() = Ib_ * u_[1];
    }
    for (int k = 0; k < 4; ++k) {
      tb_.noalias() = Ib_ * g_[k];
      Pb_.col(k) = tb_;
    }
#pragma omp parallel for schedule(static) if (ng_ > 5000)
    for (int k = 0; k < ng_; ++k) {
      const auto& bp = gb_[k];
      const auto& bc = cfg_.conditions[bp.condition];
      const Vec2 Xg = cfg_.ghosts[k], d = Xg - (2.0 * bp.Xb - Xg);
      Tensor2 Fb;
      Fb << 1.0 + Pb_(k, 0), Pb_(k, 1), Pb_(k, 2), 1.0 + Pb_(k, 3);
      Vec2 ext = Vec2::Zero();
      if (cfg_.variational) {
        for (int c = 0; c < 2; ++c)
          u_[c][nr_ + k] = bc.dirichlet[c] ? 2.0 * bc.value[c](bp.Xb, t) - Um_(k, c) : 2.0 * Ub_(k, c) - Um_(k, c);
        continue;
      }
      if (!bc.dirichlet[0] || !bc.dirichlet[1]) {
        const Vec2 a = traction_normal_column(Fb, bp.n, bc, bp.Xb, t);
        const Tensor2 F = Fb + (a - Fb * bp.n) * bp.n.transpose();
        ext = (F - Tensor2::Identity()) * d;
      }
      for (int c = 0; c < 2; ++c)
        u_[c][nr_ + k] = bc.dirichlet[c] ? 2.0 * bc.value[c](bp.Xb, t) - Um_(k, c) : Um_(k, c) + ext[c];
    }
  }
  for (int c = 0; c < 2; ++c)
    if (dir_[c]) dir_[c]->apply(u_[c], dir_target_[c]);
}

void Body2D::set_ghost_stresses(double t) {
  if (ng_ == 0) return;
  auto& Pb = Pb_;
  auto& Pm = Pm_;
  for (int k = 0; k < 4; ++k) {
    tb_.noalias() = Ib_ * P_[k];
    tm_.noalias() = Im_ * P_[k];
    Pb.col(k) = tb_;
    Pm.col(k) = tm_;
  }
  for (int g = 0; g < ng_; ++g) {
    const auto& bp = gb_[g];
    const auto& bc = cfg_.conditions[bp.condition];
    for (int c = 0; c < 2; ++c) {  // row c of P: (P_c1, P_c2) = columns 2c, 2c + 1
      Vec2 rb(Pb(g, 2 * c), Pb(g, 2 * c + 1)), rm(Pm(g, 2 * c), Pm(g, 2 * c + 1)), rg;
      if (bc.dirichlet[c]) {
        rg = rm;
      } else {
        const double tbar = bc.value[c](bp.Xb, t);
        const Vec2 rbar = rb - (rb.dot(bp.n) - tbar) * bp.n;
        rg = 2.0 * rbar - rm;
      }
      P_[2 * c][nr_ + g] = rg.x();
      P_[2 * c + 1][nr_ + g] = rg.y();
    }
  }
}

void Body2D::step(double dt) {
  set_ghost_displacements(t_);
  spmv(m_.X, u_[0], g_[0]);
  spmv(m_.Y, u_[0], g_[1]);
  spmv(m_.X, u_[1], g_[2]);
  spmv(m_.Y, u_[1], g_[3]);
#pragma omp parallel for schedule(static) if (nr_ > 20000)
  for (int i = 0; i < nr_; ++i) {
    const Tensor2 P = law(F(i));
    P_[0][i] = P(0, 0); P_[1][i] = P(0, 1); P_[2][i] = P(1, 0); P_[3][i] = P(1, 1);
  }
  if (!cfg_.variational) set_ghost_stresses(t_);
  for (int c = 0; c < 2; ++c) {
    spmv(m_.X, P_[2 * c], a_[c]);
    spmv(m_.Y, P_[2 * c + 1], tmp_);
    a_[c] += tmp_;
    if (cfg_.variational) {
      if (ng_ > 0) {
        ag_ = a_[c].tail(ng_);
        tmp_.noalias() = Et_[c] * ag_;
        a_[c].head(nr_) += tmp_.head(nr_);
      }
      const double dV = cfg_.ps * cfg_.ps;
      for (const auto& [i, cond, dA] : cfg_.real_on_traction)
        if (!cfg_.conditions[cond].dirichlet[c]) a_[c][i] += cfg_.conditions[cond].value[c](all_[i], t_) * dA / dV;
    }
    if (cfg_.hourglass > 0) add_hourglass(c, a_[c]);
    a_[c] /= cfg_.rho;
    if (cfg_.damping > 0) a_[c].head(nr_) -= cfg_.damping / dt * (u_[c].head(nr_) - up_[c].head(nr_));
    central_difference_step(u_[c], up_[c], a_[c], dt, 0, nr_);
  }
  t_ += dt;
  dt_last_ = dt;
  ++steps_;
  // The integrator also moved the Dirichlet components of the boundary particles; the next step pins them
  // again before it uses them, so pin them here already: u() and velocity() between steps then report the
  // prescribed motion, not a dt^2 a of the reaction force (which made pinned particles look like they move).
  pin_dirichlet(t_);
}

Vec2 Body2D::velocity(int i) const {
  if (!(dt_last_ > 0)) return Vec2::Zero();
  return Vec2(u_[0][i] - up_[0][i], u_[1][i] - up_[1][i]) / dt_last_;
}

void Body2D::add_hourglass(int c, Eigen::VectorXd& a) const {
  // Row c of G: g_[2c] = du_c/dX, g_[2c + 1] = du_c/dY.
  const Eigen::VectorXd &gx = g_[2 * c], &gy = g_[2 * c + 1], &u = u_[c];
  const double k = cfg_.hourglass * young_modulus(cfg_.lame);
  const int* outer = K_.outerIndexPtr();
  const int* inner = K_.innerIndexPtr();
  const double* val = K_.valuePtr();
#pragma omp parallel for schedule(static) if (nr_ > 20000)
  for (int i = 0; i < nr_; ++i) {
    double s = 0;
    for (int e = outer[i]; e < outer[i + 1]; ++e) {
      const int j = inner[e];
      const bool ghost = j >= nr_;  // a ghost's own gradient is truncated by the edge of the ghost layer
      const double Gx = 0.5 * (gx[i] + (ghost ? gx[i] : gx[j])), Gy = 0.5 * (gy[i] + (ghost ? gy[i] : gy[j]));
      const Vec2 d = all_[j] - all_[i];
      s += val[e] * (u[j] - u[i] - Gx * d.x() - Gy * d.y());
    }
    a[i] += k * s;
  }
}

Tensor2 Body2D::smoothed_cauchy(int i) const {
  Tensor2 s = Tensor2::Zero();
  double w = 0;
  for (SparseMatrix::InnerIterator it(m_.W, i); it; ++it) {
    if (it.col() >= nr_) continue;
    s += it.value() * cauchy(static_cast<int>(it.col()));
    w += it.value();
  }
  return s / w;
}

bool Body2D::finite() const {
  for (int c = 0; c < 2; ++c) if (!u_[c].head(nr_).allFinite()) return false;
  for (const auto& p : P_) if (!p.head(nr_).allFinite()) return false;
  return true;
}

}  // namespace sph
