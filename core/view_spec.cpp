#include "view_spec.h"

#include <cmath>
#include <iterator>

#include "errors.h"
#include "parse_number.h"

namespace somicage {

namespace {

const char* const kViewHint =
    "e.g. --view somigliana:nu=0.45:gamma=1:variant=local:traction=off:bulging=reference:normals=angle";

bool hasMethodOption(Method m, const std::string& key) {
  for (const MethodOptionSpec& o : m->options)
    if (key == o.key) return true;
  return false;
}

// ", or tets, tet-level" for a method with options of its own ("" without).
std::string ownOptionList(Method m, const std::string& lead) {
  std::string list;
  for (const MethodOptionSpec& o : m->options) list += (list.empty() ? lead : ", ") + std::string(o.key);
  return list;
}

std::string optionsHint(Method m) {
  const std::string list = ownOptionList(m, "");
  return list.empty() ? methodName(m) + " has no options of its own" : "its options: " + list;
}

bool sameNumber(const std::optional<double>& a, const std::optional<double>& b) {
  return a.has_value() == b.has_value() && (!a || *a == *b);
}

}  // namespace

DeformParams ViewSpec::params(const DeformParams& shared) const {
  DeformParams p = shared;
  if (nu) p.nu = *nu;
  if (gamma) p.gamma = *gamma;
  if (variant) {
    const VariantChoice& v = variantChoices()[static_cast<std::size_t>(*variant)];
    p.kind = static_cast<VariantKind>(v.kind);
    p.blend = v.blend;
  }
  if (tractionCorrection) p.tractionCorrection = *tractionCorrection;
  for (const auto& [name, value] : choices) findChoiceParameter(name)->set(p, value);
  return p;
}

bool operator==(const ViewSpec& a, const ViewSpec& b) {
  return a.method == b.method && sameNumber(a.nu, b.nu) && sameNumber(a.gamma, b.gamma) && a.variant == b.variant &&
         a.tractionCorrection == b.tractionCorrection && a.choices == b.choices && a.options == b.options;
}

bool operator<(const DeformerKey& a, const DeformerKey& b) {
  return a.method != b.method ? a.method < b.method : a.options < b.options;
}
bool operator==(const DeformerKey& a, const DeformerKey& b) { return a.method == b.method && a.options == b.options; }

std::vector<ViewSpec> viewsOf(const std::vector<Method>& methods) {
  std::vector<ViewSpec> views;
  for (Method m : methods) views.push_back(ViewSpec{m, {}, {}, {}, {}, {}, {}});
  return views;
}

ViewSpec withMethod(ViewSpec view, Method m) {
  view.method = m;
  if (!readsParameter(m, kParamNu)) view.nu.reset();
  if (!readsParameter(m, kParamGamma)) view.gamma.reset();
  if (!readsParameter(m, kParamBlend)) view.variant.reset();
  if (!readsParameter(m, kParamTractionFix)) view.tractionCorrection.reset();
  for (const ChoiceParameter& choice : choiceParameters())
    if (!readsParameter(m, choice.parameter)) view.choices.erase(choice.name);
  for (auto it = view.options.begin(); it != view.options.end();)
    it = hasMethodOption(m, it->first) ? std::next(it) : view.options.erase(it);
  return view;
}

const char* variantName(Variant variant) { return variantChoices()[static_cast<std::size_t>(variant)].name; }

const ChoiceParameter* findChoiceParameter(const std::string& name) {
  for (const ChoiceParameter& choice : choiceParameters())
    if (name == choice.name) return &choice;
  return nullptr;
}

std::optional<Variant> findViewVariant(const std::string& name) {
  if (const VariantChoice* v = findVariant(name))
    return static_cast<Variant>(v - variantChoices().data());
  return std::nullopt;
}

void validateViewSpec(const ViewSpec& view, const std::string& option) {
  const struct {
    bool set;
    DeformParameter parameter;
    const char* name;
  } own[] = {{view.nu.has_value(), kParamNu, "nu"},
             {view.gamma.has_value(), kParamGamma, "gamma"},
             {view.variant.has_value(), kParamBlend, "variant"},
             {view.tractionCorrection.has_value(), kParamTractionFix, "traction"}};
  auto require = [&](DeformParameter parameter, const std::string& name) {
    if (!readsParameter(view.method, parameter))
      throw InputError(option, -1, methodName(view.method) + " does not read " + name,
                       "give " + name + " to a view of " + methodsReading(parameter));
  };
  for (const auto& p : own)
    if (p.set) require(p.parameter, p.name);
  for (const auto& [name, value] : view.choices) {
    const ChoiceParameter* choice = findChoiceParameter(name);
    if (!choice || value < 0 || value >= static_cast<int>(choice->values.size()))
      throw InputError(option, -1, "no choice " + name + " = " + std::to_string(value), kViewHint);
    require(choice->parameter, name);
  }
  for (const auto& [key, value] : view.options) {
    if (!hasMethodOption(view.method, key))
      throw InputError(option, -1, methodName(view.method) + " has no option " + key, optionsHint(view.method));
    for (const MethodOptionSpec& spec : view.method->options) {
      if (!spec.check || key != spec.key) continue;
      try {  // its value too, here rather than at the precompute
        spec.check(value);
      } catch (const InputError& e) {
        throw InputError(option, -1, methodName(view.method) + " " + key + ": " + e.problem(), e.hint());
      }
    }
  }
  // Only the view's own values are checked here: the shared ones are the panel's (checked where they are set).
  DeformParams p;
  if (view.nu) p.nu = *view.nu;
  if (view.gamma) p.gamma = *view.gamma;
  try {
    view.method->validateParams(p);
  } catch (const InputError& e) {
    throw InputError(option, -1, methodName(view.method) + " " + e.source() + ": " + e.problem(), e.hint());
  }
}

ViewSpec parseViewSpec(const std::string& text, const std::string& option) {
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const std::size_t colon = text.find(':', start);
    parts.push_back(text.substr(start, colon == std::string::npos ? std::string::npos : colon - start));
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  const std::optional<Method> method = findMethod(parts.front());
  if (!method)
    throw InputError(option, -1, "unknown method '" + parts.front() + "' in '" + text + "'",
                     "start with one of " + methodNameList() + ", " + kViewHint);
  ViewSpec view{*method, {}, {}, {}, {}, {}, {}};
  for (std::size_t i = 1; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    const std::size_t eq = part.find('=');
    const std::string key = part.substr(0, eq), value = eq == std::string::npos ? "" : part.substr(eq + 1);
    if (eq == std::string::npos || value.empty())
      throw InputError(option, -1, "expected KEY=VALUE after ':', got '" + part + "' in '" + text + "'", kViewHint);
    auto once = [&](bool alreadySet) {
      if (alreadySet) throw InputError(option, -1, "'" + key + "' given twice in '" + text + "'", kViewHint);
    };
    if (key == "nu") {
      once(view.nu.has_value());
      view.nu = parseNumber(value, option + " nu");
    } else if (key == "gamma") {
      once(view.gamma.has_value());
      view.gamma = parseNumber(value, option + " gamma");
    } else if (key == "variant") {
      once(view.variant.has_value());
      view.variant = findViewVariant(value);
      if (!view.variant)
        throw InputError(option, -1, "variant must be " + variantNameList() + ", got '" + value + "'", kViewHint);
    } else if (key == "traction") {
      once(view.tractionCorrection.has_value());
      if (value != "on" && value != "off")
        throw InputError(option, -1, "traction must be on or off, got '" + value + "'", kViewHint);
      view.tractionCorrection = value == "on";
    } else if (const ChoiceParameter* choice = findChoiceParameter(key)) {
      once(view.choices.count(key) > 0);
      const std::optional<int> index = findChoice(*choice, value);
      if (!index)
        throw InputError(option, -1, key + " must be " + choiceNameList(*choice) + ", got '" + value + "'", kViewHint);
      view.choices[key] = *index;
    } else if (hasMethodOption(view.method, key)) {
      once(view.options.count(key) > 0);
      view.options[key] = value;
    } else {
      std::string keys = "nu, gamma, variant, traction";
      for (const ChoiceParameter& c : choiceParameters()) keys += std::string(", ") + c.name;
      throw InputError(option, -1,
                       "unknown key '" + key + "' in '" + text + "' (expected " + keys +
                           ownOptionList(view.method, ", or ") + ")",
                       kViewHint);
    }
  }
  validateViewSpec(view, option);
  return view;
}

}  // namespace somicage
