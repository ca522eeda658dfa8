#include "core/kernels.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <memory>

namespace sph {

double unit_sphere_measure(int dim) {
  switch (dim) {
    case 1: return 2.0;
    case 2: return 2.0 * M_PI;
    case 3: return 4.0 * M_PI;
    default: throw std::invalid_argument("dimension must be 1, 2 or 3");
  }
}

template <class Shape>
double numerical_normalisation(int dim) {
  struct Params { int dim; };
  Params p{dim};
  gsl_function fn;
  fn.function = [](double q, void* vp) {
    const int d = static_cast<Params*>(vp)->dim;
    return Shape::w(q) * std::pow(q, d - 1);
  };
  fn.params = &p;
  std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> ws(
      gsl_integration_workspace_alloc(1000), gsl_integration_workspace_free);
  double integral = 0.0, abserr = 0.0;
  gsl_error_handler_t* old = gsl_set_error_handler_off();
  const int status = gsl_integration_qag(&fn, 0.0, Shape::support, 0.0, 1e-13, 1000,
                                         GSL_INTEG_GAUSS61, ws.get(), &integral, &abserr);
  gsl_set_error_handler(old);
  if (status != GSL_SUCCESS && abserr > 1e-12 * integral)
    throw std::runtime_error(std::string("kernel normalisation quadrature failed for ") + Shape::name +
                             ": " + gsl_strerror(status));
  return 1.0 / (unit_sphere_measure(dim) * integral);
}

double CubicSplineShape::normalisation(int dim) {
  static constexpr double sigma[] = {2.0 / 3.0, 10.0 / (7.0 * M_PI), 1.0 / M_PI};
  return sigma[dim - 1];
}

double LucyShape::normalisation(int dim) {
  static constexpr double sigma[] = {5.0 / 4.0, 5.0 / M_PI, 105.0 / (16.0 * M_PI)};
  return sigma[dim - 1];
}

template double numerical_normalisation<CubicSplineShape>(int);
template double numerical_normalisation<LucyShape>(int);
template double numerical_normalisation<GaussianShape>(int);
template double numerical_normalisation<MollifierShape>(int);
template double numerical_normalisation<ModifiedMollifierShape>(int);

}  // namespace sph
