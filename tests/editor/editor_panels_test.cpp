// Panels drawn in a headless ImGui frame (no window, no GL), as ImGui's example_null does: issue 24's cosmetic rows
// that only a drawn frame shows.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>  // FindWindowByName, ImGuiWindow: where a window is, what it holds

#include <functional>
#include <vector>

#include "editor_test_support.h"
#include "headless_imgui.h"
#include "model/app_state.h"
#include "ui/layout.h"
#include "ui/panels.h"
#include "ui/quantity_overlay.h"
#include "ui/timeline_panel.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

class HeadlessFrame : public ::testing::Test {
 protected:
  void SetUp() override { createHeadlessImGui(1000, 700); }
  void TearDown() override { ImGui::DestroyContext(); }

  // The tooltip `draw` opens with the mouse held at `mouse` (null: none), after the frames ImGui takes to settle
  // what is hovered (from the windows of the frame before). Its text extent is DC.CursorMaxPos - CursorStartPos.
  static const ImGuiWindow* tooltipWhileHovering(ImVec2 mouse, const std::function<void()>& draw) {
    for (int frame = 0; frame < 4; ++frame) {
      ImGui::GetIO().MousePos = mouse;
      ImGui::NewFrame();
      draw();
      ImGui::EndFrame();
    }
    const ImGuiWindow* tooltip = ImGui::FindWindowByName("##Tooltip_00");  // ImGui 1.86's name for the first one
    return tooltip && tooltip->Active ? tooltip : nullptr;
  }
  static float textHeight(const ImGuiWindow* window) { return window->DC.CursorMaxPos.y - window->DC.CursorStartPos.y; }
};

}  // namespace

// Issue 24, row 15: "Sweep nu" had no tooltip. Hovering the button shows what it does.
TEST_F(HeadlessFrame, SweepNuHasATooltip) {
  AppState state;
  openDemoScene(state);
  // The button is the window's first item, at its padding.
  const ImGuiWindow* tooltip = tooltipWhileHovering(ImVec2(24, 18), [&state] {
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(340, 400));
    ImGui::Begin("Controls", nullptr, ImGuiWindowFlags_NoTitleBar);
    drawNuPlot(state);
    ImGui::End();
  });
  ASSERT_NE(tooltip, nullptr) << "no tooltip over Sweep nu";
  EXPECT_GE(textHeight(tooltip), 3 * ImGui::GetFontSize()) << "its three lines";
}

// Issue 24, row 15: the pose library window covered the third pane's label. It starts below the last pane's label
// and the three lines of numbers under it (volume change, fold-overs, p95 distortion).
TEST_F(HeadlessFrame, ThePoseLibraryStartsBelowTheLastPanesLabelAndItsNumbers) {
  AppState state;
  ImGui::NewFrame();
  const double top = menuBarHeight();
  const std::vector<ViewRect> views = layoutViews(1000, 700, panelWidth(1000), top, statusBarHeight(), 3);
  drawPoseLibraryPanel(state, top);
  const ImGuiWindow* window = ImGui::FindWindowByName("Pose library");
  ASSERT_NE(window, nullptr);
  const ViewRect& last = views.back();
  const float labelsBottom = static_cast<float>(last.y + 8) + 4 * ImGui::GetTextLineHeightWithSpacing() + 4;
  EXPECT_GE(window->Pos.y, labelsBottom) << "the window covers the last pane's label or its numbers";
  EXPECT_LT(window->Pos.x, static_cast<float>(last.x + 10)) << "the window is over the last pane's label";
  ImGui::EndFrame();
}

// Issue 24, row 15: a long notice ran off the status bar with no way to read it. Hovering the bar shows the whole
// message in a tooltip, wrapped (the bar cuts it at the window's edge).
TEST_F(HeadlessFrame, HoveringTheStatusBarShowsTheWholeMessage) {
  AppState state;
  openDemoScene(state);
  state.status.message = "loaded bar; mesh warning: 640 of 642 points lie outside the cage (or on it); they follow "
                         "the cage's nearest faces, see the log for the whole of this long line";
  const ImGuiWindow* tooltip =
      tooltipWhileHovering(ImVec2(500, 690), [&state] { drawStatusBar(state); });  // on the bar
  ASSERT_NE(tooltip, nullptr) << "no tooltip over the status bar";
  EXPECT_GE(textHeight(tooltip), 2 * ImGui::GetFontSize()) << "the message, wrapped onto two lines or more";
}
