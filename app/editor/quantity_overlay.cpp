#include "quantity_overlay.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "mesh_renderer.h"

namespace somicage::editor {

void measureViews(AppState& state) {
  if (!state.scene || state.interaction.mode != Interaction::Mode::Idle) return;
  try {
    state.quantities.update(state.deformers, state.viewMethods(), state.scene->meshVertices, state.scene->meshTriangles,
                            state.pose, state.params, state.show, state.deformGeneration);
  } catch (const std::exception& e) {
    state.errors.push_back(std::string("measuring the pose failed: ") + e.what());
    state.show = 0;
  }
}

ColorRange shownRange(const AppState& state) {
  std::vector<const ViewMeasurement*> views;
  for (Method m : state.viewMethods()) views.push_back(state.quantities.measurement(m));
  return sharedRange(views, quantityDescriptors()[static_cast<std::size_t>(state.show)].scale);
}

namespace {

ImU32 toImColor(const Eigen::Vector3f& c) {
  return IM_COL32(static_cast<int>(c[0] * 255), static_cast<int>(c[1] * 255), static_cast<int>(c[2] * 255), 255);
}

void drawLegend(const AppState& state, const ViewRect& view) {
  const QuantityDescriptor& d = quantityDescriptors()[static_cast<std::size_t>(state.show)];
  const ColorRange range = shownRange(state);
  const int row = d.scale == ColorScale::LogDiverging ? render::kDivergingMap : render::kViridisMap;
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const float w = 220, h = 14;
  const float x0 = static_cast<float>(view.x + view.width) - w - 24, y0 = static_cast<float>(view.y + view.height) - 58;
  draw->AddRectFilled(ImVec2(x0 - 10, y0 - 24), ImVec2(x0 + w + 10, y0 + h + 36), IM_COL32(20, 20, 24, 190), 3.0f);
  draw->AddText(ImVec2(x0, y0 - 20), IM_COL32(235, 235, 240, 255),
                (std::string(d.name) + (d.scale == ColorScale::LogDiverging ? "  (log scale)" : "")).c_str());
  const int steps = 64;
  for (int i = 0; i < steps; ++i) {
    const float a = x0 + w * static_cast<float>(i) / steps, b = x0 + w * static_cast<float>(i + 1) / steps;
    draw->AddRectFilled(ImVec2(a, y0), ImVec2(b + 0.5f, y0 + h),
                        toImColor(render::colorMapColor(row, (static_cast<float>(i) + 0.5f) / steps)));
  }
  char lo[32], mid[32], hi[32];
  std::snprintf(lo, sizeof lo, "%.4g", range.lo);
  std::snprintf(mid, sizeof mid, "%.4g", d.scale == ColorScale::LogDiverging ? 1.0 : 0.5 * (range.lo + range.hi));
  std::snprintf(hi, sizeof hi, "%.4g", range.hi);
  const ImU32 text = IM_COL32(235, 235, 240, 255);
  draw->AddText(ImVec2(x0, y0 + h + 2), text, lo);
  draw->AddText(ImVec2(x0 + w / 2 - ImGui::CalcTextSize(mid).x / 2, y0 + h + 2), text, mid);
  draw->AddText(ImVec2(x0 + w - ImGui::CalcTextSize(hi).x, y0 + h + 2), text, hi);
  draw->AddRectFilled(ImVec2(x0, y0 + h + 20), ImVec2(x0 + 12, y0 + h + 32), toImColor(render::kFoldoverColor));
  draw->AddText(ImVec2(x0 + 18, y0 + h + 19), text, "fold-over (det J <= 0)");
}

}  // namespace

void drawQuantityOverlay(const AppState& state, const std::vector<ViewRect>& views) {
  if (state.show <= 0) return;
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const std::vector<Method> methods = state.viewMethods();
  const float line = ImGui::GetTextLineHeightWithSpacing();
  for (std::size_t v = 0; v < views.size() && v < methods.size(); ++v) {
    const ViewMeasurement* m = state.quantities.measurement(methods[v]);
    std::string text = "measuring...";
    if (m) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "volume %+.2f%%%s\nfold-overs %d\ndistortion p95 %.3f", 100 * m->volumeChange,
                    m->closed ? "" : " (open, capped)", m->foldovers, m->distortionP95);
      text = buf;
    }
    const ImVec2 pos(static_cast<float>(views[v].x + 10), static_cast<float>(views[v].y + 8) + line + 2);
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    draw->AddRectFilled(ImVec2(pos.x - 4, pos.y - 2), ImVec2(pos.x + size.x + 4, pos.y + size.y + 2),
                        IM_COL32(20, 20, 24, 170), 3.0f);
    draw->AddText(pos, IM_COL32(235, 235, 240, 255), text.c_str());
  }
  if (!views.empty()) drawLegend(state, views.back());
}

void drawShowChoice(AppState& state) {
  const std::vector<QuantityDescriptor>& d = quantityDescriptors();
  if (ImGui::BeginCombo("show", d[static_cast<std::size_t>(state.show)].name)) {
    for (std::size_t i = 0; i < d.size(); ++i)
      if (ImGui::Selectable(d[i].name, static_cast<int>(i) == state.show)) state.show = static_cast<int>(i);
    ImGui::EndCombo();
  }
}

namespace {

// The deformer the nu plot sweeps: the current method's, when it reads nu (MethodDescriptor::parameters).
const std::shared_ptr<const CageDeformer>* nuSweepDeformer(const AppState& state) {
  if (!state.scene || !readsParameter(state.method, kParamNu)) return nullptr;
  const auto d = state.deformers.find(state.method);
  return d == state.deformers.end() ? nullptr : &d->second;
}

}  // namespace

void sweepNuNow(AppState& state) {
  const std::shared_ptr<const CageDeformer>* deformer = nuSweepDeformer(state);
  if (!deformer) return;
  try {
    state.quantities.sweepNu(*deformer, state.scene->meshVertices, state.scene->meshTriangles, state.pose, state.params,
                             nuSweepValues(-0.95, 0.49, 25), state.deformGeneration);
  } catch (const std::exception& e) {
    state.errors.push_back(std::string("nu sweep failed: ") + e.what());
  }
}

void drawNuPlot(AppState& state) {
  if (!nuSweepDeformer(state)) return;
  if (ImGui::Button("Sweep nu")) sweepNuNow(state);
  const std::vector<NuSweepEntry>& sweep = state.quantities.nuSweep();
  const bool stale = state.quantities.nuSweepGeneration() != state.deformGeneration;
  ImGui::SameLine();
  ImGui::TextDisabled(sweep.empty() ? "volume change vs nu"
                      : stale       ? "(pose changed: sweep again)"
                                    : "volume change vs nu");
  if (sweep.empty()) return;
  std::vector<float> change;
  int folds = 0;
  for (const NuSweepEntry& e : sweep) {
    change.push_back(static_cast<float>(100 * e.volumeChange));
    folds = std::max(folds, e.foldovers);
  }
  const auto [lo, hi] = std::minmax_element(change.begin(), change.end());
  const float pad = std::max(0.5f, 0.1f * (*hi - *lo));
  char overlay[64];
  std::snprintf(overlay, sizeof overlay, "%+.1f%% .. %+.1f%%, max %d folds", *lo, *hi, folds);
  ImGui::PlotLines("##nuplot", change.data(), static_cast<int>(change.size()), 0, overlay, *lo - pad, *hi + pad,
                   ImVec2(ImGui::GetContentRegionAvail().x, 80));
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  const double nu0 = sweep.front().nu, nu1 = sweep.back().nu;
  if (std::isfinite(state.params.nu)) {  // the current nu
    const float x = a.x + static_cast<float>((state.params.nu - nu0) / (nu1 - nu0)) * (b.x - a.x);
    ImGui::GetWindowDrawList()->AddLine(ImVec2(x, a.y), ImVec2(x, b.y), IM_COL32(255, 200, 60, 255), 2.0f);
  }
  if (ImGui::IsItemHovered()) {
    const double f = std::clamp((ImGui::GetIO().MousePos.x - a.x) / (b.x - a.x), 0.0f, 1.0f);
    const double nu = nu0 + f * (nu1 - nu0);
    const std::size_t k = static_cast<std::size_t>(std::lround(f * static_cast<double>(sweep.size() - 1)));
    ImGui::SetTooltip("nu %.3f: volume %+.2f%%, %d fold-overs (click: set nu)", sweep[k].nu,
                      100 * sweep[k].volumeChange, sweep[k].foldovers);
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
      DeformParams p = state.params;
      p.nu = std::clamp(nu, -0.99, 0.49);
      setParams(state, p);
      commitEdit(state, "nu");
    }
  }
}

}  // namespace somicage::editor
