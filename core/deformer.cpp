#include "deformer.h"

#include <cmath>
#include <sstream>
#include <string>

#include "errors.h"

namespace somicage {

namespace {
// A parameter value as the user would type it: 0.7, 1e+06, inf.
std::string text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}
}  // namespace

std::string rangeText(const ParameterRange& range, bool open) {
  return (open ? "(" : "[") + text(range.min) + ", " + text(range.max) + (open ? ")" : "]");
}

void validateDeformParams(const DeformParams& params) {
  if (std::isnan(params.nu) || (!std::isinf(params.nu) && (params.nu <= kNuRange.min || params.nu >= kNuRange.max)))
    throw InputError("nu", -1, "Poisson ratio " + text(params.nu) + " is out of range",
                     "use a value in " + rangeText(kNuRange, true) + ", or inf / -inf for the limit");
  if (!(params.gamma >= kGammaRange.min && params.gamma <= kGammaRange.max))
    throw InputError("gamma", -1, "bulging scale " + text(params.gamma) + " is out of range",
                     "use a value in " + rangeText(kGammaRange) +
                         ": beyond it a face's normal stretch, up to exp(gamma), loses all meaning");
  if (!(params.blend >= kBlendRange.min && params.blend <= kBlendRange.max))
    throw InputError("blend", -1, "blend " + text(params.blend) + " is outside " + rangeText(kBlendRange),
                     "use 0 for the global variant, 1 for the local variant, or a value in between");
}

void CageDeformer::deform(const Eigen::MatrixXd& posedVertices, const DeformParams& params,
                          Eigen::MatrixXd& out) const {
  evaluateFrame(coordinates_, frameWeights(posedVertices, params), dim(), threads_, out);
}

std::unique_ptr<CageDeformer> makeDeformer(Method method, const Cage& restCage, const Eigen::MatrixXd& points,
                                           const PrecomputeOptions& options, const ProgressCallback& progress) {
  return method->precompute(restCage, points, options, progress);
}

}  // namespace somicage
