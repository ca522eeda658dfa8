// An independent reference for the I-hole sheet: the linear-elastic stress concentration of exactly the
// chosen geometry (a quarter of a 2a x 2a sheet, central hole of radius R, uniform traction on x = +-a, free
// y = +-a) by the finite element method, since Heywood's formula is for an infinitely long strip. Bilinear
// quadrilaterals (2 x 2 Gauss), plane stress with nu = 0.3 (for a traction problem with a traction-free hole
// the in-plane stress does not depend on the elastic constants, Michell; nu = 0.3 keeps Q4 free of locking),
// a structured mesh of n_theta x n_r elements between the hole (r = R) and the square, graded toward the hole.
#pragma once

namespace scenes {

struct FemHoleResult {
  int elements = 0, dofs = 0;
  double concentration = 0;  ///< sigma_xx at (0, R) / applied traction (Gauss stresses extrapolated to the node)
};

FemHoleResult fem_hole_concentration(double a, double R, int n_theta, int n_r, double grading = 2.0);

}  // namespace scenes
