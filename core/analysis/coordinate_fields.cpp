#include "analysis/coordinate_fields.h"

#include <string>
#include <vector>

#include "base/errors.h"
#include "deform/boundary_conditions.h"

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

ElementTerms integrateElementTerms(const Cage& cage, const Eigen::MatrixXd& points, ElementTerms::Kind kind, int index,
                                   const IntegrationOptions& options, const ProgressCallback& progress) {
  const bool vertex = kind == ElementTerms::Kind::Vertex;
  const int d = cage.dim();
  if (index < 0 || index >= (vertex ? cage.numVertices() : cage.numFaces()))
    throw InputError("coordinate field", -1,
                     std::string("cage ") + (vertex ? "vertex " : "face ") + std::to_string(index) + " does not exist",
                     "pick an index below " + std::to_string(vertex ? cage.numVertices() : cage.numFaces()));
  ElementTerms out;
  out.kind = kind;
  out.index = index;
  out.dim = d;
  const int count = vertex ? vertexTermCount(d) : faceTermCount(d);
  const CoordinateLayout layout = somiglianaLayout(d, cage.numVertices(), cage.numFaces());  // the sink's rows
  std::vector<int> columns(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k)
    columns[static_cast<std::size_t>(k)] = vertex ? layout.vertexColumn(index, k) : layout.faceColumn(index, k);
  out.terms.resize(points.rows(), count);
  out.winding.resize(points.rows());
  out.normal = vertex ? vertexNormals(cage, cage.vertices).row(index).transpose()
                      : faceNormals(cage, cage.vertices).row(index).transpose();
  integrateSomiglianaCoordinates(cage, points, options, progress, [&](int p, const double* row, double winding) {
    for (int k = 0; k < count; ++k) out.terms(p, k) = row[columns[static_cast<std::size_t>(k)]];  // once per point
    out.winding[p] = winding;
  });
  return out;
}

Eigen::MatrixXd elementCoordinateField(const ElementTerms& element, double nu) {
  const int d = element.dim;
  Eigen::MatrixXd field(element.terms.rows(), d);
  const NuCoefficients c = nuCoefficients(d, nu);
  for (Eigen::Index p = 0; p < element.terms.rows(); ++p) {
    const Eigen::VectorXd t = element.terms.row(p).transpose();
    if (element.kind == ElementTerms::Kind::Vertex)  // Eq. 8a
      field.row(p) = (assembleVertexCoordinate(t.data(), d, nu) * element.normal).transpose();
    else  // Eq. 8b
      field.row(p) = (c.k1 * t[0] * element.normal + c.k2 * t.tail(d)).transpose();
  }
  return field;
}

}  // namespace somicage
