#include "deform/deform_params.h"

#include <cmath>
#include <sstream>
#include <string>

#include "base/errors.h"
#include "deform/parameter_schema.h"

namespace somicage {

bool operator==(const DeformParams& a, const DeformParams& b) {
  return a.blend == b.blend && a.nu == b.nu && a.gamma == b.gamma && a.tractionCorrection == b.tractionCorrection &&
         a.corotational == b.corotational && a.bulging == b.bulging && a.normals == b.normals && a.kind == b.kind &&
         a.extra == b.extra;
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
  if (params.kind != VariantKind::Blend && params.kind != VariantKind::Affine && params.kind != VariantKind::Stable)
    throw InputError("variant", -1, "variant kind " + std::to_string(static_cast<int>(params.kind)) + " is unknown",
                     "use " + variantNameList());
  for (const ParameterSpec& spec : parameterSchema()) validateParameter(spec, parameterValue(spec, params));
}

}  // namespace somicage
