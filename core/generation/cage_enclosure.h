// Does a cage strictly enclose a mesh? Exact predicates (CGAL's Epick kernel), so the answer does not depend on
// rounding: every mesh vertex strictly inside the cage (CGAL::Side_of_triangle_mesh), no mesh edge touching a cage
// face (AABB tree of the cage's faces), and the cage free of self-intersections
// (Polygon_mesh_processing::self_intersections). The cage must be closed and edge-manifold (validateCage).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "geometry/cage.h"

namespace somicage {

struct EnclosureReport {
  std::vector<int> outsideVertices;                   // mesh vertices on or outside the cage
  std::vector<int> nearestFaces;                      // for each of them, the cage face closest to it
  std::vector<int> crossedFaces;                      // cage faces that a mesh edge touches, each once
  std::vector<std::array<int, 2>> selfIntersections;  // pairs of cage faces that meet other than at shared corners

  bool encloses() const { return outsideVertices.empty() && crossedFaces.empty() && selfIntersections.empty(); }
};

// cage: closed and edge-manifold (see cage_validation.h). meshVertices #V by 3; meshTriangles #T by 3, any mesh.
EnclosureReport checkEnclosure(const Cage& cage, const Eigen::MatrixXd& meshVertices,
                               const Eigen::MatrixXi& meshTriangles);

// How closely a cage fits a mesh.
struct CageTightness {
  double hausdorff = 0.0;    // hausdorffCageToMesh, in bounding-box diagonals of the mesh
  double volumeRatio = 0.0;  // cage volume / mesh volume; NaN when the mesh is not closed, manifold and oriented
};
CageTightness measureTightness(const Cage& cage, const Eigen::MatrixXd& meshVertices,
                               const Eigen::MatrixXi& meshTriangles);

// The one-sided Hausdorff distance from the cage to the mesh: the largest distance from a point of the cage to the
// nearest point of the mesh's triangles, over the cage's vertices and a barycentric grid of `samplesPerEdge`
// intervals on each face (an estimate from below that converges as the grid is refined).
double hausdorffCageToMesh(const Cage& cage, const Eigen::MatrixXd& meshVertices, const Eigen::MatrixXi& meshTriangles,
                           int samplesPerEdge = 8);

}  // namespace somicage
