// Mean value coordinates (the deformer over them is the method core/methods/mvc_method.cpp: C = the coordinates,
// W = the posed vertices):
//   2D: Floater 2003, in the signed form of Hormann & Floater 2006 ("Mean value coordinates for arbitrary planar
//       polygons"), valid for any simple polygon (non-convex included) and any point of the plane;
//   3D: Ju, Schaefer & Warren 2005 ("Mean value coordinates for closed triangular meshes"), their robust
//       pseudo-code, valid for any closed triangle mesh and any point.
//
// The coordinates are normalised weights w_i(x) / sum_k w_k(x), one per cage vertex, so that for every point
// sum_i lambda_i = 1 and sum_i lambda_i v_i = x: they reproduce every affine map of the cage. They interpolate:
// lambda_i = delta_ij at cage vertex j, and they are linear along a cage edge and (3D) barycentric on a face.
//   2D: w_i = (tan(alpha_{i-1}/2) + tan(alpha_i/2)) / |v_i - x|, alpha_i the signed angle of edge i at x;
//       a point on an edge (|sin alpha| <= 1e-14 with cos alpha < 0) gets the linear interpolation of that edge.
//   3D: per face, w_i = (theta_i - c_{i+1} theta_{i-1} - c_{i-1} theta_{i+1}) / (d_i sin(theta_{i+1}) s_{i-1})
//       with the spherical triangle of the face seen from x (JSW 2005), with two changes for accuracy:
//       - s = sin of the spherical angle comes from det[u0 u1 u2] = 2 area h / (d0 d1 d2) (h = the height of the
//         face plane above x) instead of sign(det) sqrt(1 - c^2), which loses all digits as c -> +-1;
//       - where x is close to the plane of a face but projects outside it (|det| < 1e-3), the JSW formula cancels
//         (error ~ eps / |det|, seen as 2.5e-10 of the diameter on the BEAST mesh) and the face's weights come
//         from the exact integral they stand for, 2 int_face phi_i h / |y - x|^4 dA, in a closed form that has no
//         cancellation as h -> 0 (mean_value_coordinates.cpp, nearPlaneWeights).
//       A point within 1e-12 (relative to its distance to the corners) of a face gets the barycentric coordinates
//       of that face (JSW's "x lies on t"); a face whose plane contains x, outside it, contributes nothing (JSW's
//       "ignore t"). Faces with twice their area below 1e-12 times their longest edge squared are skipped.
// Cage vertices closer than 1e-14 times the cage diameter to x are taken as x itself (lambda = delta).
#pragma once

#include <Eigen/Core>

#include "base/progress.h"
#include "coordinates/coordinate_gradients.h"
#include "deform/coordinate_layout.h"  // RowMatrixXd
#include "geometry/cage.h"

namespace somicage {

// Normalised mean value coordinates of points (#P by d) in the cage: #P by #V. threads = 0: the OpenMP default.
// Throws somicage::Cancelled when progress returns false. The result does not depend on the thread count.
RowMatrixXd computeMeanValueCoordinates(const Cage& cage, const Eigen::MatrixXd& points, int threads = 0,
                                        const ProgressCallback& progress = noProgress);

// The exact gradients of those coordinates with respect to the point (dual numbers through the same formulas):
// rows of #V numbers (coordinate_gradients.h).
void integrateMeanValueGradients(const Cage& cage, const Eigen::MatrixXd& points, int threads,
                                 const ProgressCallback& progress, const GradientRowSink& sink);

}  // namespace somicage
