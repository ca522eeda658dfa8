#include "ismail2009/scenes/domain_2d.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "core/kernels.hpp"
#include "core/lattices.hpp"
#include "core/neighbours.hpp"

namespace scenes {

using sph::Vec2;

namespace {

BoundaryPiece segment(Vec2 a, Vec2 b, Vec2 n, int condition) {
  BoundaryPiece p;
  p.condition = condition;
  p.project = [a, b, n](const Vec2& X, Vec2& Xb, Vec2& nn) {
    const Vec2 d = b - a;
    const double s = (X - a).dot(d) / d.squaredNorm();
    if (s < -1e-12 || s > 1 + 1e-12) return false;
    Xb = a + s * d;
    nn = n;
    return true;
  };
  return p;
}

/// Lattice points (i ps, j ps) over the body's bounding box widened by g spacings: those in the body into
/// `real`, the others into `outside`.
void lattice_points(const Domain2D& dom, double ps, int g, std::vector<Vec2>& real, std::vector<Vec2>& outside) {
  const int i0 = static_cast<int>(std::floor(dom.lo.x() / ps + 1e-9)) - g, i1 = static_cast<int>(std::ceil(dom.hi.x() / ps - 1e-9)) + g;
  const int j0 = static_cast<int>(std::floor(dom.lo.y() / ps + 1e-9)) - g, j1 = static_cast<int>(std::ceil(dom.hi.y() / ps - 1e-9)) + g;
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const Vec2 X(i * ps, j * ps);
      (dom.inside(X) ? real : outside).push_back(X);
    }
}

/// Ghosts: outside points with a real particle within a cover (brute force over a local window of the
/// lattice would do; the cell list keeps it O(N)).
std::vector<Vec2> ghosts_near(const Domain2D& dom, const std::vector<Vec2>& real, const std::vector<Vec2>& outside,
                              double ps, int g, double radius) {
  std::vector<Vec2> ghosts;
  std::vector<Vec2> pts = real;
  pts.insert(pts.end(), outside.begin(), outside.end());
  sph::Box2 box{dom.lo.x() - (g + 1) * ps, dom.lo.y() - (g + 1) * ps, dom.hi.x() + (g + 1) * ps, dom.hi.y() + (g + 1) * ps};
  sph::CellList2D cells(box, radius);
  cells.build(pts);
  const std::size_t nr = real.size();
  for (std::size_t k = 0; k < outside.size(); ++k) {
    bool near = false;
    cells.for_each_neighbour(pts, nr + k, radius, [&](std::size_t j, const Vec2&, double) { near = near || j < nr; });
    if (near) ghosts.push_back(outside[k]);
  }
  return ghosts;
}

/// A corner condition of its own for a ghost in the direction n from corner c: Dirichlet components from
/// either piece, else the traction of the normal n = alpha nA + beta nB: t = alpha tA + beta tB.
sph::BoundaryCondition2D corner_condition(const Domain2D& dom, const Corner& c,
                                          const std::vector<sph::BoundaryCondition2D>& conditions, const Vec2& n) {
  Eigen::Matrix2d M;
  M << c.nA.x(), c.nB.x(), c.nA.y(), c.nB.y();
  const Vec2 ab = M.fullPivLu().solve(n);
  const auto A = conditions.at(dom.pieces[c.piece_a].condition), B = conditions.at(dom.pieces[c.piece_b].condition);
  sph::BoundaryCondition2D bc;
  for (int k = 0; k < 2; ++k) {
    bc.dirichlet[k] = A.dirichlet[k] || B.dirichlet[k];
    if (A.dirichlet[k]) bc.value[k] = A.value[k];
    else if (B.dirichlet[k]) bc.value[k] = B.value[k];
    else {
      const auto fa = A.value[k], fb = B.value[k];
      const double al = ab.x(), be = ab.y();
      bc.value[k] = [fa, fb, al, be](const Vec2& X, double t) { return al * fa(X, t) + be * fb(X, t); };
    }
  }
  return bc;
}

/// Boundary rule of the ghost Xg: the nearest piece (or corner) whose mirror point lies in the body. Every
/// nearer corner met appends its corner condition to `conditions`.
sph::BoundaryPoint2D ghost_rule(const Domain2D& dom, std::vector<sph::BoundaryCondition2D>& conditions, const Vec2& Xg) {
  sph::BoundaryPoint2D best;
  double bd = std::numeric_limits<double>::infinity();
  for (const auto& p : dom.pieces) {
    Vec2 Xb, n;
    if (!p.project(Xg, Xb, n)) continue;
    const double dist = (Xg - Xb).norm();
    if (dist < bd && dom.inside(2.0 * Xb - Xg) && (Xg - Xb).dot(n) > 0) { bd = dist; best = {Xb, n, p.condition}; }
  }
  if (!std::isfinite(bd)) {
    for (const auto& c : dom.corners) {
      const double dist = (Xg - c.C).norm();
      if (dist >= bd || !dom.inside(2.0 * c.C - Xg)) continue;
      bd = dist;
      const Vec2 n = (Xg - c.C) / dist;
      conditions.push_back(corner_condition(dom, c, conditions, n));
      best = {c.C, n, static_cast<int>(conditions.size()) - 1};
    }
  }
  if (!std::isfinite(bd)) throw std::runtime_error("make_body: no boundary point mirrors a ghost into the body");
  return best;
}

/// The real particles on a piece with a Dirichlet component, and those on a piece with a traction component
/// with their share of its length (half at a corner of two such pieces): the boundary forces of the
/// variational scheme.
void mark_boundary_particles(const Domain2D& dom, const std::vector<sph::BoundaryCondition2D>& conditions, double ps,
                             sph::TlConfig2D& cfg) {
  for (std::size_t i = 0; i < cfg.real.size(); ++i)
    for (const auto& p : dom.pieces) {
      Vec2 Xb, n;
      const auto& bc = conditions[p.condition];
      if ((bc.dirichlet[0] || bc.dirichlet[1]) && p.project(cfg.real[i], Xb, n) && (Xb - cfg.real[i]).norm() < 1e-9 * ps)
        cfg.real_on_dirichlet.emplace_back(static_cast<int>(i), p.condition);
    }
  for (std::size_t i = 0; i < cfg.real.size(); ++i) {
    std::vector<int> on;
    for (const auto& p : dom.pieces) {
      Vec2 Xb, n;
      if (p.project(cfg.real[i], Xb, n) && (Xb - cfg.real[i]).norm() < 1e-9 * ps) on.push_back(p.condition);
    }
    for (int cnd : on)
      if (!conditions[cnd].dirichlet[0] || !conditions[cnd].dirichlet[1])
        cfg.real_on_traction.emplace_back(static_cast<int>(i), cnd, on.size() > 1 ? 0.5 * ps : ps);
  }
}

}  // namespace

Domain2D rectangle_domain(double Lx, double Ly, int left, int right, int bottom, int top) {
  Domain2D d;
  const double e = 1e-9 * std::max(Lx, Ly);
  d.inside = [=](const Vec2& X) { return X.x() > -e && X.x() < Lx + e && X.y() > -e && X.y() < Ly + e; };
  d.pieces = {segment({0, 0}, {0, Ly}, {-1, 0}, left), segment({Lx, 0}, {Lx, Ly}, {1, 0}, right),
              segment({0, 0}, {Lx, 0}, {0, -1}, bottom), segment({0, Ly}, {Lx, Ly}, {0, 1}, top)};
  d.corners = {{{0, 0}, {-1, 0}, {0, -1}, 0, 2}, {{Lx, 0}, {1, 0}, {0, -1}, 1, 2},
               {{0, Ly}, {-1, 0}, {0, 1}, 0, 3}, {{Lx, Ly}, {1, 0}, {0, 1}, 1, 3}};
  d.lo = {0, 0};
  d.hi = {Lx, Ly};
  return d;
}

Domain2D quarter_hole_domain(double a, double R, int left, int bottom, int right, int top, int hole) {
  if (!(R > 0 && R < a)) throw std::invalid_argument("quarter_hole_domain: need 0 < R < a");
  Domain2D d;
  const double e = 1e-9 * a;
  d.inside = [=](const Vec2& X) {
    return X.x() > -e && X.x() < a + e && X.y() > -e && X.y() < a + e && X.norm() > R - e;
  };
  BoundaryPiece arc;
  arc.condition = hole;
  arc.project = [R](const Vec2& X, Vec2& Xb, Vec2& n) {
    const double r = X.norm();
    if (r < 1e-12 || X.x() < -1e-12 || X.y() < -1e-12) return false;
    n = -X / r;  // outward from the body = into the hole
    Xb = R * X / r;
    return true;
  };
  d.pieces = {segment({0, R}, {0, a}, {-1, 0}, left), segment({R, 0}, {a, 0}, {0, -1}, bottom),
              segment({a, 0}, {a, a}, {1, 0}, right), segment({0, a}, {a, a}, {0, 1}, top), arc};
  d.corners = {{{0, R}, {-1, 0}, {0, -1}, 0, 4}, {{R, 0}, {0, -1}, {-1, 0}, 1, 4},
               {{a, 0}, {1, 0}, {0, -1}, 2, 1}, {{0, a}, {-1, 0}, {0, 1}, 0, 3}, {{a, a}, {1, 0}, {0, 1}, 2, 3}};
  d.lo = {0, 0};
  d.hi = {a, a};
  return d;
}

sph::TlConfig2D make_body(const Domain2D& dom, std::vector<sph::BoundaryCondition2D> conditions, double ps,
                            double h_over_ps) {
  sph::TlConfig2D cfg;
  cfg.ps = ps;
  cfg.h_over_ps = h_over_ps;
  const double radius = h_over_ps * ps * sph::ModifiedMollifierShape::support;
  sph::check_particle_count((dom.hi.x() - dom.lo.x()) * (dom.hi.y() - dom.lo.y()) / (ps * ps), ps, "make_body");
  const int g = static_cast<int>(std::ceil(radius / ps));
  std::vector<Vec2> outside;
  lattice_points(dom, ps, g, cfg.real, outside);
  cfg.ghosts = ghosts_near(dom, cfg.real, outside, ps, g, radius);
  auto pieces_of = std::make_shared<std::vector<sph::BoundaryPoint2D>>();
  for (const auto& Xg : cfg.ghosts) pieces_of->push_back(ghost_rule(dom, conditions, Xg));
  mark_boundary_particles(dom, conditions, ps, cfg);
  cfg.conditions = std::move(conditions);
  auto ghosts = std::make_shared<std::vector<Vec2>>(cfg.ghosts);
  cfg.ghost_boundary = [ghosts, pieces_of](const Vec2& Xg) {
    for (std::size_t k = 0; k < ghosts->size(); ++k)
      if ((*ghosts)[k] == Xg) return (*pieces_of)[k];
    throw std::invalid_argument("ghost_boundary: not a ghost of this body");
  };
  return cfg;
}

}  // namespace scenes
