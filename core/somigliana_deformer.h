// The corotational Somigliana deformer (paper Eqs. 10-15) over precomputed Somigliana coordinates.
#pragma once

#include <memory>

#include "deformer.h"

namespace somicage {

std::unique_ptr<CageDeformer> makeSomiglianaDeformer(const Cage& restCage, const Eigen::MatrixXd& points,
                                                     const PrecomputeOptions& options,
                                                     const ProgressCallback& progress);

}  // namespace somicage
