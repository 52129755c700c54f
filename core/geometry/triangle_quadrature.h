// The paper's quadrature baseline (section 5, "Implementation"): each triangle is split into three quads
// (corner, two edge midpoints, centroid) and each quad gets an N x N Gauss-Legendre rule. Kept as the
// reference that the benchmarks compare the closed form against; it is not accurate near the cage.
#pragma once

#include <Eigen/Core>

#include "geometry/triangle_integrals.h"

namespace somicage {

// Same outputs as integrateTriangle(), by quadrature with 3 N^2 points (N = pointsPerSide >= 1). Faces that
// makeTriangleFrame() calls degenerate give all zeros. The 1D rule is cached per thread.
void integrateTriangleGauss(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                            const Eigen::Vector3d& x, int pointsPerSide, TriangleIntegrals& out);

// Gauss-Legendre nodes and weights on [0, 1].
void gaussLegendre01(int count, Eigen::VectorXd& nodes, Eigen::VectorXd& weights);

}  // namespace somicage
