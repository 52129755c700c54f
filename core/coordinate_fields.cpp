#include "coordinate_fields.h"

#include "boundary_conditions.h"
#include "errors.h"

namespace somicage {

Eigen::MatrixXd vertexCoordinateField(const SomiglianaCoordinates& coords, const Cage& cage, int vertex, double nu) {
  SOMICAGE_ASSERT(vertex >= 0 && vertex < coords.layout.numVertices, "a cage vertex");
  const Eigen::VectorXd n = vertexNormals(cage, cage.vertices).row(vertex).transpose();
  Eigen::MatrixXd field(coords.numPoints(), coords.dim);
  for (int p = 0; p < coords.numPoints(); ++p) field.row(p) = (coords.vertexCoordinate(p, vertex, nu) * n).transpose();
  return field;
}

Eigen::MatrixXd faceCoordinateField(const SomiglianaCoordinates& coords, int face, double nu) {
  SOMICAGE_ASSERT(face >= 0 && face < coords.layout.numFaces, "a cage face");
  Eigen::MatrixXd field(coords.numPoints(), coords.dim);
  for (int p = 0; p < coords.numPoints(); ++p) field.row(p) = coords.faceCoordinateTimesNormal(p, face, nu).transpose();
  return field;
}

}  // namespace somicage
