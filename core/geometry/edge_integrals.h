// Exact integrals over one straight cage edge of the kernels that 2D Somigliana coordinates need
// (paper Eqs. 3, 4, 8 with d = 2).
//
// Conventions: edge p0 -> p1 of a counter-clockwise polygon, outward unit normal n = (e_y, -e_x)/|e|;
// query point x; r = y - x, R = |r|; phi_0 = 1 at p0, phi_1 = 1 at p1 (linear hats along the edge).
#pragma once

#include <Eigen/Core>

#include "base/dual_number.h"

namespace somicage {

struct EdgeIntegrals {
  double S = 0;          // int ln(1/R)
  Eigen::Matrix2d M;     // int r r^T / R^2 (symmetric)
  double D[2];           // int phi_k (n.r) / R^2
  double A[2];           // int phi_k (n_x r_y - n_y r_x) / R^2: the entry (0,1) of int phi_k (n r^T - r n^T)/R^2
  Eigen::Matrix2d B[2];  // int phi_k (n.r) r r^T / R^4 (symmetric)
  double angle = 0;      // int h / R^2 with h = n.(x - p0): signed angle subtended by the edge, -pi just inside it
};

// The same integrals as plain arrays, for x given as doubles or as dual numbers (dual_number.h: then every output
// carries its exact gradient with respect to x). Two functions, not a template, so that each is dispatched
// (cpu_dispatch.h).
template <typename Scalar>
struct EdgeIntegralsOf {
  Scalar S, M[2][2], D[2], A[2], B[2][2][2], angle;
};
void integrateEdgeOf(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const double x[2],
                     EdgeIntegralsOf<double>& out);
void integrateEdgeOf(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const dual::Dual<2> x[2],
                     EdgeIntegralsOf<dual::Dual<2>>& out);

// Closed form, double precision, valid for any x not on the edge.
void integrateEdge(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& x, EdgeIntegrals& out);

// The limit of integrateEdge as x tends to the point `onEdge` of the edge (strictly between its ends; projected onto
// it) from the inside of the polygon, h -> 0-: the closed form with h = -0 (exact, no quadrature). It carries the
// jump of the double layer: angle = -pi, D_k = pi phi_k(onEdge), B_k = (pi/2) phi_k(onEdge) I.
void integrateEdgeInteriorLimit(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& onEdge,
                                EdgeIntegrals& out);

// Same outputs by composite Gauss-Legendre quadrature (segments x points per segment); for tests and baselines.
void integrateEdgeGauss(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& x, int segments,
                        int pointsPerSegment, EdgeIntegrals& out);

}  // namespace somicage
