// One pane of the editor (issue 12): a method and, optionally, its own values of the shared parameters, so the
// compare view is a list of views and can show the same method at two nu side by side. A parameter a view does not
// set follows the panel's. Deformers stay shared per method (nu, gamma and the variant never re-integrate: one
// precompute per method); the deformed points and the quantities are per view (AppState). Pure, no GL.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "deform_choices.h"
#include "deformer.h"

namespace somicage {

enum class Variant { Global, Local, Affine, Stable };  // core's variantChoices(), in its order

struct ViewSpec {
  Method method;
  std::optional<double> nu, gamma;  // absent: the panel's
  std::optional<Variant> variant;
  std::optional<bool> tractionCorrection;
  // Its own values of the named choices (deform_choices.h): ChoiceParameter::name -> the value's index.
  std::map<std::string, int> choices;

  // The parameters this view deforms with: `shared` with this view's own values in place.
  DeformParams params(const DeformParams& shared) const;
  bool overrides() const { return nu || gamma || variant || tractionCorrection || !choices.empty(); }
};
bool operator==(const ViewSpec& a, const ViewSpec& b);  // exact (bitwise numbers)
inline bool operator!=(const ViewSpec& a, const ViewSpec& b) { return !(a == b); }

// Views of these methods, none overriding anything (--compare a,b; sessions without "views").
std::vector<ViewSpec> viewsOf(const std::vector<Method>& methods);

// The view with method m instead, keeping the own values that m reads (a method ignores the others).
ViewSpec withMethod(ViewSpec view, Method m);

// Throws InputError(option, ...) when a value is out of range for the method (Method's validateParams on the
// resolved parameters) or the view sets a parameter its method does not read ("green does not read nu").
void validateViewSpec(const ViewSpec& view, const std::string& option);

// "METHOD[:nu=X][:gamma=Y][:variant=global|local|affine|stable][:traction=on|off][:bulging=B][:normals=N]" (--view;
// every named choice of deform_choices.h is a key). Throws InputError(option, ...) naming what is wrong: an unknown
// method or key, a repeated key, a bad value.
ViewSpec parseViewSpec(const std::string& text, const std::string& option);

const char* variantName(Variant variant);  // "global", "local", "affine", "stable"
// The choice parameter of that name (deform_choices.h), or null.
const ChoiceParameter* findChoiceParameter(const std::string& name);
std::optional<Variant> findViewVariant(const std::string& name);

}  // namespace somicage
