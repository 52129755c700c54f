// The deformation gradient J(x) = df/dx of a cage map at the points a deformer was made for, exact to rounding:
// the method's coordinate gradients (CageDeformer::coordinateGradients: dual numbers through its closed forms)
// go through the same frame weights W as the coordinates, dy/dx_a = (dC/dx_a) W, and then through the frame's
// solve in dual numbers (frame_point_kernel.h): df/dx_a = T^-1 (db/dx_a - (dT/dx_a) T^-1 b) (Eq. 11).
//
// Points that follow the exterior rule (exterior_points.h: outside the cage, on it, or with unreliable integrals)
// have no J of their own map here: their rows are NaN and defined() is false. Their positions are the deformer's.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "deform/deformer.h"

namespace somicage {

class DeformationGradients {
 public:
  // Integrates the coordinate gradients of `points` (the deformer's points, #P by d): d matrices the size of the
  // deformer's point rows of C, held until this object is destroyed (estimateGradientBytes). Front ends take them
  // from CageDeformer::gradients, which makes them once per deformer and keeps them; this constructor is the
  // cache's (and `bench`'s, which times it).
  DeformationGradients(const CageDeformer& deformer, const Eigen::MatrixXd& points,
                       const ProgressCallback& progress = noProgress);

  int dim() const { return deformer_.dim(); }
  int numPoints() const { return static_cast<int>(defined_.size()); }
  bool defined(int p) const { return defined_[static_cast<std::size_t>(p)] != 0; }
  int undefinedCount() const;
  std::size_t bytes() const;

  // For a posed cage: the deformed points (#P by d, as CageDeformer::deform) and J (#P by d*d, row-major per
  // point: column a*d + b holds df_a/dx_b; NaN rows where !defined(p)). One pass over C and one over each gradient.
  void evaluate(const Eigen::MatrixXd& posedVertices, const DeformParams& params, Eigen::MatrixXd& positions,
                Eigen::MatrixXd& jacobians) const;
  // The same for frame weights the caller made (the stable variant's fold check: fold_check.h).
  void evaluate(const FrameWeights& W, Eigen::MatrixXd& positions, Eigen::MatrixXd& jacobians) const;

 private:
  const CageDeformer& deformer_;
  std::vector<FrameCoordinates> gradients_;
  std::vector<char> defined_;
};

}  // namespace somicage
