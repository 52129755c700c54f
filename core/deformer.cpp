#include "deformer.h"

#include <cmath>
#include <string>

#include "errors.h"

namespace somicage {

bool operator==(const DeformParams& a, const DeformParams& b) {
  return a.blend == b.blend && a.nu == b.nu && a.gamma == b.gamma && a.tractionCorrection == b.tractionCorrection &&
         a.corotational == b.corotational && a.bulging == b.bulging && a.normals == b.normals && a.kind == b.kind;
}

void validateDeformParams(const DeformParams& params) {
  if (std::isnan(params.nu) || (!std::isinf(params.nu) && (params.nu <= -1 || params.nu >= 0.5)))
    throw InputError("nu", -1, "Poisson ratio " + std::to_string(params.nu) + " is out of range",
                     "use a value in (-1, 0.5), or inf / -inf for the limit");
  if (!(params.gamma >= 0) || std::isinf(params.gamma))
    throw InputError("gamma", -1, "bulging scale " + std::to_string(params.gamma) + " is invalid",
                     "use a finite value >= 0");
  if (!(params.blend >= 0 && params.blend <= 1))
    throw InputError("blend", -1, "blend " + std::to_string(params.blend) + " is outside [0, 1]",
                     "use 0 for the global variant, 1 for the local variant, or a value in between");
  if (params.kind != VariantKind::Blend && params.kind != VariantKind::Affine && params.kind != VariantKind::Stable)
    throw InputError("variant", -1, "variant kind " + std::to_string(static_cast<int>(params.kind)) + " is unknown",
                     "use " + variantNameList());
  for (const ChoiceParameter& choice : choiceParameters()) {
    const int value = choice.get(params);
    if (value < 0 || value >= static_cast<int>(choice.values.size()))
      throw InputError(choice.name, -1, std::string(choice.name) + " " + std::to_string(value) + " is not a choice",
                       "use " + choiceNameList(choice));
  }
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
