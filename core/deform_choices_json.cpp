#include "deform_choices_json.h"

#include "errors.h"

namespace somicage {

void writeChoices(const DeformParams& params, JsonValue& object) {
  object.set("variant", JsonValue::string(variantName(params)));
  for (const ChoiceParameter& choice : choiceParameters())
    object.set(choice.name, JsonValue::string(choice.values[static_cast<std::size_t>(choice.get(params))].name));
}

void readChoices(const JsonValue& object, DeformParams& params, const std::string& source) {
  if (const JsonValue* variant = object.find("variant")) {  // its kind; "blend" holds the blend
    const std::string name = variant->isString() ? variant->asString() : "";
    const VariantChoice* choice = findVariant(name);
    if (!choice && name != "blend")
      throw InputError(source, -1, "\"variant\" must be " + variantNameList() + ", or blend",
                       "fix or remove the key (default: the paper's, by \"blend\")");
    params.kind = choice ? static_cast<VariantKind>(choice->kind) : VariantKind::Blend;
  }
  for (const ChoiceParameter& choice : choiceParameters())
    if (const std::optional<int> k = readChoice(object, choice, source)) choice.set(params, *k);
}

std::optional<int> readChoice(const JsonValue& object, const ChoiceParameter& choice, const std::string& source) {
  const JsonValue* value = object.find(choice.name);
  if (!value) return std::nullopt;
  const std::optional<int> k = value->isString() ? findChoice(choice, value->asString()) : std::nullopt;
  if (!k)
    throw InputError(source, -1, "\"" + std::string(choice.name) + "\" must be " + choiceNameList(choice),
                     "fix or remove the key (default " + std::string(choice.values.front().name) + ")");
  return k;
}

}  // namespace somicage
