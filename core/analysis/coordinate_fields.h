// The coordinate fields of paper Fig. 3: how a cage vertex or a cage face moves the points around it at a given nu.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "base/progress.h"
#include "coordinates/somigliana_coordinates.h"
#include "geometry/cage.h"

namespace somicage {

// T_i(x_p) n_i for every point (#P by d): cage vertex i pushed along its unit normal n_i (the normalised sum of
// the incident faces' normals weighted by their areas, boundary_conditions.h), at nu.
Eigen::MatrixXd vertexCoordinateField(const SomiglianaCoordinates& coords, const Cage& cage, int vertex, double nu);

// K_j(x_p) n_j for every point (#P by d): the Kelvinlet response to a unit traction along face j's normal, at nu.
Eigen::MatrixXd faceCoordinateField(const SomiglianaCoordinates& coords, int face, double nu);

// One cage element's nu-independent terms at every point (#P by vertexTermCount or faceTermCount), integrated
// without keeping the whole coordinate matrix: the editor shows the field of one handle at any nu for the memory of
// a few columns (the full matrix of FIREHYDRANT's mesh is ~270 MB in double).
struct ElementTerms {
  enum class Kind { Vertex, Face };
  Kind kind = Kind::Vertex;
  int index = 0;
  int dim = 3;
  Eigen::MatrixXd terms;    // #P by the element's term count, in term order (somigliana_coordinates.h)
  Eigen::VectorXd normal;   // n_i (vertexNormals) or n_j (the rest face normal), d
  Eigen::VectorXd winding;  // #P: generalised winding number (< 1/2 outside the cage)
};
ElementTerms integrateElementTerms(const Cage& cage, const Eigen::MatrixXd& points, ElementTerms::Kind kind, int index,
                                   const IntegrationOptions& options = {},
                                   const ProgressCallback& progress = noProgress);
// The element's field at nu (#P by d): T_i(x) n_i or K_j(x) n_j, as vertexCoordinateField / faceCoordinateField.
Eigen::MatrixXd elementCoordinateField(const ElementTerms& element, double nu);

}  // namespace somicage
