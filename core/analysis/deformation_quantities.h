// What an artist reads off a deformation (issue 12): per point, from the deformation gradient J (jacobian.h), the
// local volume ratio det J (area ratio in 2D), the conformal distortion sigma_max / sigma_min and fold-overs
// (det J <= 0); per mesh face, the area ratio and the largest edge stretch; for the whole mesh, the enclosed
// signed volume (area in 2D) before and after.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace somicage {

// The per-point scalars of J (#P by d*d, row-major per point, NaN rows where J is not defined).
struct PointQuantities {
  Eigen::VectorXd detJ;        // #P; NaN where J is not defined
  Eigen::VectorXd distortion;  // #P: sigma_max / sigma_min of J (>= 1; 1 for a similarity; inf when singular)
  int foldovers = 0;           // points with a defined J and det J <= 0
  int undefined = 0;           // points without J (the exterior rule of exterior_points.h)
};
PointQuantities pointQuantities(const Eigen::MatrixXd& jacobians, int dim);

// Per mesh face (polygons fan-triangulated from their first corner): deformed / rest area (signed in 2D, where a
// flipped face is negative; unsigned in 3D) and the largest ratio of deformed to rest edge length.
struct FaceQuantities {
  Eigen::VectorXd areaRatio;    // #F; NaN for a face of zero rest area
  Eigen::VectorXd edgeStretch;  // #F; NaN for a face with a zero-length rest edge
};
FaceQuantities faceQuantities(const std::vector<std::vector<int>>& faces, const Eigen::MatrixXd& rest,
                              const Eigen::MatrixXd& deformed);

// The mesh's enclosed measure: in 3D the signed volume of a closed mesh (every edge shared by exactly two faces
// with opposite orientations), in 2D the signed area of its faces. A 3D mesh with holes (closed = false) is
// measured closed by a cone from the centroid of its boundary vertices to every boundary edge ("capped"): exact
// for a planar hole, an estimate otherwise, and only reported as such.
struct EnclosedMeasure {
  bool closed = false;
  double rest = 0, deformed = 0;                         // capped when !closed
  double change() const { return deformed / rest - 1; }  // relative change
};
EnclosedMeasure enclosedMeasure(const std::vector<std::vector<int>>& faces, const Eigen::MatrixXd& rest,
                                const Eigen::MatrixXd& deformed);
// The signed volume (3D) or area (2D) of the faces with the given vertex positions, measured from origin (3D).
double signedMeshMeasure(const std::vector<std::vector<int>>& faces, const Eigen::MatrixXd& vertices,
                         const Eigen::RowVectorXd& origin);
// The vertices on edges used by one face only (sorted); empty for a closed mesh.
std::vector<int> boundaryVertices(const std::vector<std::vector<int>>& faces);
// Whether every undirected edge of the faces is used exactly twice, in opposite directions.
bool isClosedMesh(const std::vector<std::vector<int>>& faces);

// The jump of J across a face between two evaluations of it (seam_jumps.h), a and b row-major d*d (jacobian.h):
// |a - b|_F / (1/2 (|a|_F + |b|_F)), Frobenius norms; NaN when either is not finite or both are zero.
double gradientJump(const Eigen::Ref<const Eigen::RowVectorXd>& a, const Eigen::Ref<const Eigen::RowVectorXd>& b);

// The q-quantile (q in [0, 1], linear interpolation between order statistics) of the finite values; NaN if none.
double quantile(const Eigen::VectorXd& values, double q);

// |a_p - b_p| / diameter per point (#P): how far two deformations of the same points differ, in cage diameters.
Eigen::VectorXd pointDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double diameter);

}  // namespace somicage
