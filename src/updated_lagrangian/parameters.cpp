#include "updated_lagrangian/parameters.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sph {

std::string GrayOptions::describe() const {
  std::ostringstream s;
  s << (artificial_stress ? "artstress" : "noartstress") << (xsph ? "+xsph" : "") << (viscosity ? "+visc" : "")
    << (summation_density ? "+sumdensity" : "+continuity") << (plasticity ? "+vonmises" : "");
  return s.str();
}

double GrayParameters::longitudinal_speed() const { return std::sqrt(c0 * c0 + 4.0 * mu / (3.0 * rho0)); }

double gray_time_step(const GrayParameters& p, double dp, double max_speed) {
  if (!(p.cfl > 0)) throw std::invalid_argument("time-step factor must be positive");
  const double h = p.h_over_dp * dp;
  return p.cfl * h / (p.longitudinal_speed() + max_speed);
}

}  // namespace sph
