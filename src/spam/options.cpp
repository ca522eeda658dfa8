#include "spam/options.hpp"

#include <stdexcept>

namespace sph {

std::string to_string(SpamDensity d) { return d == SpamDensity::Summation ? "sum" : "cont"; }

std::string to_string(SpamAdvection a) {
  switch (a) {
    case SpamAdvection::Velocity: return "v";
    case SpamAdvection::Shepard: return "shepard";
    case SpamAdvection::MonaghanArithmetic: return "monaghan_arith";
    case SpamAdvection::MonaghanGeometric: return "monaghan_geom";
  }
  return "?";
}

std::string to_string(SpamTorque t) {
  switch (t) {
    case SpamTorque::None: return "none";
    case SpamTorque::PairScaling: return "pair_torque";
    case SpamTorque::ParticleScaling: return "particle_torque";
    case SpamTorque::Gauss: return "gauss";
  }
  return "?";
}

SpamDensity spam_density_from_string(const std::string& s) {
  if (s == "sum") return SpamDensity::Summation;
  if (s == "cont") return SpamDensity::Continuity;
  throw std::invalid_argument("unknown SPAM density '" + s + "' (sum, cont)");
}

SpamAdvection spam_advection_from_string(const std::string& s) {
  for (auto a : {SpamAdvection::Velocity, SpamAdvection::Shepard, SpamAdvection::MonaghanArithmetic,
                 SpamAdvection::MonaghanGeometric})
    if (s == to_string(a)) return a;
  throw std::invalid_argument("unknown SPAM advection '" + s + "' (v, shepard, monaghan_arith, monaghan_geom)");
}

SpamTorque spam_torque_from_string(const std::string& s) {
  for (auto t : {SpamTorque::None, SpamTorque::PairScaling, SpamTorque::ParticleScaling, SpamTorque::Gauss})
    if (s == to_string(t)) return t;
  throw std::invalid_argument("unknown SPAM torque treatment '" + s + "' (none, pair_torque, particle_torque, gauss)");
}

std::string SpamOptions::label() const {
  std::string s = to_string(density) + "/" + to_string(advection);
  if (chain_rule) s += "/chain";
  if (torque != SpamTorque::None) s += "/" + to_string(torque);
  if (viscosity) s += "/visc";
  if (closest_approach) s += "/approach";
  return s;
}

}  // namespace sph
