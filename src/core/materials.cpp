// Material parameters and wave speeds (the stress laws are inline in materials.hpp). One section per law,
// in the order of materials.hpp.
#include "core/materials.hpp"

#include <stdexcept>
#include <string>

namespace sph {

namespace {
void require_positive(double v, const char* what) {
  if (!(v > 0.0)) throw std::invalid_argument(std::string(what) + " must be > 0, got " + std::to_string(v));
}
void require_non_negative(double v, const char* what) {
  if (!(v >= 0.0)) throw std::invalid_argument(std::string(what) + " must be >= 0, got " + std::to_string(v));
}
}  // namespace

// ----- 1. Elastic constants ---------------------------------------------------------------------------

Lame lame_from_young_poisson(double E, double nu) {
  require_positive(E, "Young's modulus E");
  // -1 < nu < 1/2 keeps both the shear and the bulk modulus positive (a stable isotropic solid).
  if (!(nu > -1.0 && nu < 0.5))
    throw std::invalid_argument("Poisson's ratio must lie in (-1, 1/2), got " + std::to_string(nu));
  return {E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), E / (2.0 * (1.0 + nu))};
}

double young_modulus(const Lame& m) { return m.mu * (3.0 * m.lambda + 2.0 * m.mu) / (m.lambda + m.mu); }

double poisson_ratio(const Lame& m) { return m.lambda / (2.0 * (m.lambda + m.mu)); }

double bulk_modulus(const Lame& m) { return m.lambda + 2.0 * m.mu / 3.0; }

// ----- 2. Wave speeds ---------------------------------------------------------------------------------

double longitudinal_wave_speed(const Lame& m, double rho) {
  require_positive(rho, "density");
  require_non_negative(p_wave_modulus(m), "lambda + 2 mu");
  return std::sqrt(p_wave_modulus(m) / rho);
}

double bar_wave_speed(double E, double rho) {
  require_positive(rho, "density");
  require_non_negative(E, "Young's modulus E");
  return std::sqrt(E / rho);
}

double transverse_wave_speed(const Lame& m, double rho) {
  require_positive(rho, "density");
  require_non_negative(m.mu, "shear modulus mu");
  return std::sqrt(m.mu / rho);
}

}  // namespace sph
