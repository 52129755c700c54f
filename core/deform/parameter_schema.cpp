#include "deform/parameter_schema.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/errors.h"
#include "base/parse_number.h"

namespace somicage {

namespace {

// The variants (deform_choices.h) as a choice, and "blend": the paper's variant at the blend given by blend
// (what a session holds for 0 < blend < 1).
std::vector<ChoiceValue> variantValues() {
  std::vector<ChoiceValue> values;
  for (const VariantChoice& v : variantChoices()) values.push_back({v.name, v.description});
  values.push_back({"blend", nullptr});  // read, not offered (ParameterSpec::values)
  return values;
}

int variantIndex(const DeformParams& params) {
  const std::string name = variantName(params);
  const std::vector<VariantChoice>& all = variantChoices();
  for (std::size_t k = 0; k < all.size(); ++k)
    if (name == all[k].name) return static_cast<int>(k);
  return static_cast<int>(all.size());  // "blend"
}

void setVariantIndex(DeformParams& params, int index) {
  const std::vector<VariantChoice>& all = variantChoices();
  if (index >= static_cast<int>(all.size())) {  // "blend": keeps the blend
    params.kind = VariantKind::Blend;
    return;
  }
  params.kind = static_cast<VariantKind>(all[static_cast<std::size_t>(index)].kind);
  params.blend = all[static_cast<std::size_t>(index)].blend;
}

const ChoiceParameter& choice(const char* name) {
  for (const ChoiceParameter& c : choiceParameters())
    if (std::string(name) == c.name) return c;
  throw std::logic_error(std::string("no choice parameter ") + name);
}

std::vector<ParameterSpec> builtInRows() {
  const ChoiceParameter& bulging = choice("bulging");
  const ChoiceParameter& normals = choice("normals");
  return {
      {"variant",
       ParameterType::Choice,
       {{"--local", "local"}, {"--global", "global"}},
       nullptr,
       "variant",
       "variant",
       "variant",
       "which boundary conditions Somigliana builds",
       {0, 0},
       false,
       false,
       0.0,
       variantValues(),
       kParamBlend,
       LabelShow::Always,
       [](const DeformParams& p) { return double(variantIndex(p)); },
       [](DeformParams& p, double v) { setVariantIndex(p, static_cast<int>(v)); }},
      {"blend",
       ParameterType::Number,
       {},
       nullptr,
       "blend",
       "blend",
       "blend",
       "blend between the global (0) and local (1) variant; overrides the variant",
       kBlendRange,
       false,
       false,
       0.0,
       {},
       kParamBlend,
       LabelShow::Never,
       [](const DeformParams& p) { return p.blend; },
       [](DeformParams& p, double v) { p.blend = v; }},
      {"nu",
       ParameterType::Number,
       {},
       nullptr,
       "nu",
       "nu",
       "Poisson ratio",
       "Poisson ratio: how much volume is kept (0.5 incompressible), or inf / -inf for the limits",
       kNuRange,
       true,
       true,
       0.0,
       {},
       kParamNu,
       LabelShow::Always,
       [](const DeformParams& p) { return p.nu; },
       [](DeformParams& p, double v) { p.nu = v; }},
      {"gamma",
       ParameterType::Number,
       {},
       nullptr,
       "gamma",
       "gamma",
       "bulging scale",
       "bulging scale: faces stretch along their normals as the cage's solid angles change (section 4.4)",
       kGammaRange,
       false,
       false,
       0.0,
       {},
       kParamGamma,
       LabelShow::Always,
       [](const DeformParams& p) { return p.gamma; },
       [](DeformParams& p, double v) { p.gamma = v; }},
      {"traction-fix",
       ParameterType::Switch,
       {{"--traction-fix", nullptr}},
       "traction",
       "traction_fix",
       "tractionCorrection",
       "traction fix",
       "the traction correction of Eq. 15",
       {0, 1},
       false,
       false,
       1.0,
       {},
       kParamTractionFix,
       LabelShow::WhenSet,
       [](const DeformParams& p) { return p.tractionCorrection ? 1.0 : 0.0; },
       [](DeformParams& p, double v) { p.tractionCorrection = v != 0; }},
      {"corotational",
       ParameterType::Switch,
       {},
       nullptr,
       "corotational",
       "corotational",
       "corotational",
       "remove the cage's best-fit rotation before the linear solve",
       {0, 1},
       false,
       false,
       0.0,
       {},
       kParamCorotational,
       LabelShow::WhenSet,
       [](const DeformParams& p) { return p.corotational ? 1.0 : 0.0; },
       [](DeformParams& p, double v) { p.corotational = v != 0; }},
      {"bulging",
       ParameterType::Choice,
       {},
       nullptr,
       "bulging",
       "bulging",
       "bulging",
       bulging.description,
       {0, 0},
       false,
       false,
       0.0,
       bulging.values,
       bulging.parameter,
       LabelShow::WhenSet,
       [](const DeformParams& p) { return double(p.bulging); },
       [](DeformParams& p, double v) { p.bulging = static_cast<Bulging>(static_cast<int>(v)); }},
      {"normals",
       ParameterType::Choice,
       {},
       nullptr,
       "normals",
       "normals",
       "normals",
       normals.description,
       {0, 0},
       false,
       false,
       0.0,
       normals.values,
       normals.parameter,
       LabelShow::WhenSet,
       [](const DeformParams& p) { return double(p.normals); },
       [](DeformParams& p, double v) { p.normals = static_cast<NormalWeights>(static_cast<int>(v)); }},
  };
}

std::vector<ParameterSpec>& schema() {
  static std::vector<ParameterSpec> rows = builtInRows();
  return rows;
}

std::string number(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::string text;
  for (int digits = 15; digits <= 17; ++digits) {  // the shortest that reads back exactly
    std::ostringstream out;
    out.precision(digits);
    out << value;
    text = out.str();
    if (std::stod(text) == value) break;
  }
  return text;
}

std::string nameList(const std::vector<ChoiceValue>& values) {
  std::string list;
  std::vector<const char*> offered;
  for (const ChoiceValue& value : values)
    if (value.description) offered.push_back(value.name);
  for (std::size_t k = 0; k < offered.size(); ++k)
    list += (k == 0 ? "" : k + 1 == offered.size() ? " or " : ", ") + std::string(offered[k]);
  return list;
}

}  // namespace

const std::vector<ParameterSpec>& parameterSchema() { return schema(); }

const ParameterSpec* findParameter(const std::string& key) {
  for (const ParameterSpec& spec : schema())
    if (key == spec.key) return &spec;
  return nullptr;
}

std::string viewKey(const ParameterSpec& spec) { return spec.viewKey ? spec.viewKey : spec.key; }

std::string cliFlag(const ParameterSpec& spec) {
  if (spec.type == ParameterType::Switch && spec.defaultValue != 0) return std::string("--no-") + spec.key;
  return std::string("--") + spec.key;
}

std::string cliValueName(const ParameterSpec& spec) {
  switch (spec.type) {
    case ParameterType::Number:
      return "V";
    case ParameterType::Choice:
      return "NAME";
    case ParameterType::Switch:
      return "on|off";
  }
  return "";
}

std::vector<ParameterFlag> parameterFlags() {
  std::vector<ParameterFlag> flags;
  for (const ParameterSpec& spec : schema()) {
    for (const ParameterAlias& alias : spec.cliAliases) flags.push_back({&spec, alias.flag, alias.value});
    const bool bare = spec.type == ParameterType::Switch;
    flags.push_back({&spec, cliFlag(spec), bare ? (spec.defaultValue != 0 ? "off" : "on") : nullptr});
  }
  return flags;
}

std::string parameterFlagHelp(const ParameterFlag& f) {
  const ParameterSpec& spec = *f.spec;
  if (f.flag != cliFlag(spec))
    return f.fixedValue ? "same as " + cliFlag(spec) + " " + f.fixedValue : std::string(spec.key) + " on or off";
  if (f.fixedValue) return (spec.defaultValue != 0 ? "skip " : "") + std::string(spec.tooltip);  // a switch
  return std::string(spec.tooltip) + ": " + parameterSyntax(spec) + " (default " +
         parameterText(spec, spec.defaultValue) + ")";
}

double parameterValue(const ParameterSpec& spec, const DeformParams& params) {
  if (spec.get) return spec.get(params);
  const auto it = params.extra.find(spec.key);
  return it == params.extra.end() ? spec.defaultValue : it->second;
}

void setParameter(const ParameterSpec& spec, DeformParams& params, double value) {
  if (spec.set)
    spec.set(params, value);
  else
    params.extra[spec.key] = value;
}

std::vector<double> parameterValues(const DeformParams& params) {
  std::vector<double> values;
  for (const ParameterSpec& spec : schema()) values.push_back(parameterValue(spec, params));
  return values;
}

std::string parameterSyntax(const ParameterSpec& spec) {
  switch (spec.type) {
    case ParameterType::Number:
      return "a value in " + rangeText(spec.range, spec.openRange) + (spec.infinities ? ", or inf / -inf" : "");
    case ParameterType::Switch:
      return "on or off";
    case ParameterType::Choice:
      return nameList(spec.values);
  }
  return "";
}

double parseParameter(const ParameterSpec& spec, const std::string& text, const std::string& source) {
  switch (spec.type) {
    case ParameterType::Number:  // its range is the method's to check first (BEM names nu = 0.5 incompressible)
      return parseNumber(text, source);
    case ParameterType::Switch:
      if (text == "on") return 1.0;
      if (text == "off") return 0.0;
      throw InputError(source, -1, "'" + text + "' is not on or off", "give on or off");
    case ParameterType::Choice:
      for (std::size_t k = 0; k < spec.values.size(); ++k)
        if (text == spec.values[k].name) return static_cast<double>(k);
      throw InputError(source, -1, "'" + text + "' is not a choice", "use " + nameList(spec.values));
  }
  return 0.0;
}

std::string parameterText(const ParameterSpec& spec, double value) {
  switch (spec.type) {
    case ParameterType::Number:
      return number(value);
    case ParameterType::Switch:
      return value != 0 ? "on" : "off";
    case ParameterType::Choice:
      return spec.values.at(static_cast<std::size_t>(value)).name;
  }
  return "";
}

void validateParameter(const ParameterSpec& spec, double value) {
  bool ok = !std::isnan(value);
  if (ok && spec.type == ParameterType::Number && !(spec.infinities && std::isinf(value)))
    ok = spec.openRange ? value > spec.range.min && value < spec.range.max
                        : value >= spec.range.min && value <= spec.range.max;
  if (ok && spec.type != ParameterType::Number) {
    const double count = spec.type == ParameterType::Switch ? 2.0 : static_cast<double>(spec.values.size());
    ok = value >= 0 && value < count && value == std::floor(value);
  }
  if (!ok)
    throw InputError(spec.key, -1, std::string(spec.label) + " " + number(value) + " is out of range",
                     "use " + parameterSyntax(spec));
}

ParameterRegistration::ParameterRegistration(ParameterSpec spec) : key_(spec.key) {
  SOMICAGE_ASSERT(!findParameter(key_), "every parameter has its own key");
  schema().push_back(std::move(spec));
}

ParameterRegistration::~ParameterRegistration() {
  std::vector<ParameterSpec>& rows = schema();
  rows.erase(std::remove_if(rows.begin(), rows.end(), [&](const ParameterSpec& s) { return key_ == s.key; }),
             rows.end());
}

}  // namespace somicage
