// An ImGui context without a window or GL, as ImGui 1.86's examples/example_null: the font atlas built and the
// display size set by hand, so panels and the input handler run in a test. ImGui::DestroyContext() ends it.
#pragma once

#include <imgui.h>

namespace somicage::editor {

inline ImGuiContext* createHeadlessImGui(float width, float height) {
  ImGuiContext* context = ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(width, height);
  io.DeltaTime = 1.0f / 60.0f;
  io.IniFilename = nullptr;
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  return context;
}

}  // namespace somicage::editor
