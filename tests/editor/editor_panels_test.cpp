// Panels drawn in a headless ImGui frame (no window, no GL), as ImGui's example_null does: issue 24's cosmetic rows
// that only a drawn frame shows.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>  // FindWindowByName, GImGui->LogBuffer: where a window is, the text a frame drew

#include <functional>
#include <string>
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

  // The text `draw` draws with the mouse held at `mouse`: the third frame's, when ImGui has settled what is hovered
  // (from the windows of the frame before) and the tooltips it opens.
  static std::string textDrawnHovering(ImVec2 mouse, const std::function<void()>& draw) {
    std::string drawn;
    for (int frame = 0; frame < 3; ++frame) {
      ImGui::GetIO().MousePos = mouse;
      ImGui::NewFrame();
      if (frame == 2) ImGui::LogToBuffer();
      draw();
      if (frame == 2) {
        drawn = GImGui->LogBuffer.c_str();
        ImGui::LogFinish();
      }
      ImGui::EndFrame();
    }
    return drawn;
  }
};

}  // namespace

// Issue 24, row 15: "Sweep nu" had no tooltip. Hovering the button shows what it does.
TEST_F(HeadlessFrame, SweepNuHasATooltip) {
  AppState state;
  openDemoScene(state);
  // The button is the window's first item, at its padding.
  const std::string drawn = textDrawnHovering(ImVec2(24, 18), [&state] {
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(340, 400));
    ImGui::Begin("Controls", nullptr, ImGuiWindowFlags_NoTitleBar);
    drawNuPlot(state);
    ImGui::End();
  });
  EXPECT_NE(drawn.find("Sweep nu"), std::string::npos) << drawn;
  EXPECT_NE(drawn.find("Deform the current pose at 25 values of nu"), std::string::npos) << drawn;
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
  EXPECT_GT(window->Pos.x, static_cast<float>(last.x)) << "the window is over the last pane";
  ImGui::EndFrame();
}

// Issue 24, row 15: a long notice ran off the status bar with no way to read it. Hovering the bar shows the whole
// message in a tooltip: the message is drawn twice, once cut in the bar and once whole.
TEST_F(HeadlessFrame, HoveringTheStatusBarShowsTheWholeMessage) {
  AppState state;
  openDemoScene(state);
  state.status.message = "loaded bar; mesh warning: 640 of 642 points lie outside the cage (or on it); they follow "
                         "the cage's nearest faces, see the log for the whole of this long line";
  const std::string drawn = textDrawnHovering(ImVec2(500, 690), [&state] { drawStatusBar(state); });  // the bar
  const std::string tail = "see the log for the whole of this long line";
  const std::size_t first = drawn.find(tail);
  ASSERT_NE(first, std::string::npos) << drawn;
  EXPECT_NE(drawn.find(tail, first + 1), std::string::npos) << "no tooltip with the whole message:\n" << drawn;
}
