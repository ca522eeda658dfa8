#include "core/lattices.hpp"

#include <unistd.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sph {

LatticeKind lattice_kind_from_string(const std::string& name) {
  if (name == "square") return LatticeKind::Square;
  if (name == "face_centred") return LatticeKind::FaceCentred;
  if (name == "triangular") return LatticeKind::Triangular;
  throw std::invalid_argument("unknown lattice '" + name + "' (square, face_centred, triangular)");
}

std::string to_string(LatticeKind kind) {
  switch (kind) {
    case LatticeKind::Square: return "square";
    case LatticeKind::FaceCentred: return "face_centred";
    case LatticeKind::Triangular: return "triangular";
  }
  return "?";
}

double row_spacing(LatticeKind kind, double dp) {
  return kind == LatticeKind::Triangular ? dp * std::sqrt(3.0) / 2.0 : dp;
}

double area_per_particle(LatticeKind kind, double dp) { return dp * row_spacing(kind, dp); }

static double row_shift(LatticeKind kind, long row, double dp) {
  if (kind == LatticeKind::Square) return 0.0;
  return (row % 2 != 0) ? 0.5 * dp : 0.0;
}

// Finite and positive (false for NaN and infinity, which would make the generators loop or overflow).
static bool finite_positive(double v) { return std::isfinite(v) && v > 0; }

void check_particle_count(double count, double spacing, const char* shape) {
  constexpr double kBytesPerParticle = 1024.0;  // a lower bound (see the header)
  const double memory = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  if (std::isfinite(count) && (memory <= 0 || count * kBytesPerParticle <= memory)) return;
  std::ostringstream m;
  m << shape << " at spacing " << spacing << ": " << count << " particles, which need more than " << count * kBytesPerParticle
    << " bytes (1 KiB each), more than this machine's " << memory << " bytes of memory: use a coarser spacing";
  throw std::invalid_argument(m.str());
}

std::vector<Vec2> lattice_block(LatticeKind kind, int nx, int ny, double dp, Vec2 origin) {
  if (nx < 0 || ny < 0 || !finite_positive(dp) || !origin.allFinite())
    throw std::invalid_argument("lattice_block: need nx, ny >= 0, finite dp > 0 and a finite origin");
  check_particle_count(static_cast<double>(nx) * ny, dp, "lattice_block");
  std::vector<Vec2> pts;
  pts.reserve(static_cast<size_t>(nx) * ny);
  const double dy = row_spacing(kind, dp);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      pts.emplace_back(origin.x() + i * dp + row_shift(kind, j, dp), origin.y() + j * dy);
  return pts;
}

std::vector<Vec2> rectangle(LatticeKind kind, double x0, double y0, double Lx, double Ly, double dp) {
  if (!finite_positive(dp) || !finite_positive(Lx) || !finite_positive(Ly) || !std::isfinite(x0) || !std::isfinite(y0))
    throw std::invalid_argument("rectangle: need finite dp, Lx, Ly > 0 and a finite corner");
  check_particle_count(Lx * Ly / area_per_particle(kind, dp), dp, "rectangle");
  const double dy = row_spacing(kind, dp);
  const int ny = static_cast<int>(std::floor(Ly / dy + 1e-9));
  std::vector<Vec2> pts;
  for (int j = 0; j < ny; ++j) {
    const double y = y0 + (j + 0.5) * dy;
    // Shifted rows: the lattice point x0 + (-1 + 1/2) dp + dp/2 = x0 also lies in [x0, x0 + Lx); starting
    // at i = 0 would drop it, leaving those rows one particle short and the block not periodic in x.
    const double shift = row_shift(kind, j, dp);
    for (int i = shift > 0 ? -1 : 0;; ++i) {
      const double x = x0 + ((i + 0.5) * dp + shift);  // grouped: exactly x0 for the first shifted point
      if (x >= x0 + Lx - 1e-9 * dp) break;
      pts.emplace_back(x, y);
    }
  }
  return pts;
}

std::vector<Vec2> ring(LatticeKind kind, Vec2 centre, double r_inner, double r_outer, double dp) {
  if (!finite_positive(dp) || !(r_outer > r_inner) || !(r_inner >= 0) || !std::isfinite(r_outer) || !centre.allFinite())
    throw std::invalid_argument("ring: need 0 <= r_inner < r_outer finite, finite dp > 0 and centre");
  check_particle_count(4.0 * r_outer * r_outer / area_per_particle(kind, dp), dp, "ring");  // the square scanned
  const double dy = row_spacing(kind, dp);
  const long nj = static_cast<long>(std::ceil(r_outer / dy)) + 1;
  const long ni = static_cast<long>(std::ceil(r_outer / dp)) + 1;
  std::vector<Vec2> pts;
  for (long j = -nj; j <= nj; ++j)
    for (long i = -ni; i <= ni; ++i) {
      const Vec2 d(i * dp + row_shift(kind, j < 0 ? -j : j, dp), j * dy);
      const double r = d.norm();
      if (r >= r_inner && r < r_outer) pts.push_back(centre + d);
    }
  return pts;
}

std::vector<Vec2> hexagon(int shells, double dp, Vec2 centre) {
  if (shells < 0 || !finite_positive(dp)) throw std::invalid_argument("hexagon: need shells >= 0, dp > 0");
  check_particle_count(3.0 * shells * (shells + 1.0) + 1.0, dp, "hexagon");
  // Axial coordinates (a, b) with |a|, |b|, |a + b| <= shells on the basis e1 = (1, 0),
  // e2 = (1/2, sqrt(3)/2).
  std::vector<Vec2> pts;
  const Vec2 e1(dp, 0.0), e2(0.5 * dp, 0.5 * std::sqrt(3.0) * dp);
  for (int b = -shells; b <= shells; ++b)
    for (int a = -shells; a <= shells; ++a)
      if (std::abs(a + b) <= shells) pts.push_back(centre + a * e1 + b * e2);
  return pts;
}

std::vector<Vec2> periodic_images(const std::vector<Vec2>& points, double Lx, double Ly, int layers,
                                  bool include_original) {
  if (layers < 0) throw std::invalid_argument("periodic_images: need layers >= 0");
  std::vector<Vec2> out;
  out.reserve(points.size() * (2 * layers + 1) * (2 * layers + 1));
  for (int j = -layers; j <= layers; ++j)
    for (int i = -layers; i <= layers; ++i) {
      if (i == 0 && j == 0 && !include_original) continue;
      for (const Vec2& p : points) out.emplace_back(p.x() + i * Lx, p.y() + j * Ly);
    }
  return out;
}

}  // namespace sph
