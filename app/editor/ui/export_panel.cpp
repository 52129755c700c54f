#include "ui/export_panel.h"

#include <imgui.h>

#include "model/app_state.h"

namespace somicage::editor {

void drawExportProgress(AppState& state) {
  if (!state.jobs.exporter.busy()) return;
  ImGui::OpenPopup("Exporting");
  if (ImGui::BeginPopupModal("Exporting", nullptr,
                             ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::Text("exporting %s", state.jobs.exporter.target().c_str());
    ImGui::ProgressBar(static_cast<float>(state.jobs.exporter.progress()), ImVec2(400, 0));
    if (ImGui::Button("Cancel")) state.jobs.exporter.cancel();
    ImGui::TextDisabled("nothing is written until the end; Cancel leaves no file");
    ImGui::EndPopup();
  }
}

}  // namespace somicage::editor
