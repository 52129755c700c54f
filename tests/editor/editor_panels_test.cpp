// Panels drawn in a headless ImGui frame (no window, no GL), as ImGui's example_null does: issue 24's rows
// that only a drawn frame shows.
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>  // FindWindowByName, ImGuiWindow: where a window is, what it holds

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/scratch_folder.h"
#include "drawn_text.h"
#include "editor_test_support.h"
#include "headless_imgui.h"
#include "model/app_state.h"
#include "model/recent_files.h"
#include "model/scene.h"
#include "ui/file_dialog.h"
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

  // One frame of `draw` with the mouse at `mouse`, its left button down or not.
  static void frame(ImVec2 mouse, bool down, const std::function<void()>& draw) {
    ImGui::GetIO().MousePos = mouse;
    ImGui::GetIO().MouseDown[0] = down;
    ImGui::NewFrame();
    draw();
    ImGui::EndFrame();
  }
  // A click on the text `label` (drawn in the frame before): press, then release, over its first glyph.
  static void click(const std::string& label, const std::function<void()>& draw) {
    const std::optional<ImVec2> at = whereDrawn(label);
    ASSERT_TRUE(at.has_value()) << "'" << label << "' is not drawn";
    const ImVec2 mouse(at->x + 3, at->y + 0.5f * ImGui::GetFontSize());
    frame(mouse, false, draw);  // hovered first, as a real mouse is
    frame(mouse, true, draw);
    frame(mouse, false, draw);
  }
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

// Issue 24, row 15: the pose library's hint ran out of its window, cut at "Store c". It wraps inside the window.
TEST_F(HeadlessFrame, ThePoseLibrarysHintWrapsInsideItsWindow) {
  AppState state;  // no poses: the hint is shown
  ImGui::NewFrame();
  drawPoseLibraryPanel(state, menuBarHeight());
  const ImGuiWindow* window = ImGui::FindWindowByName("Pose library");
  ASSERT_NE(window, nullptr);
  EXPECT_LE(window->DC.CursorMaxPos.x, window->Pos.x + window->Size.x) << "a line runs past the window's right edge";
  ImGui::EndFrame();
}

// Issue 24, row 9: the nu sweep's plot had no nu axis labels. Under the plot, on one line: the sweep's first nu at
// its left end, its last at its right end and "nu" between them (this test's sweep runs from -0.95 to 0.49).
TEST_F(HeadlessFrame, TheNuPlotLabelsItsNuAxis) {
  AppState state;
  openDemoScene(state);
  for (int k = 0; k < 25; ++k) {
    const double nu = -0.95 + (0.49 + 0.95) * k / 24.0;
    state.view.quantities.nuSweep.push_back({nu, 0.01 * nu, k > 20 ? 3 : 0});
  }
  ImGui::NewFrame();
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(340, 400));
  ImGui::Begin("Controls", nullptr, ImGuiWindowFlags_NoTitleBar);
  drawNuPlot(state);
  ImGui::End();
  ImGui::EndFrame();
  const ImGuiWindow* window = ImGui::FindWindowByName("Controls");
  ASSERT_NE(window, nullptr);
  std::optional<DrawnText> lo, hi, name, legend, button;
  for (const DrawnText& run : drawnText(*window->DrawList)) {
    if (run.text == "Sweep nu") button = run;
    if (run.text == "-0.95") lo = run;
    if (run.text == "0.49") hi = run;
    if (run.text == "nu") name = run;
    if (run.text.rfind("- volume change", 0) == 0) legend = run;
  }
  ASSERT_TRUE(lo && hi && name) << "the nu axis' labels (-0.95, nu, 0.49) are not all drawn";
  ASSERT_TRUE(legend && button);
  EXPECT_EQ(lo->pos.y, hi->pos.y);
  EXPECT_EQ(lo->pos.y, name->pos.y) << "the axis' labels on one line";
  EXPECT_LT(lo->pos.x, name->pos.x);
  EXPECT_LT(name->pos.x, hi->pos.x);
  EXPECT_LT(lo->pos.y, legend->pos.y) << "the axis is above the legend (the plot's lines are under it)";
  EXPECT_GT(hi->pos.x - lo->pos.x, 0.6f * 340) << "the labels span the plot's width";
  EXPECT_GT(lo->pos.y, button->pos.y + 80) << "the axis is under the plot (80 pixels high, under the button)";
}

// Issue 24, row 6: OK moved down the Open dialog as the Recent list grew. With ten recent scenes (the most kept)
// OK is where it was with none.
TEST_F(HeadlessFrame, TheOpenDialogsOkStaysInPlaceAsRecentGrows) {
  const std::filesystem::path empty = std::filesystem::path(::testing::TempDir()) / "somicage_open_ok_empty";
  std::filesystem::create_directories(empty);
  AppState state;
  openFileDialog(state, FileDialogPurpose::OpenScene);
  state.files.dialog.folder = empty.string();  // the browser's listing: nothing
  auto okAt = [&state] {
    for (int k = 0; k < 4; ++k) frame(ImVec2(-1, -1), false, [&state] { drawFileDialog(state); });  // auto-size
    return whereDrawn("OK");
  };
  const std::optional<ImVec2> before = okAt();
  ASSERT_TRUE(before.has_value()) << "no OK drawn";
  for (int i = 0; i < static_cast<int>(RecentFiles::kMaxEntries); ++i)
    noteRecent(state,
               RecentEntry::files("/m/scene" + std::to_string(i) + ".obj", "/m/cage" + std::to_string(i) + ".obj"));
  ASSERT_EQ(state.files.recent.entries().size(), RecentFiles::kMaxEntries);
  const std::optional<ImVec2> after = okAt();
  ASSERT_TRUE(after.has_value()) << "no OK drawn";
  EXPECT_TRUE(whereDrawn("scene9.obj + cage9.obj").has_value()) << "the newest entry is listed";
  EXPECT_EQ(after->y, before->y) << "OK moved as Recent grew";
  EXPECT_EQ(after->x, before->x);
  std::filesystem::remove_all(empty);
}

// Issue 24, row 10: there was no File > Open Recent, and a saved session was not in it until opened once. Two
// sessions saved: both are in the menu, and a click on the older one opens that one.
TEST_F(HeadlessFrame, FileOpenRecentListsSavedSessionsAndOpensTheChosenOne) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "somicage_open_recent_menu";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  AppState state;
  state.model.scene = std::make_shared<const Scene>(makeDemoScene(2));
  state.document.pose = state.model.scene->restCage.vertices;
  const std::string older = (dir / "older.json").string(), newer = (dir / "newer.json").string();
  ASSERT_TRUE(saveSessionFile(state, older));
  ASSERT_TRUE(saveSessionFile(state, newer));
  state.status.message.clear();
  const auto menu = [&state] { drawMainMenu(state); };
  frame(ImVec2(-1, -1), false, menu);
  click("File", menu);
  ASSERT_TRUE(whereDrawn("Open Recent").has_value()) << "no Open Recent in the File menu";
  const ImVec2 recent = *whereDrawn("Open Recent");
  for (int k = 0; k < 3; ++k) frame(ImVec2(recent.x + 3, recent.y + 5), false, menu);  // hovering opens it
  EXPECT_TRUE(whereDrawn("session newer.json").has_value()) << "the last saved session is not in Open Recent";
  click("session older.json", menu);
  finishSessionRead(state);
  EXPECT_EQ(state.status.message, "opened session " + older);
  EXPECT_EQ(state.files.recent.entries().front().session, older) << "the opened one comes first";
  std::filesystem::remove_all(dir);
}

// While a session is read (on its job), the control panel shows the stage naming the file, with a progress bar, and
// its Cancel stops it: the document open before stays, and the status says the session was not opened.
TEST_F(HeadlessFrame, WhileASessionIsReadThePanelShowsItAndItsCancelStopsIt) {
  ImGui::GetIO().DisplaySize = ImVec2(1000, 3000);  // tall enough for the panel's last sections
  const test::ScratchFolder dir;
  const std::string session = dir / "opened.json";
  SteeredSessionReader steered;
  AppState state;
  openDemoScene(state, 2);
  ASSERT_TRUE(saveSessionFile(state, session));
  const Document before = currentDocument(state);
  const std::size_t steps = state.document.history.size();
  loadSessionFile(state, session, steered.reader());
  waitUntil([&steered] { return steered.entered.load(); });
  const auto panel = [&state] { drawControlPanel(state); };
  frame(ImVec2(-1, -1), false, panel);
  EXPECT_TRUE(whereDrawn("Reading session opened.json").has_value()) << "the panel does not show the read";
  click("Cancel", panel);
  finishSessionRead(state);
  EXPECT_FALSE(steered.timedOut) << "Cancel did not stop the read";
  EXPECT_EQ(state.status.message, "opening session " + session + " cancelled");
  EXPECT_TRUE(currentDocument(state) == before);
  EXPECT_EQ(state.document.history.size(), steps);
}
