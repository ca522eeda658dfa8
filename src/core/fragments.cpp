#include "core/fragments.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace sph {

std::size_t Fragments::largest() const { return sizes.empty() ? 0 : *std::max_element(sizes.begin(), sizes.end()); }

Fragments find_fragments(const std::vector<Vec2>& x, const Box2& box, double link, const std::vector<bool>& include) {
  const std::size_t n = x.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  auto in = [&](std::size_t i) { return include.empty() || include[i]; };
  CellList2D cells(box, link);
  cells.build(x);
  for (std::size_t i = 0; i < n; ++i) {
    if (!in(i)) continue;
    cells.for_each_neighbour(x, i, link, [&](std::size_t j, const Vec2&, double) {
      if (j < i && in(j)) {
        const std::size_t ri = find(i), rj = find(j);
        if (ri != rj) parent[std::max(ri, rj)] = std::min(ri, rj);
      }
    });
  }
  Fragments f;
  f.label.assign(n, SIZE_MAX);
  std::vector<std::size_t> piece_of_root(n, SIZE_MAX);
  for (std::size_t i = 0; i < n; ++i) {
    if (!in(i)) continue;
    const std::size_t r = find(i);
    if (piece_of_root[r] == SIZE_MAX) {
      piece_of_root[r] = f.count++;
      f.sizes.push_back(0);
    }
    f.label[i] = piece_of_root[r];
    ++f.sizes[f.label[i]];
  }
  return f;
}

}  // namespace sph
