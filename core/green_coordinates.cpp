#include "green_coordinates.h"

#include "errors.h"

namespace somicage {

// Placeholder until the comparison-methods work lands.
std::unique_ptr<CageDeformer> makeGreenDeformer(const Cage&, const Eigen::MatrixXd&, const PrecomputeOptions&,
                                                const ProgressCallback&) {
  throw InputError("--method", -1, "method 'green' is not available yet", "use --method somigliana");
}

}  // namespace somicage
