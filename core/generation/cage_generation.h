// Automatic cage generation: a closed, edge-manifold, outward triangle mesh with at most maxFaces faces, free of
// self-intersections, that strictly encloses a mesh (every vertex inside, no edge crossing it).
//
// Pipeline, in units of the mesh's bounding-box diagonal (so that it works the same at any scale):
//   1. offset_surface.h: the surface at distance `margin` around the triangles, after a morphological closing that
//      fills gaps narrower than about 1/sqrt(maxFaces) (detail the budget cannot show anyway); cavities are filled;
//   2. cage_simplification.h: edge collapses down to maxFaces, never crossing a barrier surface at margin / 2,
//      never crossing itself, no fold-overs, no angle below minAngleDegrees;
//   3. cage_enclosure.h: the exact check. Where it fails, the vertices of the faces concerned are pushed outward
//      along their normals and the check repeated; a self-intersection or a budget that could not be met restarts
//      from 1 with a larger margin. After a bounded number of tries, an InputError says what to change.
//   4. cage_shrink.h: vertices move toward the mesh and convex edges flip where exact tests prove the enclosure is
//      kept (an inward flow in the spirit of Nested Cages); the exact check of 3 then has the last word.
// Any mesh: open, several components, non-manifold, with thin parts or handles (a handle may be filled).
#pragma once

#include <Eigen/Core>
#include <string>

#include "base/progress.h"
#include "generation/cage_enclosure.h"
#include "geometry/cage.h"

namespace somicage {

struct CageGenerationOptions {
  int maxFaces = 200;             // at least kMinFaces
  double margin = 0.0;            // distance cage - mesh as a fraction of the bounding-box diagonal; 0: automatic
  double minAngleDegrees = 10.0;  // no triangle of the cage gets a smaller angle

  static constexpr int kMinFaces = 12;
};

struct GeneratedCage {
  Cage cage;
  double margin = 0.0;           // the margin used (fraction of the diagonal), after any retries
  double voxelSize = 0.0;        // of the offset surface, fraction of the diagonal
  double minAngleDegrees = 0.0;  // smallest triangle angle of the cage
  int attempts = 0;              // offset surfaces made (1 unless a try was rejected)
  int repairRounds = 0;          // rounds of pushing vertices outward after the exact check
  CageTightness tightness;       // how closely the cage fits the mesh (cage_enclosure.h)
};

// vertices #V by 3, triangles #T by 3 (any mesh; see triangulatePolygons in obj_io.h for polygons). source names the
// mesh in errors. progress covers the whole call; throws Cancelled when it returns false, InputError when the mesh
// has no triangles or no extent, the options are out of range, or no valid cage was found within the tries.
GeneratedCage generateCage(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles,
                           const CageGenerationOptions& options, const std::string& source,
                           const ProgressCallback& progress = noProgress);

// The smallest angle of the cage's triangles, in degrees.
double minimumAngleDegrees(const Cage& cage);

}  // namespace somicage
