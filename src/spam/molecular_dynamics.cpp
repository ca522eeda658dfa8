#include "spam/molecular_dynamics.hpp"

#include <cmath>
#include <stdexcept>

#include "core/blow_up.hpp"
#include "core/neighbours.hpp"

namespace sph {

MdSolver::MdSolver(const std::vector<Vec2>& reference, const MdState& initial, const MdParams& p) : p_(p), y_(initial) {
  if (!(p.mass > 0) || !(p.bond_cutoff > 0) || !(p.rest_length > 0))
    throw std::invalid_argument("MdSolver: need mass, rest length and bond cutoff > 0");
  if (initial.x.size() != reference.size() || initial.v.size() != reference.size())
    throw std::invalid_argument("MdSolver: the initial state must have one position and velocity per reference particle");
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

void MdSolver::derivative(const MdState& y, MdState& dy) const {
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

double MdSolver::potential_energy() const {
  const MdState& y = y_;
  double u = 0;
  for (const auto& [i, j] : bonds_) {
    const double s = p_.rest_length - (y.x[i] - y.x[j]).norm();
    u += 0.5 * p_.spring * s * s;
  }
  return u;
}

void MdSolver::step(double dt) {
  rk_.step(y_, t_, dt, [this](double, const MdState& s, MdState& d) { derivative(s, d); });
  t_ += dt;
  ++steps_;
  const std::size_t bad = first_bad_particle(y_.x.size(), [this](std::size_t i) { return !(y_.x[i].allFinite() && y_.v[i].allFinite()); });
  if (bad < y_.x.size()) throw_blow_up(steps_, t_, bad, y_.x[bad], "non-finite position or velocity");
}

}  // namespace sph
