// The fundamental solutions of linear elasticity, pointwise (paper Eqs. 3 and 4), with mu = 1.
// Used by the quadrature baselines and by tests; the coordinates themselves use the exact integrals.
#pragma once

#include <Eigen/Core>

namespace somicage {

// Coefficients a = 1/(2^{d-1} pi) and b = a/(4(1 - nu)) of Eqs. 3-4 (mu = 1). nu may be +-infinity (b = 0).
double kelvinA(int dim);
double kelvinB(int dim, double nu);

// Eq. 3: the Kelvinlet K(y, x) for r = y - x (3D: (a-b)/r I + b r r^T/r^3; 2D: (a-b) ln(1/r) I + b r r^T/r^2).
Eigen::Matrix3d kelvinlet(const Eigen::Vector3d& r, double nu);
Eigen::Matrix2d kelvinlet(const Eigen::Vector2d& r, double nu);

// Eq. 4: the traction kernel T(y, x) for r = y - x and the unit normal n at y.
Eigen::Matrix3d tractionKernel(const Eigen::Vector3d& r, const Eigen::Vector3d& n, double nu);
Eigen::Matrix2d tractionKernel(const Eigen::Vector2d& r, const Eigen::Vector2d& n, double nu);

}  // namespace somicage
