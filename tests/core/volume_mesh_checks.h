// What the volume mesh tests measure of a mesh.
#pragma once

#include "geometry/volume_mesh.h"

namespace somicage::test {

// The sum of a volume mesh's signed simplex measures: the volume it covers when all are positive.
inline double totalMeasure(const VolumeMesh& mesh) {
  double sum = 0;
  for (int s = 0; s < mesh.numSimplices(); ++s) sum += signedSimplexMeasure(mesh, s);
  return sum;
}

}  // namespace somicage::test
