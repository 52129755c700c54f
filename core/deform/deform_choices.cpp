#include "deform/deform_choices.h"

#include "base/errors.h"
#include "deform/deformer.h"

namespace somicage {

const std::vector<ChoiceParameter>& choiceParameters() {
  static const std::vector<ChoiceParameter> table{
      {"bulging",
       "how the normal stretch grows with gamma",
       kParamBulging,
       {{"solid-angle", "the paper's text: exp(gamma x change of the signed solid angle of the vertex normals / 4 pi)"},
        {"reference", "the authors' code: gamma squared and the unsigned solid angle (the paper's figures)"},
        {"swept-volume", "the authors' second measure: exp(gamma^2 x volume the face swept / cage volume)"},
        {"polygon", "solid-angle per flat polygon: coplanar neighbours share one eta, whatever their split"}},
       [](const DeformParams& p) { return static_cast<int>(p.bulging); },
       [](DeformParams& p, int v) { p.bulging = static_cast<Bulging>(v); }},
      {"normals",
       "how vertex normals and vertex rotations weight their faces",
       kParamNormals,
       {{"area", "by face area (the paper's)"},
        {"angle", "by corner angle: a flat region's normals do not depend on how it is triangulated"}},
       [](const DeformParams& p) { return static_cast<int>(p.normals); },
       [](DeformParams& p, int v) { p.normals = static_cast<NormalWeights>(v); }},
  };
  return table;
}

const std::vector<VariantChoice>& variantChoices() {
  static const std::vector<VariantChoice> table{
      {"global", "one best-fit rotation for the whole cage (the paper's, Fig. 4)", int(VariantKind::Blend), 0.0},
      {"local", "per-face rotations blended to the vertices (the paper's, Fig. 4)", int(VariantKind::Blend), 1.0},
      {"affine", "global with the best-fit affine map: reproduces any affine pose exactly", int(VariantKind::Affine),
       0.0},
      {"stable", "local without the fold-overs local makes at high nu", int(VariantKind::Stable), 1.0},
  };
  return table;
}

const VariantChoice* findVariant(const std::string& name) {
  for (const VariantChoice& v : variantChoices())
    if (name == v.name) return &v;
  return nullptr;
}

std::string variantNameList() {
  std::string list;
  const std::vector<VariantChoice>& all = variantChoices();
  for (std::size_t k = 0; k < all.size(); ++k)
    list += (k == 0 ? "" : k + 1 == all.size() ? " or " : ", ") + std::string(all[k].name);
  return list;
}

std::string variantName(const DeformParams& params) {
  for (const VariantChoice& v : variantChoices())
    if (static_cast<int>(params.kind) == v.kind && (params.kind != VariantKind::Blend || params.blend == v.blend))
      return v.name;
  return "blend";
}

void setVariant(DeformParams& params, const std::string& name, const std::string& source) {
  const VariantChoice* v = findVariant(name);
  if (!v) throw InputError(source, -1, "'" + name + "' is not a choice", "use " + variantNameList());
  params.kind = static_cast<VariantKind>(v->kind);
  params.blend = v->blend;
}

std::optional<int> findChoice(const ChoiceParameter& parameter, const std::string& value) {
  for (std::size_t k = 0; k < parameter.values.size(); ++k)
    if (value == parameter.values[k].name) return static_cast<int>(k);
  return std::nullopt;
}

std::string choiceNameList(const ChoiceParameter& parameter) {
  std::string list;
  const std::size_t n = parameter.values.size();
  for (std::size_t k = 0; k < n; ++k)
    list += (k == 0 ? "" : k + 1 == n ? " or " : ", ") + std::string(parameter.values[k].name);
  return list;
}

int parseChoice(const ChoiceParameter& parameter, const std::string& value, const std::string& source) {
  if (const std::optional<int> k = findChoice(parameter, value)) return *k;
  throw InputError(source, -1, std::string(parameter.name) + " '" + value + "' is not a choice",
                   "use " + choiceNameList(parameter));
}

}  // namespace somicage
