#include "deform/parameter_json.h"

#include <cmath>
#include <limits>

#include "base/errors.h"

namespace somicage {

JsonValue parameterJson(const ParameterSpec& spec, double value) {
  switch (spec.type) {
    case ParameterType::Number:
      if (std::isinf(value)) return JsonValue::string(value > 0 ? "inf" : "-inf");
      return JsonValue::number(value);
    case ParameterType::Switch:
      return JsonValue::boolean(value != 0);
    case ParameterType::Choice:
      return JsonValue::string(parameterText(spec, value));
  }
  return JsonValue();
}

std::optional<double> readParameterJson(const JsonValue& object, const ParameterSpec& spec, const std::string& source) {
  const JsonValue* v = object.find(spec.sessionKey);
  if (!v) return std::nullopt;
  const std::string key = std::string("\"") + spec.sessionKey + "\"";
  const auto wrong = [&]() -> double {
    throw InputError(
        source, -1,
        key + " must be " + parameterSyntax(spec) + (spec.type == ParameterType::Switch ? " (true or false)" : ""),
        "fix or remove the key (default " + parameterText(spec, spec.defaultValue) + ")");
  };
  double value = 0;
  switch (spec.type) {
    case ParameterType::Number:
      if (v->isNumber()) {
        value = v->asNumber();
      } else if (spec.infinities && v->isString() && (v->asString() == "inf" || v->asString() == "-inf")) {
        value =
            v->asString() == "inf" ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
      } else {
        wrong();
      }
      break;
    case ParameterType::Switch:
      if (v->type() != JsonValue::Type::Bool) wrong();
      value = v->asBool() ? 1.0 : 0.0;
      break;
    case ParameterType::Choice:
      if (!v->isString()) wrong();
      try {
        value = parseParameter(spec, v->asString(), source);
      } catch (const InputError&) {
        wrong();
      }
      break;
  }
  return value;  // a number's range is checked with the method's words first (validateParams), as parseParameter
}

void writeParameters(const DeformParams& params, JsonValue& object) {
  for (const ParameterSpec& spec : parameterSchema())
    object.set(spec.sessionKey, parameterJson(spec, parameterValue(spec, params)));
}

void readParameters(const JsonValue& object, DeformParams& params, const std::string& source) {
  for (const ParameterSpec& spec : parameterSchema())
    if (const std::optional<double> value = readParameterJson(object, spec, source)) setParameter(spec, params, *value);
}

}  // namespace somicage
