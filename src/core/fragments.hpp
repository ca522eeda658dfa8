// Automatic fracture detection: the number of connected pieces of a particle set, two particles being
// linked when they are closer than a link distance. An intact body is one piece; the unphysical
// "fracture" of the tensile instability opens gaps wider than the particle spacing and splits it.
#pragma once

#include <cstddef>
#include <vector>

#include "core/neighbours.hpp"

namespace sph {

struct Fragments {
  std::size_t count = 0;               ///< number of connected pieces
  std::vector<std::size_t> label;      ///< piece of each particle (0 .. count-1); SIZE_MAX for excluded
  std::vector<std::size_t> sizes;      ///< particles per piece, largest first order not guaranteed
  std::size_t largest() const;
};

/// Connected components of the particles with include[i] true (all if `include` is empty), linked at
/// distance < link. Union-find over a cell list: O(N).
Fragments find_fragments(const std::vector<Vec2>& x, const Box2& box, double link,
                         const std::vector<bool>& include = {});

}  // namespace sph
