// The deformation parameters (parameter_schema.h) in JSON: the one writer and reader of a session's "params" object
// and of its views' own values, for the editor's sessions, `somicage animate` and Python's load_session.
#pragma once

#include <optional>
#include <string>

#include "base/json.h"
#include "deform/parameter_schema.h"

namespace somicage {

// A value as JSON: a number (a string "inf" / "-inf" for an infinity), true / false, or a choice's name.
JsonValue parameterJson(const ParameterSpec& spec, double value);
// The row's value under its session key in object, none when absent; throws InputError(source, ...) naming the
// key and what it takes when the value is of the wrong kind (a number's range is the method's validateParams to check).
std::optional<double> readParameterJson(const JsonValue& object, const ParameterSpec& spec, const std::string& source);

// Every row under its session key ("variant": "affine", "blend": 0, "nu": "inf", "tractionCorrection": true, ...).
void writeParameters(const DeformParams& params, JsonValue& object);
// The rows present in object set in params, in table order (variant before blend); absent ones keep their value
// (sessions saved before a parameter existed).
void readParameters(const JsonValue& object, DeformParams& params, const std::string& source);

}  // namespace somicage
