// The simplex of a volume mesh (volume_mesh.h) that holds a point, and the point's barycentric coordinates in it,
// through a uniform grid of the simplices' bounding boxes: a query tests the few simplices of one cell, never all.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/volume_mesh.h"

namespace somicage {

class SimplexLocator {
 public:
  explicit SimplexLocator(const VolumeMesh& mesh);

  // Barycentric coordinates below -kTolerance put a point outside a simplex: round-off on a face (a point on
  // the cage, or on a face between two simplices) still finds a simplex.
  static constexpr double kTolerance = 1e-10;

  struct Location {
    int simplex = -1;             // -1: in no simplex (outside the cage)
    Eigen::VectorXd barycentric;  // d + 1 numbers summing to 1, for vertex k of the simplex
  };
  // Of the simplices holding x, the one in which x lies deepest (largest smallest coordinate).
  Location locate(const Eigen::VectorXd& x) const;

  // The barycentric coordinates of x in simplex s (extrapolated outside it).
  Eigen::VectorXd barycentric(int s, const Eigen::VectorXd& x) const;
  // The gradients of simplex s's barycentric coordinates (volume_mesh.h: barycentricGradients).
  const Eigen::MatrixXd& gradients(int s) const { return gradients_[static_cast<std::size_t>(s)]; }

 private:
  const VolumeMesh& mesh_;
  std::vector<Eigen::MatrixXd> gradients_;
  Eigen::VectorXd lower_, cellSize_;
  Eigen::VectorXi cells_;                  // per axis
  std::vector<std::vector<int>> buckets_;  // per cell, the simplices whose box meets it
  int cellIndex(const Eigen::VectorXi& cell) const;
};

}  // namespace somicage
