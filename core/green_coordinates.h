// Green coordinates (Lipman, Levin, Cohen-Or 2008), 2D and 3D, as a CageDeformer.
#pragma once

#include <memory>

#include "deformer.h"

namespace somicage {

std::unique_ptr<CageDeformer> makeGreenDeformer(const Cage& restCage, const Eigen::MatrixXd& points,
                                                const PrecomputeOptions& options, const ProgressCallback& progress);

}  // namespace somicage
