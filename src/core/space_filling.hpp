// An order of the particles along a space-filling curve (Morton / Z-order of the cells of side `cell` that
// cover `box`): particles close in space get close indices, so the neighbours of a particle sit close in
// memory. Reorder (fields.hpp) applies the order to every field of a state.
#pragma once

#include <cstdint>
#include <vector>

#include "core/neighbours.hpp"
#include "core/types.hpp"

namespace sph {

/// order[i] = index of the particle that goes to position i (a permutation of 0 .. x.size() - 1). Particles
/// outside a non-periodic box are clamped to its edge cells; equal cells keep their relative order.
std::vector<std::uint32_t> morton_order(const std::vector<Vec2>& x, const Box2& box, double cell);

}  // namespace sph
