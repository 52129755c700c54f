// The coordinate fields of paper Fig. 3: how a cage vertex or a cage face moves the points around it at a given nu.
#pragma once

#include <Eigen/Core>

#include "cage.h"
#include "somigliana_coordinates.h"

namespace somicage {

// T_i(x_p) n_i for every point (#P by d): cage vertex i pushed along its unit normal n_i (the normalised sum of
// the incident faces' normals weighted by their areas, boundary_conditions.h), at nu.
Eigen::MatrixXd vertexCoordinateField(const SomiglianaCoordinates& coords, const Cage& cage, int vertex, double nu);

// K_j(x_p) n_j for every point (#P by d): the Kelvinlet response to a unit traction along face j's normal, at nu.
Eigen::MatrixXd faceCoordinateField(const SomiglianaCoordinates& coords, int face, double nu);

}  // namespace somicage
