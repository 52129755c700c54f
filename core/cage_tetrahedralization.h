// A tetrahedral mesh of a cage's interior (the volume mesh of volume_mesh.h, for the Phong deformer) with CGAL's
// Mesh_3 (docs/engine.md, "Phong": why Mesh_3). Part of the cage generation library (core/CMakeLists.txt).
#pragma once

#include "volume_mesh.h"

namespace somicage {

// Detail levels of tetrahedralizeCage: 0 keeps about the cage's vertices, each level halves the element size.
constexpr int kTetLevels = 5;  // 0 .. 4
constexpr int kDefaultTetLevel = 1;

// The tetrahedra of a 3D cage's interior: the cage's vertices first, in order, and its faces as the boundary
// (Steiner vertices on the faces and inside). Level L > 0 bounds edges, faces and cells by 2^-(L+1) cage
// diameters. A 2D cage gets the star of its edges when it is star-shaped (starVolumeMesh). Throws InputError
// when Mesh_3 loses a cage vertex or the result is not a mesh of the cage (checkVolumeMesh).
VolumeMesh tetrahedralizeCage(const Cage& cage, int level = kDefaultTetLevel);

// The VolumeMesher of the front ends: the method option "tet-level" (a whole number 0 .. 4, InputError naming
// --tet-level otherwise) passed to tetrahedralizeCage.
VolumeMesh tetrahedralizeCageWithOptions(const Cage& cage, const MethodOptions& options);

}  // namespace somicage
