// Repairs the cage defects that have only one sensible fix and move no vertex: face orientation.
//   3D: per connected component of a closed, edge-manifold triangle mesh, the faces are oriented consistently by a
//       breadth-first walk over shared edges (the majority orientation of the component wins), then the component
//       is flipped when its normals point into the solid: a component nested inside an odd number of others (all
//       its vertices inside each) bounds a cavity and must have a negative signed volume, every other one (crossing
//       components included) a positive volume.
//   2D: the same walk over shared vertices makes each loop's edges follow each other, then each clockwise loop
//       (negative signed area; a loop inside an odd number of others: positive) is reversed.
// Nothing is repaired when the cage has invalid indices, a face that repeats a vertex, a boundary, a non-manifold
// ridge, or no consistent orientation (a Moebius-like surface): validateCage then reports it. Vertices (order and
// count) and the face order never change, so a posed cage still matches; a repaired face lists its corners in
// reverse order ((a, b, c) becomes (c, b, a)), which undoes exactly the same reversal in the file.
#pragma once

#include <string>
#include <vector>

#include "geometry/cage.h"

namespace somicage {

struct CageRepair {
  Cage cage;                       // the input, with some faces reversed
  std::vector<std::string> fixes;  // one sentence per repair done, naming the first few faces; empty: unchanged
};

CageRepair repairCage(const Cage& cage);

}  // namespace somicage
