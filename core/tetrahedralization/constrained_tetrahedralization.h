// A constrained Delaunay tetrahedralization of a 3D cage's interior with TetGen (Debian's libtet; docs/engine.md,
// "Phong": why). The cage's triangles are kept as they are (no vertex added on them); Steiner vertices go inside
// only where the cage has no tetrahedralization without them (Schoenhardt-like concavities). Milliseconds for a
// cage: level 0 of tetrahedralizeCage; refined to a size, its fallback when Mesh_3 fails or runs out of time.
// Part of the cage generation library (core/CMakeLists.txt).
#pragma once

#include "geometry/volume_mesh.h"

namespace somicage {

// The tetrahedra of a closed, consistently oriented triangle cage: its vertices first, in order, exactly; then the
// Steiner vertices. maxVolume > 0 bounds each tetrahedron's volume and asks for a radius-edge ratio of 2 instead,
// with Steiner vertices on the cage's faces too. Throws InputError when TetGen refuses the cage (e.g. it
// intersects itself).
VolumeMesh constrainedTetrahedralization(const Cage& cage, double maxVolume = 0);

}  // namespace somicage
