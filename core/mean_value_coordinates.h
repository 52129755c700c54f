// Mean value coordinates (Floater 2003 / Hormann-Floater 2006 in 2D, Ju-Schaefer-Warren 2005 in 3D) as a CageDeformer.
#pragma once

#include <memory>

#include "deformer.h"

namespace somicage {

std::unique_ptr<CageDeformer> makeMeanValueDeformer(const Cage& restCage, const Eigen::MatrixXd& points,
                                                    const PrecomputeOptions& options,
                                                    const ProgressCallback& progress);

}  // namespace somicage
