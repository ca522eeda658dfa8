#include "total_lagrangian/interpolation_1d.hpp"

#include <algorithm>
#include <string>

#include "core/lattices.hpp"

namespace sph {

ParticleLine uniform_line(double a, double b, double ps, double ghost_width) {
  if (!(ps > 0.0) || !(b > a)) throw std::invalid_argument("uniform_line: need b > a and ps > 0");
  if (ghost_width < 0.0) throw std::invalid_argument("uniform_line: ghost_width must be >= 0");
  const double spans = (b - a) / ps;
  check_particle_count(spans, ps, "uniform_line");
  const long n = std::lround(spans);
  if (n < 1 || std::abs(spans - n) > 1e-9 * std::max(1.0, spans))
    throw std::invalid_argument("uniform_line: (b - a) / ps = " + std::to_string(spans) + " is not an integer");
  // Ghosts strictly within ghost_width of the end particles (a small slack absorbs rounding).
  const long g = ghost_width > 0.0 ? static_cast<long>(std::floor(ghost_width / ps + 1e-9)) : 0;
  ParticleLine line;
  for (long i = -g; i <= n + g; ++i) {
    line.x.push_back(a + static_cast<double>(i) * ps);
    line.volume.push_back(ps);
  }
  line.first_real = static_cast<std::size_t>(g);
  line.n_real = static_cast<std::size_t>(n + 1);
  return line;
}

std::pair<std::size_t, std::size_t> neighbour_range(const ParticleLine& line, double x, double radius) {
  const auto lo = std::upper_bound(line.x.begin(), line.x.end(), x - radius);
  const auto hi = std::lower_bound(lo, line.x.end(), x + radius);
  return {static_cast<std::size_t>(lo - line.x.begin()), static_cast<std::size_t>(hi - line.x.begin())};
}

}  // namespace sph
