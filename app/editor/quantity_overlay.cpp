#include "quantity_overlay.h"

#include <imgui.h>

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

}  // namespace somicage::editor
