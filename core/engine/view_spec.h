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

#include "deform/deformer.h"
#include "deform/parameter_schema.h"

namespace somicage {

struct ViewSpec {
  Method method;
  // Its own parameter values (parameter_schema.h), by key ("nu", "variant": the value as the row holds it: a
  // choice's index, a switch's 1 or 0); a parameter not here follows the panel's.
  std::map<std::string, double> own;
  // The method's own precompute options (MethodDescriptor::options), e.g. Phong's {"tet-level": "2"}: views that
  // differ here have deformers of their own (the Fig. 8 demo's coarse and finer tetrahedra).
  MethodOptions options;

  // The parameters this view deforms with: `shared` with this view's own values in place.
  DeformParams params(const DeformParams& shared) const;
  bool overrides() const { return !own.empty(); }
  // Its own value of the parameter, if it has one.
  std::optional<double> value(const std::string& key) const;
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

// "METHOD[:KEY=VALUE]..." (--view): KEY is a parameter's view key (parameter_schema.h: nu=X, gamma=Y,
// variant=local, traction=on|off, bulging=B, ...) or one of the method's own options (phong:tet-level=2). Throws
// InputError(option, ...) naming what is wrong: an unknown method or key, a repeated key, a bad value.
ViewSpec parseViewSpec(const std::string& text, const std::string& option);

// "nu, gamma, variant, traction, ...": every parameter's --view key, for help texts and messages.
std::string viewKeyList();
// The parameter whose --view key this is (parameter_schema.h), or null.
const ParameterSpec* findViewParameter(const std::string& key);

}  // namespace somicage
