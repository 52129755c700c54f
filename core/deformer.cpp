#include "deformer.h"

#include <cmath>
#include <sstream>
#include <string>

#include "errors.h"
#include "medit_io.h"

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

Eigen::MatrixXd CageDeformer::posedVolumeMesh(const Eigen::MatrixXd&, const DeformParams&) const {
  return Eigen::MatrixXd(0, dim());
}

void CageDeformer::deform(const Eigen::MatrixXd& posedVertices, const DeformParams& params,
                          Eigen::MatrixXd& out) const {
  evaluateFrame(coordinates_, frameWeights(posedVertices, params), dim(), threads_, out);
}

std::shared_ptr<const VolumeMesh> volumeMeshFor(const Cage& restCage, const PrecomputeOptions& options,
                                                int* reoriented) {
  if (options.volumeMesh) return options.volumeMesh;
  int flipped = 0;
  std::shared_ptr<VolumeMesh> mesh;
  if (const auto file = options.methodOptions.find("tets"); file != options.methodOptions.end()) {
    MeditMesh read = readMedit(file->second);
    flipped = checkVolumeMesh(read.mesh, restCage, read.source);
    mesh = std::make_shared<VolumeMesh>(std::move(read.mesh));
  } else if (std::unique_ptr<VolumeMesh> star =
                 options.methodOptions.count("tet-level") == 0 ? starVolumeMesh(restCage) : nullptr) {
    mesh = std::move(star);  // the coarsest mesh there is, the same in every front end
  } else if (options.volumeMesher) {
    mesh = std::make_shared<VolumeMesh>(options.volumeMesher(restCage, options.methodOptions));
    try {
      flipped = checkVolumeMesh(*mesh, restCage, {"the generated tetrahedral mesh", {}, {}});
    } catch (const InputError& e) {  // e.g. a sliver CGAL left flat: the user can only change the level
      throw InputError("--tet-level", -1, "the generated tetrahedral mesh is unusable: " + e.problem(),
                       "try another --tet-level, or give a tetrahedral mesh with --tets");
    }
  } else {
    throw InputError("--tets", -1, "the cage needs a tetrahedral mesh, and it is not star-shaped from its centroid",
                     "give one with --tets FILE.mesh (Python: tets=), or use a front end that tetrahedralizes cages "
                     "(the somicage command, the editor)");
  }
  if (reoriented) *reoriented = flipped;
  return mesh;
}

std::unique_ptr<CageDeformer> makeDeformer(Method method, const Cage& restCage, const Eigen::MatrixXd& points,
                                           const PrecomputeOptions& options, const ProgressCallback& progress) {
  return method->precompute(restCage, points, options, progress);
}

}  // namespace somicage
