#include "deform_params.h"

#include <cmath>
#include <sstream>
#include <string>

#include "errors.h"

namespace somicage {

bool operator==(const DeformParams& a, const DeformParams& b) {
  return a.blend == b.blend && a.nu == b.nu && a.gamma == b.gamma && a.tractionCorrection == b.tractionCorrection &&
         a.corotational == b.corotational && a.bulging == b.bulging && a.normals == b.normals && a.kind == b.kind;
}

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

}  // namespace somicage
