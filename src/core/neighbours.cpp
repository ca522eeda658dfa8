#include "core/neighbours.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sph {

void CellList2D::build(const std::vector<Vec2>& x) {
  const std::size_t n = x.size();
  cell_of_.resize(n);
  sorted_.resize(n);
  std::fill(cell_start_.begin(), cell_start_.end(), 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x[i].x()) || !std::isfinite(x[i].y()))
      throw std::runtime_error("CellList2D: particle " + std::to_string(i) + " has a non-finite position");
    const std::size_t c = static_cast<std::size_t>(cell_y(x[i].y())) * nx_ + cell_x(x[i].x());
    cell_of_[i] = c;
    ++cell_start_[c + 1];
  }
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  // Stable fill: temporarily use cell_start_ shifted as insertion cursors, then restore.
  for (std::size_t i = 0; i < n; ++i) sorted_[cell_start_[cell_of_[i]]++] = i;
  for (std::size_t c = cell_start_.size() - 1; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
  cell_start_[0] = 0;
  x_sorted_.resize(n);
  for (std::size_t k = 0; k < n; ++k) x_sorted_[k] = x[sorted_[k]];
}

std::vector<std::vector<std::size_t>> brute_force_neighbours(const std::vector<Vec2>& x, const Box2& box,
                                                             double radius) {
  CellList2D metric(box, radius);  // only for its minimum-image displacement
  std::vector<std::vector<std::size_t>> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j)
      if (j != i && metric.displacement(x[i], x[j]).norm() < radius) out[i].push_back(j);
  return out;
}

Box2 bounding_box(const std::vector<Vec2>& points) {
  if (points.empty()) throw std::invalid_argument("bounding_box: no points");
  Box2 box;
  box.xmin = box.xmax = points.front().x();
  box.ymin = box.ymax = points.front().y();
  for (const Vec2& p : points) {
    box.xmin = std::min(box.xmin, p.x()); box.xmax = std::max(box.xmax, p.x());
    box.ymin = std::min(box.ymin, p.y()); box.ymax = std::max(box.ymax, p.y());
  }
  return box;
}

}  // namespace sph
