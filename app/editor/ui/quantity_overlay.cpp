#include "ui/quantity_overlay.h"

#include <imgui.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "analysis/deformation_analysis.h"
#include "analysis/deformation_quantities.h"
#include "deform/deform_choices.h"
#include "deform/method.h"
#include "engine/view_spec.h"
#include "interaction/element_pick.h"
#include "jobs/measure_worker.h"
#include "mesh_renderer.h"
#include "model/selection.h"
#include "model/view_quantities.h"
#include "model/view_quantity.h"
#include "ui/pane_overlays.h"
#include "ui/panels.h"  // tooltip

namespace somicage::editor {

namespace {

// The selected cage element whose coordinate field is shown: in face mode the first face with every vertex
// selected, else the first selected vertex.
void selectedElement(const AppState& state, int& vertex, int& face) {
  vertex = face = -1;
  if (!state.model.scene) return;
  if (state.input.elementMode == ElementMode::Face) {
    const Eigen::MatrixXi& f = state.model.scene->restCage.faces;
    for (Eigen::Index j = 0; j < f.rows() && face < 0; ++j) {
      bool all = true;
      for (Eigen::Index k = 0; k < f.cols(); ++k) all = all && state.input.selection.isSelected(f(j, k));
      if (all) face = static_cast<int>(j);
    }
    if (face >= 0) return;
  }
  const std::vector<int> selected = state.input.selection.indices();
  if (!selected.empty()) vertex = selected.front();
}

// View v's deformer (null while its method's precompute runs).
std::shared_ptr<const CageDeformer> deformerOf(const AppState& state, std::size_t v) {
  const auto d = state.model.deformers.find(deformerKey(state.views()[v]));
  return d == state.model.deformers.end() ? nullptr : d->second;
}

// The deformer the nu plot sweeps: the current method's, when it reads nu (MethodDescriptor::parameters).
const std::shared_ptr<const CageDeformer>* nuSweepDeformer(const AppState& state) {
  if (!state.model.scene || !readsParameter(state.document.method, kParamNu)) return nullptr;
  const auto d = state.model.deformers.find(state.document.method);
  return d == state.model.deformers.end() ? nullptr : &d->second;
}

void turnOff(AppState& state, const std::string& error) {
  state.status.errors.push_back(error);
  state.view.quantities.show.setAll(0);
}

}  // namespace

MeasureRequest measureRequest(const AppState& state) {
  MeasureRequest r;
  r.scene = state.model.scene;
  r.pose = state.document.pose;
  r.poseGeneration = state.model.deformGeneration;
  int vertex = -1, face = -1;
  selectedElement(state, vertex, face);
  const std::vector<ViewSpec> views = state.views();
  for (std::size_t v = 0; v < views.size(); ++v) {
    MeasureView view;
    view.quantity = state.view.quantities.show.view(v).quantity;
    view.params = state.viewParams(v);  // each view is measured at its own nu (the field too)
    const QuantitySource source = quantityDescriptor(view.quantity).source;
    if (source == QuantitySource::Jacobian || source == QuantitySource::Difference)
      view.deformer = deformerOf(state, v);
    const int other = state.view.quantities.show.otherView(v, views.size());
    if (source == QuantitySource::Difference && other >= 0) {
      view.otherDeformer = deformerOf(state, static_cast<std::size_t>(other));
      view.otherParams = state.viewParams(static_cast<std::size_t>(other));
    } else if (source == QuantitySource::Field) {  // the fields its descriptor says it can show
      if (views[v].method->fields & kFieldVertex) view.fieldVertex = vertex;
      if (views[v].method->fields & kFieldFace) view.fieldFace = face;
    }
    r.views.push_back(std::move(view));
  }
  return r;
}

void measureViews(AppState& state) {
  ViewQuantities& q = state.view.quantities;
  if (!state.model.scene) return;
  const std::size_t viewCount = state.views().size();
  q.measured.resize(viewCount);
  MeasureRequest request = measureRequest(state);
  const MeasureKey key = measureKey(request);
  if (std::optional<MeasureOutcome> outcome = state.jobs.measure.poll()) {
    if (!outcome->error.empty()) {
      turnOff(state, "measuring the pose failed: " + outcome->error);
    } else if (outcome->cancelled) {
      state.status.message = "measuring cancelled";
    } else if (outcome->key.sweep) {
      q.nuSweep = std::move(outcome->sweep);
      q.nuSweepVariants = std::move(outcome->variantSweeps);
      const std::shared_ptr<const CageDeformer>* deformer = nuSweepDeformer(state);
      const bool current = outcome->key.poseGeneration == state.model.deformGeneration && deformer;
      q.nuSweepPose = current ? state.document.pose : Eigen::MatrixXd();
      q.nuSweepDeformer = current ? *deformer : nullptr;
      q.nuSweepParams = state.document.params;
      logLine(state, "job nu sweep");
    } else if (outcome->key == key) {
      for (std::size_t v = 0; v < viewCount && v < outcome->views.size(); ++v)
        q.measured[v] = std::move(outcome->views[v]);
      q.installed = key;
      ++q.generation;
    } else {
      ++q.droppedStale;  // its pose (or scene, or choice) is gone: the current one is measured next
    }
  }
  if (state.jobs.measure.busy()) return;
  if (q.sweepRequested) {
    q.sweepRequested = false;
    if (const std::shared_ptr<const CageDeformer>* deformer = nuSweepDeformer(state)) {
      MeasureRequest sweep = request;
      MeasureView view;
      view.deformer = *deformer;
      view.params = state.document.params;
      sweep.views.assign(1, view);
      sweep.sweepView = 0;
      sweep.sweepNus = nuSweepValues(-0.95, 0.49, 25);
      sweep.sweepVariants = readsParameter(state.document.method, kParamBlend);  // BEM reads nu, not the variant
      state.jobs.measure.start(std::move(sweep));
      return;
    }
  }
  if (!needsWorker(request)) {
    if (q.installed != MeasureKey{}) {  // nothing uses the gradients or field terms any more: free them
      state.jobs.measure.release();
      for (const auto& [key, deformer] : state.model.deformers) deformer->releaseGradients();  // kept with C
      q.installed = MeasureKey{};
      for (std::size_t v = 0; v < viewCount; ++v) q.measured[v].reset();
      ++q.generation;
    }
    return;
  }
  if (key != q.installed) state.jobs.measure.start(std::move(request));
}

bool measurementsSettled(AppState& state) {
  measureViews(state);
  // busy() before ready(): a job ending between the two leaves its outcome waiting, which is not settled
  return !state.jobs.measure.busy() && !state.jobs.measure.ready() && !state.view.quantities.sweepRequested;
}

ColorRange shownRange(const AppState& state, int quantity) {
  return quantityRange(state.view.quantities.show, quantity, state.view.quantities.measurements(state.views().size()));
}

namespace {

ImU32 toImColor(const Eigen::Vector3f& c) {
  return IM_COL32(static_cast<int>(c[0] * 255), static_cast<int>(c[1] * 255), static_cast<int>(c[2] * 255), 255);
}

const ImU32 kText = IM_COL32(235, 235, 240, 255);

// "views of Somigliana or BEM only": the methods whose descriptor lists element fields (MethodDescriptor::fields).
std::string methodsShowingFields() {
  std::vector<std::string> names;
  for (Method m : allMethods())
    if (m->fields) names.emplace_back(m->displayName);
  std::string list;
  for (std::size_t k = 0; k < names.size(); ++k)
    list += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + names[k];
  return "views of " + list + " only";
}

int colorMapRow(const QuantityDescriptor& d) {
  return d.scale == ColorScale::LogDiverging ? render::kDivergingMap : render::kViridisMap;
}

// Fold-overs have two classes, not a scale: every unfolded vertex at the map's neutral centre, the folded ones
// magenta. A colour bar from 0.999 to 1.001 said nothing (issue 24, row 8); two swatches say what the colours mean.
void drawCategoryLegend(const QuantityDescriptor& d, const ViewRect& view) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const char* labels[2] = {"det J > 0", "fold-over (det J <= 0)"};
  const ImU32 colors[2] = {toImColor(render::colorMapColor(render::kDivergingMap, 0.5f)),
                           toImColor(render::kFoldoverColor)};
  const ViewRect box =
      legendBox(view, std::max(ImGui::CalcTextSize(d.name).x, 18 + ImGui::CalcTextSize(labels[1]).x), false);
  const float x0 = static_cast<float>(box.x + kLegendPadding), y0 = static_cast<float>(box.y + 24);
  draw->AddRectFilled(ImVec2(static_cast<float>(box.x), static_cast<float>(box.y)),
                      ImVec2(static_cast<float>(box.x + box.width), static_cast<float>(box.y + box.height)),
                      IM_COL32(20, 20, 24, 190), 3.0f);
  draw->AddText(ImVec2(x0, y0 - 20), kText, d.name);
  for (int k = 0; k < 2; ++k) {
    const float y = y0 + 4 + 20 * static_cast<float>(k);
    draw->AddRectFilled(ImVec2(x0, y), ImVec2(x0 + 12, y + 12), colors[k]);
    draw->AddText(ImVec2(x0 + 18, y - 1), kText, labels[k]);
  }
}

void drawLegend(const AppState& state, int quantity, const ViewRect& view) {
  const QuantityDescriptor& d = quantityDescriptor(quantity);
  if (std::string(d.id) == "foldover") {
    drawCategoryLegend(d, view);
    return;
  }
  const ColorRange range = shownRange(state, quantity);
  const auto fixed = state.view.quantities.show.ranges.find(quantity);
  const bool isFixed = fixed != state.view.quantities.show.ranges.end() && fixed->second.fixed;
  const bool log = d.scale == ColorScale::LogDiverging;
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const float w = static_cast<float>(kLegendBarWidth), h = 14;
  const std::string title = legendTitle(d, isFixed);
  const char* note = legendNote(d);
  // The automatic range leaves out each view's most extreme 2 % (view_quantity.h): say how many take the end colours.
  const long beyond = verticesBeyond(
      viewsShowing(state.view.quantities.show, quantity, state.view.quantities.measurements(state.views().size())), range);
  char beyondText[64] = "";
  if (beyond > 0)
    std::snprintf(beyondText, sizeof beyondText, "%ld %s beyond the ends", beyond, beyond == 1 ? "vertex" : "vertices");
  const ViewRect box = legendBox(view,
                                 std::max({ImGui::CalcTextSize(title.c_str()).x, ImGui::CalcTextSize(note).x,
                                           ImGui::CalcTextSize(beyondText).x}),
                                 beyond > 0);
  const float x0 = static_cast<float>(box.x + kLegendPadding), y0 = static_cast<float>(box.y + 24);
  draw->AddRectFilled(ImVec2(static_cast<float>(box.x), static_cast<float>(box.y)),
                      ImVec2(static_cast<float>(box.x + box.width), static_cast<float>(box.y + box.height)),
                      IM_COL32(20, 20, 24, 190), 3.0f);
  if (beyond > 0) draw->AddText(ImVec2(x0, y0 + h + 37), IM_COL32(170, 170, 180, 255), beyondText);
  draw->AddText(ImVec2(x0, y0 - 20), kText, title.c_str());
  const int steps = 64;
  for (int i = 0; i < steps; ++i) {
    const float a = x0 + w * static_cast<float>(i) / steps, b = x0 + w * static_cast<float>(i + 1) / steps;
    draw->AddRectFilled(ImVec2(a, y0), ImVec2(b + 0.5f, y0 + h),
                        toImColor(render::colorMapColor(colorMapRow(d), (static_cast<float>(i) + 0.5f) / steps)));
  }
  char lo[32], mid[32], hi[32];
  std::snprintf(lo, sizeof lo, "%.4g", range.lo);
  std::snprintf(mid, sizeof mid, "%.4g", log ? 1.0 : 0.5 * (range.lo + range.hi));
  std::snprintf(hi, sizeof hi, "%.4g", range.hi);
  draw->AddText(ImVec2(x0, y0 + h + 2), kText, lo);
  draw->AddText(ImVec2(x0 + w / 2 - ImGui::CalcTextSize(mid).x / 2, y0 + h + 2), kText, mid);
  draw->AddText(ImVec2(x0 + w - ImGui::CalcTextSize(hi).x, y0 + h + 2), kText, hi);
  if (d.source == QuantitySource::Jacobian) {
    draw->AddRectFilled(ImVec2(x0, y0 + h + 20), ImVec2(x0 + 12, y0 + h + 32), toImColor(render::kFoldoverColor));
    draw->AddText(ImVec2(x0 + 18, y0 + h + 19), kText, "fold-over (det J <= 0)");
  } else {
    draw->AddText(ImVec2(x0, y0 + h + 19), IM_COL32(170, 170, 180, 255), note);
  }
}

void drawBoxedText(ImDrawList* draw, ImVec2 pos, const std::string& text) {
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  draw->AddRectFilled(ImVec2(pos.x - 4, pos.y - 2), ImVec2(pos.x + size.x + 4, pos.y + size.y + 2),
                      IM_COL32(20, 20, 24, 170), 3.0f);
  draw->AddText(pos, kText, text.c_str());
}

std::string viewNumbers(const AppState& state, std::size_t v, std::size_t viewCount) {
  const ViewShow& s = state.view.quantities.show.view(v);
  const QuantityDescriptor& d = quantityDescriptor(s.quantity);
  const ViewMeasurement* m = state.view.quantities.measurement(v);
  char buf[200];
  switch (d.source) {
    case QuantitySource::None:
      return "";
    case QuantitySource::Jacobian:
      if (!m) return "measuring...";
      std::snprintf(buf, sizeof buf, "volume %+.2f%%%s\nfold-overs %d\ndistortion p95 %.3f", 100 * m->volumeChange,
                    m->closed ? "" : " (open, capped)", m->foldovers, m->distortionP95);
      return buf;
    case QuantitySource::Difference: {
      const int w = state.view.quantities.show.otherView(v, viewCount);
      if (w < 0) return "difference: needs the compare view";
      if (!m) return "measuring...";
      // Two lines: in one line a narrow pane (a third of 1000 pixels) cut it short, e.g. "to BEM nu=0.00: max ..."
      std::snprintf(buf, sizeof buf, "to %s:\nmax %.4f, median %.4f diameters",
                    viewShortName(state, static_cast<std::size_t>(w)).c_str(), m->values.maxCoeff(),
                    quantile(m->values, 0.5));
      return buf;
    }
    case QuantitySource::Field: {
      int vertex = -1, face = -1;
      selectedElement(state, vertex, face);
      if (!state.views()[v].method->fields) return "field: " + methodsShowingFields();
      if (vertex < 0 && face < 0) return "field: select a cage vertex or face";
      if (!m) return "measuring...";
      std::snprintf(buf, sizeof buf, "field of cage %s %d at nu %.3g", vertex >= 0 ? "vertex" : "face",
                    vertex >= 0 ? vertex : face, state.viewParams(v).nu);
      return buf;
    }
  }
  return "";
}

// The mesh vertex of view v under the mouse (selection.h's pickPoint, 8 pixels, on the points the measurement m was
// taken at, else the view's displayed points), -1 when none.
int hoveredVertex(const AppState& state, std::size_t v, const ViewMeasurement& m, const ViewRect& rect,
                  const Eigen::Vector2d& mouse) {
  const Eigen::MatrixXd& points = m.points.rows() ? m.points : displayedPoints(state, v);
  return pickPoint(projectPoints(state.view.camera, points, rect.width, rect.height), mouse - rect.origin(), 8.0);
}

// A 2D field's arrows (paper Fig. 3) at their rest positions, coloured by magnitude in the view's range; the longest
// spans about one grid step.
void drawFieldArrows(const AppState& state, std::size_t v, const ViewRect& rect) {
  const ViewMeasurement* m = state.view.quantities.measurement(v);
  if (!m || m->arrowPoints.rows() < 2) return;
  const int quantity = state.view.quantities.show.view(v).quantity;
  const ColorRange range = shownRange(state, quantity);
  const Eigen::Matrix4d mvp =
      state.view.camera.projectionMatrix(rect.width / rect.height) * state.view.camera.viewMatrix();
  auto screen = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector4d c = mvp * Eigen::Vector4d(p.x(), p.y(), 0.0, 1.0);
    return ImVec2(static_cast<float>(rect.x + (c.x() / c.w() + 1) * 0.5 * rect.width),
                  static_cast<float>(rect.y + (1 - c.y() / c.w()) * 0.5 * rect.height));
  };
  const double step = (m->arrowPoints.row(1) - m->arrowPoints.row(0)).norm();
  const double longest = m->arrowVectors.rowwise().norm().maxCoeff();
  if (!(longest > 0)) return;
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  for (Eigen::Index k = 0; k < m->arrowPoints.rows(); ++k) {
    const Eigen::Vector2d p = m->arrowPoints.row(k).transpose(), f = m->arrowVectors.row(k).transpose();
    const double magnitude = f.norm();
    const ImU32 color = toImColor(render::colorMapColor(
        render::kViridisMap, std::max(0.0f, colorCoordinate(magnitude, 1.0, range, ColorScale::Viridis))));
    const ImVec2 a = screen(p - 0.45 * step * f / longest), b = screen(p + 0.45 * step * f / longest);
    const float dx = b.x - a.x, dy = b.y - a.y, len = std::sqrt(dx * dx + dy * dy);
    const float ux = len > 0 ? dx / len : 0, uy = len > 0 ? dy / len : 0, head = std::min(6.0f, 0.4f * len);
    const ImVec2 left(b.x - head * (ux + 0.5f * uy), b.y - head * (uy - 0.5f * ux));
    const ImVec2 right(b.x - head * (ux - 0.5f * uy), b.y - head * (uy + 0.5f * ux));
    for (int pass = 0; pass < 2; ++pass) {  // a dark outline first, so the arrows read over a coloured mesh
      const ImU32 c = pass == 0 ? IM_COL32(10, 10, 14, 220) : color;
      draw->AddLine(a, b, c, pass == 0 ? 4.0f : 2.0f);
      if (len >= 3) draw->AddTriangleFilled(left, right, b, c);
    }
  }
}

HoverReadout drawHoverValue(const AppState& state, const std::vector<ViewRect>& views) {
  if (ImGui::GetIO().WantCaptureMouse || state.input.mouse.mode != Interaction::Mode::Idle) return {};
  const ImVec2 mp = ImGui::GetIO().MousePos;
  const Eigen::Vector2d mouse(mp.x, mp.y);
  for (std::size_t v = 0; v < views.size() && v < state.views().size(); ++v) {
    if (!views[v].contains(mouse)) continue;
    const ViewMeasurement* m = state.view.quantities.measurement(v);
    if (!m) return {};
    const int i = hoveredVertex(state, v, *m, views[v], mouse);
    if (i < 0 || i >= m->values.size()) return {};
    const QuantityDescriptor& d = quantityDescriptor(state.view.quantities.show.view(v).quantity);
    char buf[200];
    int n = std::isfinite(m->values[i]) ? std::snprintf(buf, sizeof buf, "%s %.6g", d.name, m->values[i])
                                        : std::snprintf(buf, sizeof buf, "%s undefined", d.name);
    if (m->detJ.size() && std::string(d.id) != "detj" && n > 0)  // what the other J quantities come from
      n += std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), "  (det J %.4g)", m->detJ[i]);
    if (n > 0) std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), "\nvertex %d", i);
    drawBoxedText(ImGui::GetForegroundDrawList(), ImVec2(mp.x + 16, mp.y + 12), buf);
    return {static_cast<int>(v), i, d.id, m->values[i]};
  }
  return {};
}

}  // namespace

HoverReadout drawQuantityOverlay(const AppState& state, const std::vector<ViewRect>& views) {
  const std::size_t n = std::min(views.size(), state.views().size());
  if (!state.view.quantities.show.anyShown(n)) return {};
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  for (std::size_t v = 0; v < n; ++v) {
    const std::string text = viewNumbers(state, v, n);
    if (!text.empty())
      drawBoxedText(draw, ImVec2(static_cast<float>(views[v].x + kLabelLeft), static_cast<float>(views[v].y + kNumbersTop)),
                    text);
  }
  for (std::size_t v = 0; v < n; ++v) drawFieldArrows(state, v, views[v]);
  const ShowSettings& show = state.view.quantities.show;
  for (std::size_t v = 0; v < n; ++v)
    if (show.drawsLegend(v, n)) drawLegend(state, show.view(v).quantity, views[v]);
  if (state.view.hideUi || !state.view.screenshotRequest.empty()) return {};  // not in a capture
  return drawHoverValue(state, views);
}

void logHoverReadout(AppState& state, const HoverReadout& hover) {
  if (!state.status.logActions) return;
  char line[160];
  if (hover.vertex < 0)
    std::snprintf(line, sizeof line, "hover none");
  else
    std::snprintf(line, sizeof line, "hover view %d vertex %d %s %.17g", hover.view, hover.vertex, hover.quantity,
                  hover.value);
  if (state.status.hoverLogged == line) return;
  state.status.hoverLogged = line;
  std::printf("%s\n", line);
  std::fflush(stdout);
}

namespace {

bool quantityCombo(const char* label, int& quantity) {
  const std::vector<QuantityDescriptor>& d = quantityDescriptors();
  bool changed = false;
  if (ImGui::BeginCombo(label, d[static_cast<std::size_t>(quantity)].name)) {
    for (std::size_t i = 0; i < d.size(); ++i)
      if (ImGui::Selectable(d[i].name, static_cast<int>(i) == quantity)) {
        changed = quantity != static_cast<int>(i);
        quantity = static_cast<int>(i);
      }
    ImGui::EndCombo();
  }
  return changed;
}

void drawRangeSetting(AppState& state, int quantity) {
  const QuantityDescriptor& d = quantityDescriptor(quantity);
  auto it = state.view.quantities.show.ranges.find(quantity);
  RangeSetting setting = it != state.view.quantities.show.ranges.end() ? it->second : RangeSetting{};
  setting.range = rangeFieldsValue(state.view.quantities.show, quantity, shownRange(state, quantity));
  ImGui::PushID(quantity);
  bool changed = ImGui::Checkbox("fixed range", &setting.fixed);
  ImGui::SameLine();
  ImGui::TextDisabled("%s", d.id);
  if (!setting.fixed) ImGui::BeginDisabled();
  ImGui::SetNextItemWidth(90);
  changed |= ImGui::InputDouble("min", &setting.range.lo, 0, 0, "%.4g");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  changed |= ImGui::InputDouble("max", &setting.range.hi, 0, 0, "%.4g");
  if (!setting.fixed) ImGui::EndDisabled();
  const std::string problem = setting.fixed ? rangeProblem(setting.range, d.scale) : "";
  if (!problem.empty()) ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "%s: automatic range used", problem.c_str());
  if (changed) {
    state.view.quantities.show.ranges[quantity] = setting;
    ++state.view.quantities.generation;
  }
  ImGui::PopID();
}

}  // namespace

void drawShowChoice(AppState& state) {
  ShowSettings& show = state.view.quantities.show;
  const std::size_t viewCount = state.views().size();
  for (std::size_t v = 0; v < viewCount; ++v) {
    int quantity = show.view(v).quantity;
    const std::string label = viewCount > 1 ? "view " + std::to_string(v + 1) : "show";  // the panel's pane numbers
    ImGui::PushID(static_cast<int>(v));
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("Mean value ").x);
    if (quantityCombo(label.c_str(), quantity)) show.setView(v, quantity, viewCount);
    if (quantityDescriptor(quantity).source == QuantitySource::Difference && viewCount > 1) {
      int other = show.otherView(v, viewCount);
      ImGui::SetNextItemWidth(140);
      if (ImGui::BeginCombo("to", viewShortName(state, static_cast<std::size_t>(other)).c_str())) {
        for (std::size_t w = 0; w < viewCount; ++w)
          if (w != v && ImGui::Selectable(viewShortName(state, w).c_str(), static_cast<int>(w) == other)) {
            show.setView(v, quantity, viewCount);
            show.views[v].other = static_cast<int>(w);
          }
        ImGui::EndCombo();
      }
    }
    ImGui::PopID();
  }
  std::vector<int> shown;  // each quantity's range once
  for (std::size_t v = 0; v < viewCount; ++v) {
    const int quantity = show.view(v).quantity;
    if (quantity > 0 && std::find(shown.begin(), shown.end(), quantity) == shown.end()) shown.push_back(quantity);
  }
  for (int quantity : shown) drawRangeSetting(state, quantity);
  MeasureWorker& worker = state.jobs.measure;
  if (worker.busy()) {
    const std::string stage = worker.stage();
    ImGui::TextUnformatted(stage.empty() ? "measuring..." : stage.c_str());
    ImGui::ProgressBar(static_cast<float>(worker.progress()), ImVec2(-60.0f, 0.0f));
    ImGui::SameLine();
    if (ImGui::Button("Cancel##measure")) {
      worker.cancel();
      show.setAll(0);  // else the next frame would start it again
      state.view.quantities.sweepRequested = false;
    }
  }
}

void sweepNuNow(AppState& state) { state.view.quantities.sweepRequested = true; }

bool nuSweepCurrent(const AppState& state) {
  const ViewQuantities& q = state.view.quantities;
  const std::shared_ptr<const CageDeformer>* deformer = nuSweepDeformer(state);
  DeformParams swept = q.nuSweepParams;
  swept.nu = state.document.params.nu;  // what it sweeps
  return !q.nuSweep.empty() && deformer && q.nuSweepDeformer.lock() == *deformer &&
         q.nuSweepPose.rows() == state.document.pose.rows() && q.nuSweepPose.cols() == state.document.pose.cols() &&
         q.nuSweepPose == state.document.pose && swept == state.document.params;
}

namespace {

// The fold-over lines of the nu plot: each variant's (Somigliana), else the current parameters' alone (BEM).
struct FoldLine {
  std::string name;
  const std::vector<NuSweepEntry>* entries;
  ImU32 color;
  bool current;  // the panel's variant: drawn thicker
};

std::vector<FoldLine> foldLines(const AppState& state) {
  const ViewQuantities& q = state.view.quantities;
  if (q.nuSweepVariants.empty()) return {{"fold-overs", &q.nuSweep, toImColor(render::kFoldoverColor), true}};
  // One colour per variant, in variantChoices()' order (global, local, affine, stable); none is the current nu's
  // yellow or the volume line's.
  const ImU32 colors[] = {IM_COL32(90, 170, 255, 255), IM_COL32(255, 80, 200, 255), IM_COL32(110, 220, 110, 255),
                          IM_COL32(255, 150, 60, 255)};
  const std::string current = variantName(q.nuSweepParams);
  std::vector<FoldLine> lines;
  for (std::size_t k = 0; k < q.nuSweepVariants.size(); ++k) {
    const VariantSweep& v = q.nuSweepVariants[k];
    lines.push_back({v.variant, &v.entries, colors[k % std::size(colors)], v.variant == current});
  }
  return lines;
}

}  // namespace

void drawNuPlot(AppState& state) {
  if (!nuSweepDeformer(state)) return;
  if (ImGui::Button("Sweep nu")) sweepNuNow(state);
  tooltip(
      "Deform the current pose at 25 values of nu in (-0.95, 0.49) and plot the volume change and the fold-over\n"
      "count against nu, one fold-over line per Somigliana variant (global, local, affine, stable), on the\n"
      "measuring worker; a click on the plot sets nu.");
  const std::vector<NuSweepEntry>& sweep = state.view.quantities.nuSweep;
  ImGui::SameLine();
  ImGui::TextDisabled(sweep.empty() || nuSweepCurrent(state) ? "volume change vs nu"
                                                             : "(the pose changed: sweep again)");
  if (sweep.empty()) return;
  const std::vector<FoldLine> lines = foldLines(state);
  std::vector<float> change;
  int folds = 0;  // the fold-over axis' top: the largest count of any line
  for (const NuSweepEntry& e : sweep) change.push_back(static_cast<float>(100 * e.volumeChange));
  for (const FoldLine& line : lines)
    for (const NuSweepEntry& e : *line.entries) folds = std::max(folds, e.foldovers);
  const auto [lo, hi] = std::minmax_element(change.begin(), change.end());
  const float pad = std::max(0.5f, 0.1f * (*hi - *lo));
  char overlay[64];
  std::snprintf(overlay, sizeof overlay, "%+.1f%% .. %+.1f%%", *lo, *hi);
  ImGui::PlotLines("##nuplot", change.data(), static_cast<int>(change.size()), 0, overlay, *lo - pad, *hi + pad,
                   ImVec2(ImGui::GetContentRegionAvail().x, 80));
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  // The fold-over counts on their own axis, 0 at the bottom and the sweep's largest count at the top.
  const double nu0 = sweep.front().nu, nu1 = sweep.back().nu;
  auto xOf = [&](double nu) { return a.x + static_cast<float>((nu - nu0) / (nu1 - nu0)) * (b.x - a.x); };
  auto yOfFolds = [&](int f) {
    return b.y - 3 - (folds > 0 ? static_cast<float>(f) / static_cast<float>(folds) : 0.0f) * (b.y - a.y - 6);
  };
  for (const FoldLine& line : lines) {
    const std::vector<NuSweepEntry>& e = *line.entries;
    for (std::size_t k = 1; k < e.size(); ++k)
      draw->AddLine(ImVec2(xOf(e[k - 1].nu), yOfFolds(e[k - 1].foldovers)), ImVec2(xOf(e[k].nu), yOfFolds(e[k].foldovers)),
                    line.color, line.current ? 2.5f : 1.5f);
  }
  if (std::isfinite(state.document.params.nu)) {  // the current nu
    const float x = xOf(state.document.params.nu);
    draw->AddLine(ImVec2(x, a.y), ImVec2(x, b.y), IM_COL32(255, 200, 60, 255), 2.0f);
  }
  {  // the nu axis: its ends under the plot's corners, its name in the middle
    char lo[24], hi[24];
    std::snprintf(lo, sizeof lo, "%.2f", nu0);
    std::snprintf(hi, sizeof hi, "%.2f", nu1);
    const ImU32 axis = ImGui::GetColorU32(ImGuiCol_TextDisabled);
    const float y = b.y + 1;
    draw->AddText(ImVec2(a.x, y), axis, lo);
    draw->AddText(ImVec2(b.x - ImGui::CalcTextSize(hi).x, y), axis, hi);
    draw->AddText(ImVec2(0.5f * (a.x + b.x) - 0.5f * ImGui::CalcTextSize("nu").x, y), axis, "nu");
    ImGui::Dummy(ImVec2(0, ImGui::GetTextLineHeight()));
  }
  ImGui::TextColored(ImGui::GetStyleColorVec4(ImGuiCol_PlotLines), "- volume change %% (left scale)");
  if (lines.size() == 1) {
    ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(lines.front().color), "- fold-overs (0 .. %d)", folds);
  } else {  // the legend: the axis, then one entry per variant on the next line, the panel's marked
    ImGui::TextDisabled("fold-overs (0 .. %d), per variant:", folds);
    tooltip("Fold-over vertices (det J <= 0) against nu for each variant at the panel's other parameters;\n"
            "* marks the panel's variant (the volume change is its).");
    for (std::size_t k = 0; k < lines.size(); ++k) {
      if (k > 0) ImGui::SameLine();
      ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(lines[k].color), "- %s%s", lines[k].name.c_str(),
                         lines[k].current ? "*" : "");
    }
  }
  if (ImGui::IsMouseHoveringRect(a, b)) {
    const double f = std::clamp((ImGui::GetIO().MousePos.x - a.x) / (b.x - a.x), 0.0f, 1.0f);
    const double nu = nu0 + f * (nu1 - nu0);
    const std::size_t k = static_cast<std::size_t>(std::lround(f * static_cast<double>(sweep.size() - 1)));
    std::string folded;
    for (const FoldLine& line : lines)
      if (k < line.entries->size())
        folded += "\n  " + line.name + ": " + std::to_string((*line.entries)[k].foldovers) + " fold-overs";
    ImGui::SetTooltip("nu %.3f: volume %+.2f%% (click: set nu)%s", sweep[k].nu, 100 * sweep[k].volumeChange,
                      folded.c_str());
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
      DeformParams p = state.document.params;
      p.nu = std::clamp(nu, -0.99, 0.49);
      setParams(state, p);
      commitEdit(state, "nu");
    }
  }
}

}  // namespace somicage::editor
