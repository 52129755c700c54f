// One pose of a mesh, measured: the deformed points and their exact J (jacobian.h) and every quantity derived from
// them (deformation_quantities.h); and the nu sweep, which re-evaluates only the cheap per-frame weights (nu never
// re-integrates, paper section 5).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "analysis/deformation_quantities.h"
#include "analysis/seam_jumps.h"
#include "deform/jacobian.h"

namespace somicage {

struct DeformationAnalysis {
  Eigen::MatrixXd positions;  // #P by d
  Eigen::MatrixXd jacobians;  // #P by d*d (jacobian.h)
  PointQuantities points;
  FaceQuantities faces;
  EnclosedMeasure volume;  // area in 2D
  SeamJumps seams;         // the jumps of J across a volume mesh's faces (seam_jumps.h); empty when not measured
};

// restPoints: the points the gradients were made for (#P by d); faces: the mesh's faces over them (may be empty);
// seams: the same mesh's seam evaluator (null: not measured).
DeformationAnalysis analyzeDeformation(const DeformationGradients& gradients, const Eigen::MatrixXd& restPoints,
                                       const std::vector<std::vector<int>>& faces, const Eigen::MatrixXd& posedVertices,
                                       const DeformParams& params, const SeamJumpEvaluator* seams = nullptr);

struct NuSweepEntry {
  double nu = 0;
  double volumeChange = 0;  // deformed / rest - 1 (EnclosedMeasure: capped for an open 3D mesh)
  int foldovers = 0;
};

// The values nu_k = from + k (to - from) / (count - 1), k < count, of a sweep; throws InputError (source "--nu-sweep")
// unless -1 < from, to < 0.5 and count >= 2.
std::vector<double> nuSweepValues(double from, double to, int count);

// analyzeDeformation's volume change and fold-over count at each nu (the other parameters as given).
std::vector<NuSweepEntry> sweepNu(const DeformationGradients& gradients, const Eigen::MatrixXd& restPoints,
                                  const std::vector<std::vector<int>>& faces, const Eigen::MatrixXd& posedVertices,
                                  DeformParams params, const std::vector<double>& nus,
                                  const ProgressCallback& progress = noProgress);

}  // namespace somicage
