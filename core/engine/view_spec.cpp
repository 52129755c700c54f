#include "engine/view_spec.h"

#include <cmath>
#include <iterator>

#include "base/errors.h"
#include "base/parse_number.h"

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

}  // namespace

DeformParams ViewSpec::params(const DeformParams& shared) const {
  DeformParams p = shared;
  for (const ParameterSpec& spec : parameterSchema())  // in the table's order: variant before blend
    if (const std::optional<double> v = value(spec.key)) setParameter(spec, p, *v);
  return p;
}

std::optional<double> ViewSpec::value(const std::string& key) const {
  const auto it = own.find(key);
  return it == own.end() ? std::nullopt : std::optional<double>(it->second);
}

bool operator==(const ViewSpec& a, const ViewSpec& b) {
  return a.method == b.method && a.own == b.own && a.options == b.options;
}

bool operator<(const DeformerKey& a, const DeformerKey& b) {
  return a.method != b.method ? a.method < b.method : a.options < b.options;
}
bool operator==(const DeformerKey& a, const DeformerKey& b) { return a.method == b.method && a.options == b.options; }

std::vector<ViewSpec> viewsOf(const std::vector<Method>& methods) {
  std::vector<ViewSpec> views;
  for (Method m : methods) views.push_back(ViewSpec{m, {}, {}});
  return views;
}

ViewSpec withMethod(ViewSpec view, Method m) {
  view.method = m;
  for (const ParameterSpec& spec : parameterSchema())
    if (!readsParameter(m, spec.parameter)) view.own.erase(spec.key);
  for (auto it = view.options.begin(); it != view.options.end();)
    it = hasMethodOption(m, it->first) ? std::next(it) : view.options.erase(it);
  return view;
}

std::string viewKeyList() {
  std::string keys;
  for (const ParameterSpec& spec : parameterSchema()) keys += (keys.empty() ? "" : ", ") + viewKey(spec);
  return keys;
}

const ParameterSpec* findViewParameter(const std::string& key) {
  for (const ParameterSpec& spec : parameterSchema())
    if (key == viewKey(spec)) return &spec;
  return nullptr;
}

void validateViewSpec(const ViewSpec& view, const std::string& option) {
  for (const auto& [key, value] : view.own) {
    const ParameterSpec* spec = findParameter(key);
    if (!spec) throw InputError(option, -1, "no parameter " + key, kViewHint);
    if (!readsParameter(view.method, spec->parameter))
      throw InputError(option, -1, methodName(view.method) + " does not read " + viewKey(*spec),
                       "give " + viewKey(*spec) + " to a view of " + methodsReading(spec->parameter));
    if (spec->type != ParameterType::Number) {  // a name's index or a switch (numbers: the method's check below)
      try {
        validateParameter(*spec, value);
      } catch (const InputError& e) {
        throw InputError(option, -1, methodName(view.method) + " " + e.source() + ": " + e.problem(), e.hint());
      }
    }
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
  DeformParams p;  // the defaults, with the view's own values: its method checks their ranges
  for (const auto& [key, value] : view.own) setParameter(*findParameter(key), p, value);
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
  ViewSpec view{*method, {}, {}};
  for (std::size_t i = 1; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    const std::size_t eq = part.find('=');
    const std::string key = part.substr(0, eq), value = eq == std::string::npos ? "" : part.substr(eq + 1);
    if (eq == std::string::npos || value.empty())
      throw InputError(option, -1, "expected KEY=VALUE after ':', got '" + part + "' in '" + text + "'", kViewHint);
    auto once = [&](bool alreadySet) {
      if (alreadySet) throw InputError(option, -1, "'" + key + "' given twice in '" + text + "'", kViewHint);
    };
    if (const ParameterSpec* spec = findViewParameter(key)) {
      once(view.own.count(spec->key) > 0);
      view.own[spec->key] = parseParameter(*spec, value, option + " " + key);
    } else if (hasMethodOption(view.method, key)) {
      once(view.options.count(key) > 0);
      view.options[key] = value;
    } else {
      throw InputError(option, -1,
                       "unknown key '" + key + "' in '" + text + "' (expected " + viewKeyList() +
                           ownOptionList(view.method, ", or ") + ")",
                       kViewHint);
    }
  }
  validateViewSpec(view, option);
  return view;
}

}  // namespace somicage
