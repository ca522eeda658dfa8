#include "spam/molecular_dynamics.hpp"

#include <cmath>
#include <stdexcept>

#include "core/neighbours.hpp"

namespace sph {

MolecularDynamics::MolecularDynamics(const std::vector<Vec2>& reference, const MdParams& p) : p_(p) {
  if (!(p.mass > 0) || !(p.bond_cutoff > 0) || !(p.rest_length > 0))
    throw std::invalid_argument("MolecularDynamics: need mass, rest length and bond cutoff > 0");
  const std::size_t n = reference.size();
  Box2 box = bounding_box(reference);
  box.xmax += 1e-9 + p.bond_cutoff; box.ymax += 1e-9 + p.bond_cutoff;
  CellList2D cells(box, p.bond_cutoff);
  cells.build(reference);
  std::vector<std::vector<std::size_t>> adj(n);
  for (std::size_t i = 0; i < n; ++i)
    cells.for_each_neighbour(reference, i, p.bond_cutoff, [&](std::size_t j, const Vec2&, double) {
      adj[i].push_back(j);
      if (i < j) bonds_.emplace_back(i, j);
    });
  start_.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) start_[i + 1] = start_[i] + adj[i].size();
  partner_.reserve(start_[n]);
  for (const auto& a : adj) partner_.insert(partner_.end(), a.begin(), a.end());
}

void MolecularDynamics::derivative(const MdState& y, MdState& dy) const {
  const long n = static_cast<long>(y.x.size());
  const double k_over_m = p_.spring / p_.mass;
#pragma omp parallel for schedule(static) if (n >= 1000)
  for (long i = 0; i < n; ++i) {
    Vec2 a = Vec2::Zero();
    for (std::size_t b = start_[i]; b < start_[i + 1]; ++b) {
      const Vec2 d = y.x[i] - y.x[partner_[b]];
      const double r = d.norm();
      a += (k_over_m * (p_.rest_length - r) / r) * d;  // F = -dphi/dr along the bond
    }
    dy.x[i] = y.v[i];
    dy.v[i] = a;
  }
}

double MolecularDynamics::potential_energy(const MdState& y) const {
  double u = 0;
  for (const auto& [i, j] : bonds_) {
    const double s = p_.rest_length - (y.x[i] - y.x[j]).norm();
    u += 0.5 * p_.spring * s * s;
  }
  return u;
}

void MolecularDynamics::step(MdState& y, double t, double dt) {
  rk_.step(y, t, dt, [this](double, const MdState& s, MdState& d) { derivative(s, d); });
}

}  // namespace sph
