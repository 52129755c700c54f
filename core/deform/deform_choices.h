// The deformation parameters that take one of a few named values (--bulging, --normals): their one table. The
// command line, the editor (panel, command line, sessions), Python and Blender read their names, help texts and
// defaults from it, so a new choice is a row here and its use in the deformer (docs/engine.md, "Choices").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "deform/method.h"

namespace somicage {

struct DeformParams;

// How the normal stretch eta_j grows with bulging (section 4.4; docs/engine.md, "Bulging conventions").
enum class Bulging {
  SolidAngle,   // the paper's text: eta = lambda exp(gamma dOmega / (2^(d-1) pi)), signed solid angle (default)
  Reference,    // the authors' code: gamma^2 and the unsigned solid angle
  SweptVolume,  // the authors' second measure: eta = lambda exp(gamma^2 V_e / V_0)
  Polygon,      // SolidAngle summed over each planar polygon of the rest cage: independent of how it is split
};

// How vertex normals (for bulging) and vertex rotations average their incident faces.
enum class NormalWeights {
  Area,   // by face area (the paper's; default)
  Angle,  // by corner angle: a planar region's normals do not depend on its triangulation
};

struct ChoiceValue {
  const char* name;         // "solid-angle": the option's value, the session's and Python's string
  const char* description;  // one line for help texts and tooltips
};

struct ChoiceParameter {
  const char* name;         // "bulging": --bulging, the session key, Python's keyword, Blender's property
  const char* description;  // one line for help texts and tooltips
  DeformParameter parameter;
  std::vector<ChoiceValue> values;  // index = the enum's value; values[0] is the default
  int (*get)(const DeformParams& params);
  void (*set)(DeformParams& params, int value);
};

// The variants by name (--variant, sessions' views, Python's variant=, Blender): the paper's global and local (the
// blend's ends) and the two beyond it. Each sets DeformParams::kind and blend.
struct VariantChoice {
  const char* name;         // "global"
  const char* description;  // one line for help texts and tooltips
  int kind;                 // VariantKind (deformer.h)
  double blend;
};
const std::vector<VariantChoice>& variantChoices();  // global, local, affine, stable
const VariantChoice* findVariant(const std::string& name);
std::string variantNameList();  // "global, local, affine or stable"
// The variant of params: its VariantChoice's name, or "blend" for the paper's variant at 0 < blend < 1.
std::string variantName(const DeformParams& params);
// Sets kind and blend; throws InputError(source, ...) naming the variants when there is none of that name.
void setVariant(DeformParams& params, const std::string& name, const std::string& source);

// Every choice parameter, in the order help texts and panels list them.
const std::vector<ChoiceParameter>& choiceParameters();

// The value's index, or none when the parameter has no value of that name.
std::optional<int> findChoice(const ChoiceParameter& parameter, const std::string& value);
// "solid-angle, reference or swept-volume": for help texts and hints.
std::string choiceNameList(const ChoiceParameter& parameter);
// The value's index; throws InputError(source, ...) naming the values when there is none of that name.
int parseChoice(const ChoiceParameter& parameter, const std::string& value, const std::string& source);

}  // namespace somicage
