// Where a mesh lies relative to its cage, judged from their bounding boxes before any precompute: a mesh that is
// far larger or smaller than its cage, or lies beside it, usually comes from a file in other units (millimetres
// against metres, inches against centimetres) or with another origin. Every front end prints the warning.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "geometry/cage.h"

namespace somicage {

struct MeshPlacement {
  double sizeRatio = 1;   // mesh bounding-box diagonal / cage bounding-box diagonal (0 for a single point)
  bool disjoint = false;  // the two bounding boxes do not meet
};

// Beyond these the mesh cannot be what the cage was made for: mostly outside it (larger), or a speck in it.
constexpr double kMeshLargerThanCage = 4;
constexpr double kMeshSmallerThanCage = 1e-3;

MeshPlacement measureMeshPlacement(const Cage& cage, const Eigen::MatrixXd& points);

// One sentence saying what is wrong and what to do, when the mesh is too large, too small or beside the cage;
// nothing when it fits. meshPath and cagePath name the files.
std::optional<std::string> describeMeshPlacement(const MeshPlacement& placement, const std::string& meshPath,
                                                 const std::string& cagePath);

}  // namespace somicage
