// The cage: a closed triangle mesh in 3D or a simple polygon in 2D.
#pragma once

#include <Eigen/Core>

namespace somicage {

// vertices: #V by d (d = 2 or 3).
// faces:    #F by d vertex indices.
//   3D: triangles, counter-clockwise seen from outside, so (v1-v0)x(v2-v0) points outward.
//   2D: edges (v_k, v_{k+1}) of a counter-clockwise polygon; the outward edge normal is (e_y, -e_x)/|e|.
struct Cage {
  Eigen::MatrixXd vertices;
  Eigen::MatrixXi faces;

  int dim() const { return static_cast<int>(vertices.cols()); }
  int numVertices() const { return static_cast<int>(vertices.rows()); }
  int numFaces() const { return static_cast<int>(faces.rows()); }
};

// A 2D cage from a polygon given as a counter-clockwise vertex loop (#V by 2).
Cage makePolygonCage(const Eigen::MatrixXd& loop);

// Unit outward normals of the faces (#F by d), and their areas (3D) or lengths (2D) (#F).
Eigen::MatrixXd faceNormals(const Cage& cage, const Eigen::MatrixXd& vertices);
Eigen::VectorXd faceAreas(const Cage& cage, const Eigen::MatrixXd& vertices);

// The signed volume of the tetrahedron (o, a, b, c) and the signed area of the triangle (a, b, c): positive when
// counter-clockwise seen from outside (3D: from the side b - a x c - a points to), the one term of every signed
// volume and area below and in deformation_quantities.h / offset_surface.cpp.
double signedTetrahedronVolume(const Eigen::Vector3d& o, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c);
double signedTriangleArea(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

// Face j's share of the signed volume (3D: triangles) or area (2D: edges) of faces over vertices, measured from
// origin (1 by d): the tetrahedron (origin, face) or triangle (origin, edge). Summed over a closed surface it is
// the enclosed measure, positive when the normals point out; an origin near the faces keeps the sum's
// cancellation small. The one signed volume of the code base (validation, repair, the editor's demo meshes).
double signedFaceMeasure(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& faces, int j,
                         const Eigen::RowVectorXd& origin);
inline double signedFaceMeasure(const Cage& cage, int j, const Eigen::RowVectorXd& origin) {
  return signedFaceMeasure(cage.vertices, cage.faces, j, origin);
}
// The sum over all faces, about the vertices' centroid.
double signedMeasure(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& faces);

// Faces whose twice-area is at most this fraction of their longest edge squared have no usable normal.
constexpr double kDegenerateFace = 1e-12;

// The one test of a face with no usable normal, which every integrator skips: a triangle with twice its area at
// most kDegenerateFace times its longest edge squared (or not finite), an edge of zero length (or not finite).
// Validation (cage_validation.h) refuses such faces and, more strictly, faces small against the whole cage.
bool isDegenerateTriangle(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2);
bool isDegenerateFace(const Cage& cage, int j);

// Internal precondition of every precompute: a 2D or 3D cage whose faces have d corners, and points (#P by d) of
// the same dimension. Input boundaries (obj_io, the CLI) report bad input before it gets here.
void assertCageAndPoints(const Cage& cage, const Eigen::MatrixXd& points);

// Largest distance between two cage vertices (bounding-box diagonal, cheap and scale-faithful).
double cageDiameter(const Eigen::MatrixXd& vertices);

}  // namespace somicage
