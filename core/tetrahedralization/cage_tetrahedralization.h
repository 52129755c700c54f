// A tetrahedral mesh of a cage's interior (the volume mesh of volume_mesh.h, for the Phong deformer): TetGen's
// constrained Delaunay tetrahedralization at level 0, CGAL's Mesh_3 above it, bounded in time and falling back to
// the former (docs/engine.md, "Phong": why these two). Part of the cage generation library (core/CMakeLists.txt).
#pragma once

#include <cstddef>

#include "base/progress.h"
#include "geometry/volume_mesh.h"

namespace somicage {

// How long Mesh_3 may refine before tetrahedralizeCage stops it and falls back to the constrained tetrahedralization.
struct TetrahedralizationBound {
  double seconds = 20;
  std::size_t maxVertices = 500000;  // about 60 MB of triangulation
};

// The tetrahedra of a 3D cage's interior: the cage's vertices first, in order, exactly, and its faces as the
// boundary, all positively oriented, checked by checkVolumeMesh. Level 0: the constrained Delaunay
// tetrahedralization (constrained_tetrahedralization.h). Level L > 0: Mesh_3 bounding edges, faces and cells by
// 2^-(L+1) cage diameters (Steiner vertices on the faces and inside); when it is not done within `bound`, or its
// mesh fails the check (CACTUS's cage: a hole), the constrained tetrahedralization refined to cells of that size,
// with VolumeMesh::fallback saying so and why (the front ends show it as a warning). progress (fraction of
// the bound used, on the calling thread) may stop it: Cancelled. A 2D cage gets the star of its edges when it is
// star-shaped (starVolumeMesh). Throws InputError when neither mesher can mesh the cage.
VolumeMesh tetrahedralizeCage(const Cage& cage, int level = kDefaultTetLevel,
                              const ProgressCallback& progress = noProgress,
                              const TetrahedralizationBound& bound = {});

// The VolumeMesher of the front ends: tetrahedralizeCage at parseTetLevel(options) (volume_mesh.h).
VolumeMesh tetrahedralizeCageWithOptions(const Cage& cage, const MethodOptions& options,
                                         const ProgressCallback& progress = noProgress);

}  // namespace somicage
