// Green coordinates (Lipman, Levin, Cohen-Or 2008, "Green Coordinates"), 2D and 3D; the deformer over them is the
// method core/methods/green_method.cpp, which stores C = [phi | psi | x | 1] and evaluates every frame as one
// product C W (frame_evaluation.h) with W = [v~_i ; s_j n~_j ; (s R)^T ; t^T]. Points outside the cage
// (sum_i phi_i = 0 there), on it, or with unreliable coordinates follow the exterior rule of exterior_points.h.
//
// Conventions are those of docs/method.md: outward face normals n_j, r = y - x for a boundary point y and the
// query point x, phi_i^f the hat function of vertex i on face f, psi_j the indicator of face j.
//   3D: phi_i(x) = 1/(4 pi) sum_{f ∋ i} int_f phi_i^f (n_f.r)/|r|^3     (the double layer of the hat of vertex i)
//       psi_j(x) = 1/(4 pi) int_j 1/|r|                                (the single layer of face j)
//   2D: phi_i(x) = 1/(2 pi) sum_{f ∋ i} int_f phi_i^f (n_f.r)/|r|^2,    psi_j(x) = 1/(2 pi) int_j ln(1/|r|)
// These are the paper's phi_i = int Gamma_i dG/dn and psi_j = -int G with G = -1/(4 pi r) (3D), ln(r)/(2 pi) (2D),
// so Green's third identity applied to the linear function x gives, for x strictly inside the cage,
//   x = sum_i phi_i v_i + sum_j psi_j n_j,       sum_i phi_i = 1   (sum_i phi_i = 0 outside).
//
// Deformation (Lipman et al. 2008, with their quasi-conformal face scale in 3D):
//   x~ = sum_i phi_i v~_i + sum_j psi_j s_j n~_j,   n~_j the unit normal of the posed face,
//   s_j = |e~_j| / |e_j|                                                                  (2D, edge lengths)
//   s_j = sqrt(|u~|^2 |v|^2 - 2 (u~.v~)(u.v) + |v~|^2 |u|^2) / (sqrt(8) area_j)            (3D)
// with u, v two edge vectors of the rest face j and u~, v~ the same edges on the posed face. This reproduces
// any similarity of the cage exactly (s_j = the scale) and is quasi-conformal in 3D.
//
// The integrals are exact closed forms (green_coordinates.cpp), not the paper's GCTriInt routine, whose divisions
// by zero near face planes and edges the Somigliana paper points out. They stay finite everywhere: for a point in
// a face plane, 1e-9 from a face or an edge, or exactly on the cage (where the coordinates are singular and the
// values meaningless, but never NaN). Accuracy: round-off away from the cage, ~eps * diameter / distance next to
// an edge (the problem's own conditioning). Faces with twice their area below 1e-12 times their longest edge
// squared (3D) or of zero length (2D) contribute nothing, and their posed normal is not used.
#pragma once

#include <Eigen/Core>

#include "base/progress.h"
#include "deform/coordinate_layout.h"  // RowMatrixXd
#include "geometry/cage.h"

namespace somicage {

struct GreenCoordinates {
  RowMatrixXd phi;  // #P by #V vertex coordinates
  RowMatrixXd psi;  // #P by #F face coordinates
};

// Green coordinates of points (#P by d) with respect to the cage (d = cage.dim()). threads = 0: the OpenMP
// default. Throws somicage::Cancelled when progress returns false. The result does not depend on the thread count.
GreenCoordinates computeGreenCoordinates(const Cage& cage, const Eigen::MatrixXd& points, int threads = 0,
                                         const ProgressCallback& progress = noProgress);

// The face scales s_j of a posed cage (#F, see above); 1 for every face at rest, 0 for a degenerate rest face.
Eigen::VectorXd greenFaceScales(const Cage& restCage, const Eigen::MatrixXd& posedVertices);

}  // namespace somicage
