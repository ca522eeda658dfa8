// Particle generators: regular lattices and the shapes cut from them.
//
// Square: points (i dp, j dp). Face-centred (Gray et al. 2001, Section 5.3.2): square rows with every
// second row shifted by dp/2. Triangular (Hoover et al. 2004): rows dp sqrt(3)/2 apart, every second
// row shifted by dp/2, nearest-neighbour distance dp. All positions are 2D Eigen vectors.
#pragma once

#include <string>
#include <vector>

#include "core/types.hpp"

namespace sph {

enum class LatticeKind { Square, FaceCentred, Triangular };
LatticeKind lattice_kind_from_string(const std::string& name);  // square, face_centred, triangular
std::string to_string(LatticeKind kind);

/// Row spacing of a lattice with in-row spacing dp (dp for square/face-centred, dp sqrt(3)/2 triangular).
double row_spacing(LatticeKind kind, double dp);
/// Area per particle: dp^2, or dp^2 sqrt(3)/2 for the triangular lattice.
double area_per_particle(LatticeKind kind, double dp);

/// Refuses, before anything is allocated, a particle set that cannot fit in this machine's memory: `count`
/// particles (estimated by the generator from its extent and spacing) at a lower bound of 1 KiB per particle
/// (a particle's fields, its rates and its ~14-28 neighbour pairs in every formulation here take more), more
/// than the physical memory. Throws std::invalid_argument naming the shape, the spacing and the count. Every
/// generator below calls it, so a resolution typed wrong (dp = 1e-9) stops at once with that message.
void check_particle_count(double count, double spacing, const char* shape);

/// nx x ny block of a lattice with its first point at `origin`; rows with odd index are shifted by dp/2
/// for the face-centred and triangular kinds.
std::vector<Vec2> lattice_block(LatticeKind kind, int nx, int ny, double dp, Vec2 origin = Vec2::Zero());

/// The lattice points inside the rectangle [x0, x0 + Lx) x [y0, y0 + Ly), first point at
/// (x0 + dp/2, y0 + dp/2): each particle sits at the centre of its own dp x dp cell (square lattice).
/// For the other kinds rows are row_spacing apart starting half a row spacing above y0; the shifted rows
/// start at x0 itself, so that with Lx a whole number of dp every row has Lx/dp points and the block tiles
/// periodically in x (and in y when the number of rows is even).
std::vector<Vec2> rectangle(LatticeKind kind, double x0, double y0, double Lx, double Ly, double dp);

/// Lattice points with r_inner <= |x - centre| < r_outer, from a lattice of spacing dp through `centre`.
std::vector<Vec2> ring(LatticeKind kind, Vec2 centre, double r_inner, double r_outer, double dp);

/// Regular hexagon of a triangular lattice with `shells` rings around the centre particle:
/// 3 shells (shells + 1) + 1 particles (217 for shells = 8, Hoover et al. 2004 Fig 4), spacing dp,
/// vertices along +-x.
std::vector<Vec2> hexagon(int shells, double dp, Vec2 centre = Vec2::Zero());

/// Copies of `points` shifted by (i Lx, j Ly) for |i|, |j| <= layers, excluding (0, 0) when
/// `include_original` is false: the periodic images used by lattice sums.
std::vector<Vec2> periodic_images(const std::vector<Vec2>& points, double Lx, double Ly, int layers,
                                  bool include_original = true);

}  // namespace sph
