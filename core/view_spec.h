// One pane of the editor (issue 12): a method and, optionally, its own values of the shared parameters, so the
// compare view is a list of views and can show the same method at two nu side by side. A parameter a view does not
// set follows the panel's. Deformers stay shared per method and method options (nu, gamma and the variant never
// re-integrate: one precompute per DeformerKey); the deformed points and the quantities are per view (AppState).
// Pure, no GL.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
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
  // The method's own precompute options (MethodDescriptor::options), e.g. Phong's {"tet-level": "2"}: views that
  // differ here have deformers of their own (the Fig. 8 demo's coarse and finer tetrahedra).
  MethodOptions options;

  // The parameters this view deforms with: `shared` with this view's own values in place.
  DeformParams params(const DeformParams& shared) const;
  bool overrides() const { return nu || gamma || variant || tractionCorrection || !choices.empty(); }
};
bool operator==(const ViewSpec& a, const ViewSpec& b);  // exact (bitwise numbers)
inline bool operator!=(const ViewSpec& a, const ViewSpec& b) { return !(a == b); }

// What a deformer is made from besides the scene: views with equal keys share one.
struct DeformerKey {
  DeformerKey(Method m, MethodOptions o = {}) : method(m), options(std::move(o)) {}  // NOLINT: a method, no options
  DeformerKey(const MethodDescriptor& m) : method(m) {}                               // NOLINT: as Method
  Method method;
  MethodOptions options;
};
inline DeformerKey deformerKey(const ViewSpec& view) { return {view.method, view.options}; }
bool operator<(const DeformerKey& a, const DeformerKey& b);
bool operator==(const DeformerKey& a, const DeformerKey& b);

// Views of these methods, none overriding anything (--compare a,b; sessions without "views").
std::vector<ViewSpec> viewsOf(const std::vector<Method>& methods);

// The view with method m instead, keeping the own values and options that m reads (a method ignores the others).
ViewSpec withMethod(ViewSpec view, Method m);

// Throws InputError(option, ...) when a value is out of range for the method (Method's validateParams on the
// resolved parameters), the view sets a parameter its method does not read ("green does not read nu") or an
// option that is not the method's (an option's value is checked where it is used: the precompute).
void validateViewSpec(const ViewSpec& view, const std::string& option);

// "METHOD[:nu=X][:gamma=Y][:variant=global|local|affine|stable][:traction=on|off][:bulging=B][:normals=N]
// [:OPTION=VALUE]" (--view; every named choice of deform_choices.h is a key, and so is each of the method's own
// options, e.g. phong:tet-level=2). Throws InputError(option, ...) naming what is wrong: an unknown
// method or key, a repeated key, a bad value.
ViewSpec parseViewSpec(const std::string& text, const std::string& option);

const char* variantName(Variant variant);  // "global", "local", "affine", "stable"
// The choice parameter of that name (deform_choices.h), or null.
const ChoiceParameter* findChoiceParameter(const std::string& name);
std::optional<Variant> findViewVariant(const std::string& name);

}  // namespace somicage
