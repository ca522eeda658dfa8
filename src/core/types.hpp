// The vector and tensor types of the whole library, defined once: positions, velocities and forces are
// 2D vectors; stresses and deformation gradients are D x D tensors (2D plane strain, 3D where a law needs it).
#pragma once

#include <Eigen/Core>

namespace sph {

using Vec2 = Eigen::Vector2d;
template <int D>
using Tensor = Eigen::Matrix<double, D, D>;
using Tensor2 = Tensor<2>;
using Tensor3 = Tensor<3>;

}  // namespace sph
