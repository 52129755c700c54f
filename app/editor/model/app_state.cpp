// The views: which are shown, their labels, the compare settings and framing.
#include "model/app_state.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "deform/parameter_schema.h"
#include "geometry/volume_mesh.h"
#include "interaction/gizmo.h"
#include "model/view_quantity.h"
#include "ui/layout.h"
#include "ui/pane_overlays.h"

namespace somicage::editor {

std::vector<ViewSpec> shownViews(bool compare, const std::vector<ViewSpec>& compareViews, const ViewSpec& single) {
  if (compare && compareViews.size() >= 2) return compareViews;
  return {single};
}

ViewSpec singleViewOf(Method method, const MethodOptions& options) {
  return withMethod(ViewSpec{method, {}, options}, method);
}

std::vector<DeformerKey> deformerKeysOf(const std::vector<ViewSpec>& views) {
  std::vector<DeformerKey> keys;
  for (const ViewSpec& shown : views)
    if (std::find(keys.begin(), keys.end(), deformerKey(shown)) == keys.end()) keys.push_back(deformerKey(shown));
  return keys;
}

std::vector<ViewSpec> AppState::views() const { return shownViews(view.compare, view.compareViews, singleView()); }

ViewSpec AppState::singleView() const { return singleViewOf(document.method, view.methodOptions); }

std::vector<DeformerKey> AppState::deformerKeys() const { return deformerKeysOf(views()); }

std::string viewLabel(const AppState& state, std::size_t v) {
  const ViewSpec view = state.views()[v];
  const Method method = view.method;
  const DeformParams params = view.params(state.document.params);
  std::string label = method->displayName;
  char buf[160];
  for (const ParameterSpec& spec : parameterSchema()) {  // parameter_schema.h: what each row's LabelShow says
    const double value = parameterValue(spec, params);
    const bool own = view.own.count(spec.key) > 0;
    if (!readsParameter(method, spec.parameter) || spec.labelShow == LabelShow::Never ||
        (spec.labelShow == LabelShow::WhenSet && value == spec.defaultValue && !own))
      continue;
    const std::string text = parameterText(spec, value);
    if (spec.type == ParameterType::Number) {
      std::snprintf(buf, sizeof buf, "%.2f", value);
      label += "  " + std::string(spec.key) + "=" + (std::isinf(value) ? text : buf);
    } else if (spec.type == ParameterType::Switch) {
      label += "  " + std::string(value != 0 ? "" : "no ") + spec.label;
    } else if (spec.labelShow == LabelShow::Always) {  // the variant: "local", or "blend 0.50" between the two
      std::snprintf(buf, sizeof buf, " %.2f", params.blend);
      label += "  " + text + (text == "blend" ? buf : "");
    } else {
      label += "  " + std::string(spec.key) + " " + text;
    }
    if (own) label += " (own)";
  }
  for (const auto& [key, value] : view.options) label += "  " + key + " " + value + " (own)";
  // Which tetrahedra a volume method gets without options of its own (deformer.h: volumeMeshFor): the cage's star.
  if (method->needsVolumeMesh && view.options.count("tets") + view.options.count("tet-level") == 0 &&
      state.model.scene && starVolumeMesh(state.model.scene->restCage))
    label += "  star tetrahedra";
  if (!hasDeformer(state, deformerKey(view)))  // the scene is shown while its deformers are computed
    label += state.jobs.precompute.busy()      ? "  (precomputing...)"
             : state.model.precomputeCancelled ? "  (cancelled: an edit precomputes it)"
                                               : "  (not precomputed)";
  return label;
}

std::string viewShortName(const AppState& state, std::size_t v) {
  const ViewSpec view = state.views()[v];
  std::string name = view.method->displayName;
  if (const std::optional<double> nu = view.value("nu")) {
    char buf[48];
    std::snprintf(buf, sizeof buf, " nu=%.2f", *nu);
    name += buf;
  }
  for (const auto& [key, value] : view.options) name += " " + key + " " + value;
  return name;
}

void setMethodOptions(AppState& state, MethodOptions options) {
  if (state.view.methodOptions == options) return;
  state.view.methodOptions = std::move(options);
  state.model.deformDirty = true;
  ensureDeformers(state);
}

void setCompare(AppState& state, bool on) {
  if (on && !state.view.compare) state.view.frameRequested = true;  // narrower views: frame everything again
  if (on != state.view.compare) state.view.quantities.clearSweep();
  state.view.compare = on;
  state.model.deformDirty = true;
  ensureDeformers(state);
}

void setCompareViews(AppState& state, std::vector<ViewSpec> views) {
  if (views.size() < 2 || views.size() > kMaxCompareViews) return;
  state.view.compareViews = std::move(views);
  setCompare(state, true);
}

void removeCompareView(AppState& state, std::size_t v) {
  if (state.view.compareViews.size() <= 2 || v >= state.view.compareViews.size()) return;
  std::vector<ViewShow>& shows = state.view.quantities.show.views;
  if (shows.size() > 1 && v < shows.size()) shows.erase(shows.begin() + static_cast<std::ptrdiff_t>(v));
  std::vector<ViewSpec> views = state.view.compareViews;
  views.erase(views.begin() + static_cast<std::ptrdiff_t>(v));
  setCompareViews(state, std::move(views));
}

Eigen::Vector3d selectionPivot(const AppState& state) {
  const Eigen::VectorXd c = state.input.selection.centroid(state.document.pose);
  Eigen::Vector3d pivot = Eigen::Vector3d::Zero();
  for (Eigen::Index k = 0; k < std::min<Eigen::Index>(c.size(), 3); ++k) pivot[k] = c[k];
  return pivot;
}

// The room framing has in the first pane (the panes share the camera and are as large, to a pixel): clear of every
// pane's overlays (pane_overlays.h) and, with a selection, its gizmo's ring inside the pane (gizmo.h).
namespace {
FrameRoom frameRoom(const AppState& state) {
  FrameRoom room;
  const ViewRect pane = state.view.panes.empty() ? ViewRect{} : state.view.panes.front();
  room.width = pane.width;
  room.height = pane.height;
  room.keepClear = paneOverlayBoxes(state, state.view.panes);
  if (state.view.showCage && !state.input.selection.empty() && state.document.pose.rows() > 0) {
    room.point = selectionPivot(state);
    room.hasPoint = true;
    room.pointPixels = GizmoLayout::kRingPixels + GizmoLayout::kGrabPixels;
  }
  return room;
}
}  // namespace

void frameAll(AppState& state) {
  if (!state.model.scene) return;
  ensureCpuPoints(state, 0);
  Eigen::Vector3d lo, hi, clo, chi;
  bounds3(displayedPoints(state, 0), lo, hi);
  bounds3(state.document.pose.rows() > 0 ? state.document.pose : state.model.scene->restCage.vertices, clo, chi);
  state.view.camera.frame(lo.cwiseMin(clo), hi.cwiseMax(chi), frameRoom(state));
}

void frameRest(AppState& state) {
  if (!state.model.scene) return;
  Eigen::Vector3d lo, hi, clo, chi;
  bounds3(state.model.scene->meshVertices, lo, hi);
  bounds3(state.model.scene->restCage.vertices, clo, chi);
  state.view.camera.frame(lo.cwiseMin(clo), hi.cwiseMax(chi), frameRoom(state));
}

}  // namespace somicage::editor
