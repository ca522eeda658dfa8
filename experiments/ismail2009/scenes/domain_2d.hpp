// Shared scene code for the 2D total Lagrangian runs of Ismail 2009 Section 5.4 (I-2d, I-hole, bench_tl_hole):
// a domain on a square lattice (real particles inside, ghosts within one cover outside), and for every ghost
// the boundary point it mirrors through (src/total_lagrangian/boundary_2d.hpp): the nearest piece of boundary whose
// mirror point lies in the body, else a corner (point reflection).
#pragma once

#include <functional>
#include <vector>

#include "total_lagrangian/body_2d.hpp"

namespace scenes {

struct BoundaryPiece {
  /// Projects X onto the piece: true and (Xb, outward normal n) if the projection lies on the piece.
  std::function<bool(const sph::Vec2& X, sph::Vec2& Xb, sph::Vec2& n)> project;
  int condition = 0;
};

struct Corner {
  sph::Vec2 C, nA, nB;  ///< the point and the outward normals of the two pieces meeting there
  int piece_a = 0, piece_b = 0;
};

struct Domain2D {
  std::function<bool(const sph::Vec2&)> inside;  ///< closed body (boundary included)
  std::vector<BoundaryPiece> pieces;
  std::vector<Corner> corners;
  sph::Vec2 lo, hi;  ///< bounding box of the body
};

/// Rectangle [0, Lx] x [0, Ly]; conditions of the left, right, bottom and top edges.
Domain2D rectangle_domain(double Lx, double Ly, int left, int right, int bottom, int top);
/// Quarter of a square plate [0, a]^2 with a hole of radius R at the origin: edges x = 0 (left, y >= R),
/// y = 0 (bottom, x >= R), x = a (right), y = a (top) and the hole arc.
Domain2D quarter_hole_domain(double a, double R, int left, int bottom, int right, int top, int hole);

/// Real particles (lattice points (i ps, j ps) in the body), ghosts, boundary rules and Dirichlet particles
/// of a body on `dom`; material and kernel fields of the returned config are left for the caller.
sph::TlConfig2D make_body(const Domain2D& dom, std::vector<sph::BoundaryCondition2D> conditions, double ps,
                            double h_over_ps);

}  // namespace scenes
