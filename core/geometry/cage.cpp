#include "geometry/cage.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "base/errors.h"

namespace somicage {

Cage makePolygonCage(const Eigen::MatrixXd& loop) {
  SOMICAGE_ASSERT(loop.cols() == 2, "a polygon loop has 2 columns");
  Cage cage;
  cage.vertices = loop;
  const int n = static_cast<int>(loop.rows());
  cage.faces.resize(n, 2);
  for (int k = 0; k < n; ++k) cage.faces.row(k) << k, (k + 1) % n;
  return cage;
}

// Unnormalised normal: the cross product (3D, twice the area) or the rotated edge (2D, the length).
static Eigen::VectorXd scaledNormal(const Cage& cage, const Eigen::MatrixXd& V, int j) {
  if (cage.dim() == 3) {
    const Eigen::Vector3d v0 = V.row(cage.faces(j, 0)), v1 = V.row(cage.faces(j, 1)), v2 = V.row(cage.faces(j, 2));
    return (v1 - v0).cross(v2 - v0);
  }
  const Eigen::Vector2d e = V.row(cage.faces(j, 1)) - V.row(cage.faces(j, 0));
  return Eigen::Vector2d(e.y(), -e.x());
}

Eigen::MatrixXd faceNormals(const Cage& cage, const Eigen::MatrixXd& vertices) {
  Eigen::MatrixXd N(cage.numFaces(), cage.dim());
  for (int j = 0; j < cage.numFaces(); ++j) N.row(j) = scaledNormal(cage, vertices, j).normalized();
  return N;
}

Eigen::VectorXd faceAreas(const Cage& cage, const Eigen::MatrixXd& vertices) {
  Eigen::VectorXd A(cage.numFaces());
  const double scale = cage.dim() == 3 ? 0.5 : 1.0;
  for (int j = 0; j < cage.numFaces(); ++j) A(j) = scale * scaledNormal(cage, vertices, j).norm();
  return A;
}

void assertCageAndPoints(const Cage& cage, const Eigen::MatrixXd& points) {
  const int dim = cage.dim();
  SOMICAGE_ASSERT(dim == 2 || dim == 3, "cages are 2D or 3D");
  SOMICAGE_ASSERT(points.cols() == dim, "points and cage have the same dimension");
  SOMICAGE_ASSERT(cage.faces.cols() == dim, "3D faces are triangles, 2D faces are edges");
}

double signedTetrahedronVolume(const Eigen::Vector3d& o, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c) {
  return (a - o).dot((b - o).cross(c - o)) / 6.0;
}

double signedTriangleArea(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const Eigen::Vector2d u = b - a, w = c - a;
  return 0.5 * (u.x() * w.y() - u.y() * w.x());
}

double signedFaceMeasure(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& faces, int j,
                         const Eigen::RowVectorXd& origin) {
  if (vertices.cols() == 3)
    return signedTetrahedronVolume(origin.transpose(), vertices.row(faces(j, 0)).transpose(),
                                   vertices.row(faces(j, 1)).transpose(), vertices.row(faces(j, 2)).transpose());
  return signedTriangleArea(origin.transpose(), vertices.row(faces(j, 0)).transpose(),
                            vertices.row(faces(j, 1)).transpose());
}

double signedMeasure(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& faces) {
  if (vertices.rows() == 0) return 0.0;
  const Eigen::RowVectorXd centre = vertices.colwise().mean();
  double sum = 0.0;
  for (int j = 0; j < faces.rows(); ++j) sum += signedFaceMeasure(vertices, faces, j, centre);
  return sum;
}

bool isDegenerateTriangle(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) {
  const double twiceArea = (p1 - p0).cross(p2 - p0).norm();
  const double longest = std::max({(p1 - p0).squaredNorm(), (p2 - p0).squaredNorm(), (p2 - p1).squaredNorm()});
  return !(twiceArea > kDegenerateFace * longest) || !std::isfinite(longest);
}

bool isDegenerateFace(const Cage& cage, int j) {
  if (cage.dim() == 3)
    return isDegenerateTriangle(cage.vertices.row(cage.faces(j, 0)), cage.vertices.row(cage.faces(j, 1)),
                                cage.vertices.row(cage.faces(j, 2)));
  const Eigen::RowVectorXd e = cage.vertices.row(cage.faces(j, 1)) - cage.vertices.row(cage.faces(j, 0));
  const double length = e.norm();
  return !(length > 0) || !std::isfinite(length);
}

double cageDiameter(const Eigen::MatrixXd& vertices) {
  if (vertices.rows() == 0) return 0.0;
  return (vertices.colwise().maxCoeff() - vertices.colwise().minCoeff()).norm();
}

}  // namespace somicage
