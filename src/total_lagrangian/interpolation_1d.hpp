// SPH interpolation of a known function on a line of particles (Ismail 2009, Sections 2.3-2.8).
//
//   <f>(x_p)  =   sum_q f(x_q) W(x_p - x_q, h) dV_q                                  eq (2.24)
//   <f'>(x_p) = - sum_q f(x_q) d/dx W(x_p - x, h)|_{x = x_q} dV_q
//             =   sum_q f(x_q) dW/dr(|x_p - x_q|, h) sign(x_p - x_q) dV_q           eq (2.25)
//
// Eq (2.25) is used as printed (no f_p subtracted), so without ghost particles the boundary deficit of
// sum_q W dV also spoils the gradient, as the thesis's Fig 2.10 shows. Ghost particles (Section 2.8.1,
// Fig 2.24) continue the lattice beyond the ends and carry the function "extended beyond the end points"
// (Section 2.7); they are ordinary summation partners.
//
// Particles are kept sorted by position, so the neighbours of x are one contiguous index range found by
// binary search: O(N x neighbours), no N x N matrices (the thesis's eqs 2.31-2.34 are the same sums).
#pragma once

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

namespace sph {

/// Particles on a line, sorted by position. Real particles are [first_real, first_real + n_real); the
/// others are ghosts.
struct ParticleLine {
  std::vector<double> x;       // positions, ascending
  std::vector<double> volume;  // dV_q (length per particle in 1D)
  std::size_t first_real = 0, n_real = 0;
  std::size_t size() const { return x.size(); }
  bool is_real(std::size_t i) const { return i >= first_real && i < first_real + n_real; }
};

/// Particles x_i = a + i ps for i = 0..N with N = (b - a) / ps (must be an integer to 1e-9: the end
/// particles sit on the boundary, like the boundary particles of Fig 2.25), each with dV = ps, plus
/// ghosts continuing the lattice out to `ghost_width` beyond each end (0 = no ghosts).
ParticleLine uniform_line(double a, double b, double ps, double ghost_width);

/// Index range [lo, hi) of the particles with |x_q - x| < radius.
std::pair<std::size_t, std::size_t> neighbour_range(const ParticleLine& line, double x, double radius);

/// sum_q g(x_p, x_q) over the particles within the support of particle p, for every p.
template <class Term>
std::vector<double> particle_sums(const ParticleLine& line, double radius, Term term) {
  std::vector<double> out(line.size(), 0.0);
  for (std::size_t p = 0; p < line.size(); ++p) {
    const auto [lo, hi] = neighbour_range(line, line.x[p], radius);
    double s = 0.0;
    for (std::size_t q = lo; q < hi; ++q) s += term(p, q);
    out[p] = s;
  }
  return out;
}

/// Eq (2.24) at every particle. `weight_scale` multiplies W: 1 keeps the cover function's own integral
/// normalisation (eq 2.19); 1 / lattice_sum_of_weights(...) normalises it on the particle lattice.
template <class K>
std::vector<double> sph_value(const K& kernel, double h, const ParticleLine& line, const std::vector<double>& f,
                              double weight_scale = 1.0) {
  if (f.size() != line.size()) throw std::invalid_argument("sph_value: one value per particle required");
  return particle_sums(line, kernel.support() * h, [&](std::size_t p, std::size_t q) {
    return f[q] * weight_scale * kernel.W(std::abs(line.x[p] - line.x[q]), h) * line.volume[q];
  });
}

/// Eq (2.25) at every particle (dW/dr = 0 at r = 0, so the self term vanishes).
template <class K>
std::vector<double> sph_gradient(const K& kernel, double h, const ParticleLine& line, const std::vector<double>& f,
                                 double weight_scale = 1.0) {
  if (f.size() != line.size()) throw std::invalid_argument("sph_gradient: one value per particle required");
  return particle_sums(line, kernel.support() * h, [&](std::size_t p, std::size_t q) {
    const double d = line.x[p] - line.x[q];
    if (d == 0.0) return 0.0;
    return f[q] * weight_scale * kernel.dWdr(std::abs(d), h) * (d > 0 ? 1.0 : -1.0) * line.volume[q];
  });
}

/// sum_q W(x_p - x_q, h) dV_q at every particle: 1 where the cover is full and well sampled; its deficit
/// at an end particle without ghosts is the boundary "droop" of Section 2.7.
template <class K>
std::vector<double> sum_of_weights(const K& kernel, double h, const ParticleLine& line, double weight_scale = 1.0) {
  return sph_value(kernel, h, line, std::vector<double>(line.size(), 1.0), weight_scale);
}

/// sum_j W(j ps, h) ps over the infinite uniform lattice: the interior value of sum_of_weights.
template <class K>
double lattice_sum_of_weights(const K& kernel, double h, double ps) {
  const double radius = kernel.support() * h;
  double s = kernel.W(0.0, h);
  for (int j = 1; j * ps < radius; ++j) s += 2.0 * kernel.W(j * ps, h);
  return s * ps;
}

/// <x'> of f(x) = x at an interior particle of the infinite uniform lattice, eq (2.25):
/// 2 sum_{j>0} j ps |dW/dr(j ps)| ps. Exactly 1 in the continuum; its error is the lattice
/// ("(dx/h)^2", eq 2.35) part of the gradient error, which refinement at fixed h/ps does not reduce.
template <class K>
double lattice_gradient_of_linear(const K& kernel, double h, double ps) {
  const double radius = kernel.support() * h;
  double s = 0.0;
  for (int j = 1; j * ps < radius; ++j) s -= 2.0 * j * ps * kernel.dWdr(j * ps, h);
  return s * ps;
}

}  // namespace sph
