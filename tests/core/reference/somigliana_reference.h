// An independent evaluation of the Somigliana deformer, for tests only, written from the paper's definitions and
// docs/method.md and sharing no code with core/ beyond the Cage struct:
//   - the coordinates T_i(x), K_j(x) (Eq. 8) by adaptive Gauss-Legendre quadrature (adaptive_quadrature.h) of the
//     kernels exactly as Eqs. 3 and 4 write them (mu = 1, a = 1/(2^{d-1} pi), b = a/(4(1-nu)), r = y - x), at the
//     requested nu (no nu-independent split, no closed form);
//   - the boundary conditions of docs/method.md (Umeyama similarity, polar face rotations and the mean singular value,
//     the geodesic blend, area-weighted vertex rotations, signed-solid-angle bulging, Eqs. 12-15);
//   - the deformed point of Eq. 11, x~ = T(x)^-1 [sum_i R_i T_i R_i^T v~_i + sum_j s_j R_j K_j n_j].
// Only points strictly inside the cage have a defined Eq. 11 (core's exterior rule is a separate convention).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "adaptive_quadrature.h"
#include "geometry/cage.h"

namespace somicage::reference {

// The scalars a, b of Eqs. 3-4 for mu = 1: a = 1/(2^{d-1} pi), b = a/(4(1-nu)); nu = +-infinity is the limit b = 0.
struct KernelScalars {
  double a, b;
};
KernelScalars kernelScalars(int d, double nu);

// Unit outward normal and area (3D) or length (2D) of face j for the cage's faces at the vertex positions V.
void faceGeometry(const Cage& cage, const Eigen::MatrixXd& V, int j, Eigen::VectorXd& normal, double& area);

// T_i(x) (#V, d by d) and K_j(x) (#F, d by d) of one point (Eq. 8).
struct Coordinates {
  std::vector<Eigen::MatrixXd> T, K;
};

// The coordinates of x (strictly inside or outside the cage, not on it) for each nu of `nus`.
std::vector<Coordinates> integrateCoordinates(const Cage& cage, const Eigen::VectorXd& x,
                                              const std::vector<double>& nus, const QuadratureOptions& options = {});

struct PoseParameters {
  double blend = 0;  // 0 global, 1 local
  double nu = 0;
  double gamma = 0;
  bool tractionCorrection = true;
};

struct BoundaryConditions {
  std::vector<Eigen::MatrixXd> vertexRotation, faceRotation;  // R_i, R_j
  std::vector<double> tractionScale;                          // s_j (s'_j after Eq. 15)
};

// Rotations and traction scales of a posed cage (#V by d, rest order): docs/method.md "Deformer", Eqs. 12-15.
BoundaryConditions boundaryConditions(const Cage& rest, const Eigen::MatrixXd& posed, const PoseParameters& p);

// Eq. 11: x~ = T(x)^-1 [sum_i R_i T_i R_i^T v~_i + sum_j s_j R_j K_j n_j], T(x) = sum_i R_i T_i R_i^T.
Eigen::VectorXd deformPoint(const Cage& rest, const Eigen::MatrixXd& posed, const Coordinates& coordinates,
                            const BoundaryConditions& bc);

// Generalised winding number of x with respect to the cage (1 inside, 0 outside): signed solid angles
// (van Oosterom-Strackee) / 4 pi in 3D, signed angles / 2 pi in 2D.
double windingNumber(const Cage& cage, const Eigen::VectorXd& x);

// Distance from x to the nearest face of the cage.
double distanceToCage(const Cage& cage, const Eigen::VectorXd& x);

}  // namespace somicage::reference
