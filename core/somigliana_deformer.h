// The corotational Somigliana deformer (paper Eqs. 10-15) over precomputed Somigliana coordinates.
#pragma once

#include <memory>

#include "deformer.h"

namespace somicage {

std::unique_ptr<CageDeformer> makeSomiglianaDeformer(const Cage& restCage, const Eigen::MatrixXd& points,
                                                     const PrecomputeOptions& options,
                                                     const ProgressCallback& progress);

// The same from coordinates already integrated for these points (e.g. to inspect them first, as the benchmark does).
std::unique_ptr<CageDeformer> makeSomiglianaDeformer(const Cage& restCage, const SomiglianaCoordinates& coords,
                                                     const Eigen::MatrixXd& points, const PrecomputeOptions& options);

}  // namespace somicage
