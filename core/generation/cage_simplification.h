// Simplifies a closed surface around a mesh down to a face budget without letting it come closer to the mesh than a
// barrier surface: CGAL's edge-collapse simplification (Lindstrom-Turk cost and placement, which keep volume and
// shape) with a filter that refuses a collapse when one of the triangles it makes
//   - crosses the barrier (an AABB tree of the barrier's triangles): the surface keeps its clearance from the mesh;
//   - crosses a triangle of the mesh itself (another AABB tree), in case the barrier has a gap, or sweeps over one
//     (the tetrahedra between the new vertex and the faces it replaces hold no part of the mesh), so that no mesh
//     point changes side;
//   - crosses another triangle of the surface (a uniform grid of the current triangles): no self-intersection;
//   - turns its normal by more than 90 degrees (no fold-over), or has an angle below minAngleDegrees (no needles,
//     unless it replaces a worse one: marching cubes makes slivers).
// A closed input stays closed and edge-manifold (CGAL keeps the topology of each collapse valid).
#pragma once

#include <Eigen/Core>

#include "base/progress.h"
#include "geometry/cage.h"

namespace somicage {

struct SimplificationOptions {
  int maxFaces = 200;
  double minAngleDegrees = 10.0;
};

struct SimplificationResult {
  Cage surface;            // outward, closed, edge-manifold
  bool budgetMet = false;  // false: every remaining collapse was refused above maxFaces
};

// surface and barrier as made by offsetSurfaces (offset_surface.h) around the mesh (meshVertices #V by 3,
// meshTriangles #T by 3). progress covers [0, 1]; throws Cancelled.
SimplificationResult simplifyOutsideBarrier(const Cage& surface, const Cage& barrier,
                                            const Eigen::MatrixXd& meshVertices, const Eigen::MatrixXi& meshTriangles,
                                            const SimplificationOptions& options, const ProgressCallback& progress);

}  // namespace somicage
