// The choice parameters (deform_choices.h) in a session's "params" object: the one writer and reader, for the
// editor's sessions and `somicage animate`.
#pragma once

#include <optional>
#include <string>

#include "deformer.h"
#include "json.h"

namespace somicage {

// Sets "variant": "affine" (the variant's name, or "blend" for the paper's at 0 < blend < 1; the blend itself is
// the session's "blend") and "bulging": "solid-angle", ..., one key per choice parameter.
void writeChoices(const DeformParams& params, JsonValue& object);

// Reads the choice keys present in object into params (an absent key, as in sessions saved before the choice
// existed, keeps params' value). Throws InputError(source, ...) naming the key and its values on a bad value.
void readChoices(const JsonValue& object, DeformParams& params, const std::string& source);
// One choice key of object: its value's index, none when absent; throws as readChoices on a bad value (the
// session's "views" entries read their own choices with it).
std::optional<int> readChoice(const JsonValue& object, const ChoiceParameter& choice, const std::string& source);

}  // namespace somicage
