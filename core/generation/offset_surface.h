// The closed surface at a distance from a triangle soup (any mesh: open, non-manifold, several components), made
// with OpenVDB: the unsigned distance field of the triangles on a voxel grid, a morphological closing of the solid
// {distance <= offset} (dilate by offset + closing, erode by closing, so that gaps narrower than about twice the
// closing radius fill up), and its boundary meshed by OpenVDB's dual marching cubes.
// The result encloses every triangle at a distance of about `offset` (up to the voxel size), keeps only the outer
// shells (cavities are filled, a shell inside another is dropped), and is oriented outward.
#pragma once

#include <Eigen/Core>

#include "geometry/cage.h"

namespace somicage {

struct OffsetSurfaceOptions {
  double voxelSize = 0.0;  // in the units of the mesh
  double offset = 0.0;     // distance of the surface from the triangles (> voxelSize)
  double closing = 0.0;    // radius of the morphological closing (0: none)
  double barrier = 0.0;    // distance of the barrier surface (0 < barrier < offset), without closing
};

struct OffsetSurfaces {
  Cage surface;  // at `offset`, closed
  Cage barrier;  // at `barrier`: what a simplified surface must not cross to keep a clearance from the mesh
};

// vertices #V by 3, triangles #T by 3. Both results are closed, oriented triangle meshes (possibly several
// components); they may have non-manifold vertices where marching cubes is ambiguous (cage_simplification splits them).
OffsetSurfaces offsetSurfaces(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles,
                              const OffsetSurfaceOptions& options);

}  // namespace somicage
