// The last step of cage generation, in the spirit of Nested Cages' inward flow (Sacht et al. 2015): moves each
// vertex of a cage that encloses a mesh toward the mesh, one vertex at a time, and keeps a move only when it
// provably keeps the enclosure (exact predicates, CGAL's Epick kernel):
//   - no mesh triangle meets the tetrahedra (old vertex, new vertex, opposite edge) swept by its faces, nor the new
//     faces: no mesh point changes side and no mesh edge crosses the cage;
//   - the new faces cross no other face of the cage (no self-intersection), do not flip their normal, keep their
//     smallest angle above minAngleDegrees (or above what they had), and the vertex stays `clearance` from the mesh.
// So a cage that strictly encloses the mesh before still does after, with the same topology.
#pragma once

#include <Eigen/Core>

#include "base/progress.h"
#include "geometry/cage.h"

namespace somicage {

struct ShrinkOptions {
  double clearance = 0.0;  // the least distance from a moved vertex to the mesh, in the mesh's units
  double minAngleDegrees = 10.0;
  int rounds = 6;  // passes over all vertices (moves, then edge flips)
};

// cage: closed, edge-manifold, outward, strictly enclosing the mesh (meshVertices #V by 3, meshTriangles #T by 3).
// Returns the number of vertex moves made. progress covers [0, 1]; throws Cancelled.
int shrinkTowardMesh(Cage& cage, const Eigen::MatrixXd& meshVertices, const Eigen::MatrixXi& meshTriangles,
                     const ShrinkOptions& options, const ProgressCallback& progress = noProgress);

}  // namespace somicage
