#include "mean_value_coordinates.h"

#include "errors.h"

namespace somicage {

// Placeholder until the comparison-methods work lands.
std::unique_ptr<CageDeformer> makeMeanValueDeformer(const Cage&, const Eigen::MatrixXd&, const PrecomputeOptions&,
                                                const ProgressCallback&) {
  throw InputError("--method", -1, "method 'mvc' is not available yet", "use --method somigliana");
}

}  // namespace somicage
