// A cover function bound to its smoothing length: W(r), dW/dr(r) and the support radius, the interface the
// SPH-matrix builders and the boundary corrections take. BoundKernel<Kernel> is a compile-time kernel (the
// 2D bodies); KernelFn (sph_matrices.hpp) is the same interface for a kernel chosen by name at run time.
#pragma once

#include "core/kernels.hpp"

namespace sph {

template <class Kernel>
struct BoundKernel {
  BoundKernel(int dim, double h) : kernel(dim), dim(dim), h(h), radius(Kernel::support() * h) {}
  Kernel kernel;
  int dim;
  double h, radius;
  double W(double r) const { return kernel.W(r, h); }
  double dWdr(double r) const { return kernel.dWdr(r, h); }
};

}  // namespace sph
