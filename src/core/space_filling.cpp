#include "core/space_filling.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace sph {

namespace {

// Spreads the low 32 bits of v to the even bits of a 64-bit word.
std::uint64_t spread_bits(std::uint64_t v) {
  v &= 0xffffffffULL;
  v = (v | (v << 16)) & 0x0000ffff0000ffffULL;
  v = (v | (v << 8)) & 0x00ff00ff00ff00ffULL;
  v = (v | (v << 4)) & 0x0f0f0f0f0f0f0f0fULL;
  v = (v | (v << 2)) & 0x3333333333333333ULL;
  v = (v | (v << 1)) & 0x5555555555555555ULL;
  return v;
}

std::uint32_t cell_of(double v, double vmin, double L, double cell, bool periodic) {
  double t = (v - vmin) / L;
  if (periodic) t -= std::floor(t);
  const double n = std::max(1.0, std::floor(L / cell)), c = std::floor(t * n);
  return static_cast<std::uint32_t>(c < 0 ? 0 : (c >= n ? n - 1 : c));
}

}  // namespace

std::vector<std::uint32_t> morton_order(const std::vector<Vec2>& x, const Box2& box, double cell) {
  if (!(cell > 0) || !(box.Lx() > 0) || !(box.Ly() > 0)) throw std::invalid_argument("morton_order: need cell > 0 and a non-empty box");
  std::vector<std::uint64_t> key(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    key[i] = spread_bits(cell_of(x[i].x(), box.xmin, box.Lx(), cell, box.periodic_x)) |
             (spread_bits(cell_of(x[i].y(), box.ymin, box.Ly(), cell, box.periodic_y)) << 1);
  std::vector<std::uint32_t> order(x.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
  return order;
}

}  // namespace sph
