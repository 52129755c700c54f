#include "ui/compare_views_panel.h"

#include <imgui.h>

#include <cmath>
#include <optional>
#include <vector>

#include "deform/method.h"
#include "deform/parameter_schema.h"
#include "engine/session.h"
#include "engine/view_spec.h"
#include "ui/panels.h"           // tooltip
#include "ui/parameter_panel.h"  // sliderSpan

namespace somicage::editor {

void drawCompareViews(AppState& state) {
  std::vector<ViewSpec> views = state.view.compareViews;
  bool changed = false;
  std::optional<std::size_t> removed;
  for (std::size_t v = 0; v < views.size(); ++v) {
    ViewSpec& view = views[v];
    ImGui::PushID(static_cast<int>(v));
    ImGui::Text("%d", static_cast<int>(v + 1));
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110);
    if (ImGui::BeginCombo("##method", view.method->displayName)) {
      for (Method m : allMethods())
        if (ImGui::Selectable(m->displayName, m == view.method) && m != view.method) {
          view = withMethod(view, m);
          changed = true;
        }
      ImGui::EndCombo();
    }
    tooltip("The method of this pane (views of one method share its precomputed coordinates)");
    if (readsParameter(view.method, kParamNu)) {
      ImGui::SameLine();
      bool own = view.own.count("nu") > 0;
      if (ImGui::Checkbox("own nu", &own)) {
        if (own)
          view.own["nu"] = std::isfinite(state.document.params.nu) ? state.document.params.nu : 0.0;
        else
          view.own.erase("nu");
        changed = true;
      }
      tooltip(
          "Give this pane its own nu (e.g. the same method at two nu side by side, paper Fig. 3); off: the\n"
          "panel's nu. nu never re-integrates, so this is as fast as the panel's slider.");
    }
    if (views.size() > 2) {
      ImGui::SameLine();
      if (ImGui::SmallButton("x")) removed = v;
      tooltip("Remove this pane");
    }
    if (const std::optional<double> ownNu = view.value("nu")) {
      float nu = static_cast<float>(*ownNu);
      ImGui::Indent();
      ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("nu ").x);
      float lo = 0, hi = 0;
      sliderSpan(*findParameter("nu"), lo, hi);  // the table's range, as the panel's slider
      if (ImGui::SliderFloat("nu", &nu, lo, hi, "%.3f", ImGuiSliderFlags_AlwaysClamp)) {
        view.own["nu"] = nu;
        changed = true;
      }
      tooltip("This pane's Poisson ratio nu in (-1, 0.5). Ctrl+click to type a value.");
      ImGui::Unindent();
    }
    ImGui::PopID();
  }
  if (removed) {
    removeCompareView(state, *removed);
    return;
  }
  if (views.size() < kMaxCompareViews) {
    if (ImGui::Button("+ view")) {
      views.push_back(views.back());
      changed = true;
    }
    tooltip("Add a pane: a copy of the last one, to give another method or nu");
  }
  if (changed) setCompareViews(state, views);
}

}  // namespace somicage::editor
