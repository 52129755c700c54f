// The real input handler (input.cpp) driven through ImGui without a window or GL, as in ImGui's
// examples/example_null (1.86: build the font atlas and set DisplaySize by hand): clicks, Shift+click,
// box selection, handle drags, G/R/S with Enter/Esc, A / Alt+A, undo/redo shortcuts.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>
#include <imgui.h>

#include "app_state.h"
#include "input.h"
#include "layout.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

class InputHarness : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(1000, 700);
    io.DeltaTime = 1.0f / 60.0f;
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    views = layoutViews(1000, 700, 0, 0, 0, 1);
    state.viewAspect = views[0].width / views[0].height;
    requestDemo(state, 3);
    std::optional<PrecomputeOutcome> out = state.worker.wait();
    ASSERT_TRUE(out.has_value());
    installOutcome(state, std::move(*out));
    ASSERT_TRUE(state.scene);
    frame();
  }
  void TearDown() override { ImGui::DestroyContext(); }

  void frame() {
    ImGui::NewFrame();
    handleInput(state, views);
    ImGui::EndFrame();
  }
  void moveTo(const Eigen::Vector2d& p) {
    ImGui::GetIO().MousePos = ImVec2(static_cast<float>(p.x()), static_cast<float>(p.y()));
    frame();
  }
  void button(int b, bool down) {
    ImGui::GetIO().MouseDown[b] = down;
    frame();
  }
  void click(const Eigen::Vector2d& p) {
    moveTo(p);
    button(0, true);
    button(0, false);
  }
  void key(int k) {
    ImGui::GetIO().KeysDown[k] = true;
    frame();
    ImGui::GetIO().KeysDown[k] = false;
    frame();
  }
  Eigen::Vector2d handle(int i) const {
    Eigen::Vector2d s;
    state.camera.project(state.pose.row(i).transpose(), views[0].width, views[0].height, s);
    return s + views[0].origin();
  }
  // A cage vertex whose handle is not covered by another one (the demo view shows all 20 apart).
  int someVertex() const { return 7; }

  AppState state;
  std::vector<ViewRect> views;
};

}  // namespace

TEST_F(InputHarness, ClickSelectsAndShiftClickToggles) {
  click(handle(3));
  EXPECT_EQ(state.selection.indices(), (std::vector<int>{3}));
  ImGui::GetIO().KeyShift = true;
  click(handle(5));
  EXPECT_EQ(state.selection.indices(), (std::vector<int>{3, 5}));
  click(handle(3));
  EXPECT_EQ(state.selection.indices(), (std::vector<int>{5}));
  ImGui::GetIO().KeyShift = false;
  click(Eigen::Vector2d(3, 3));  // background click clears
  EXPECT_TRUE(state.selection.empty());
  EXPECT_FALSE(state.history.canUndo());  // selecting is not a pose edit
}

TEST_F(InputHarness, BoxDragSelectsTheHandlesInside) {
  moveTo(Eigen::Vector2d(2, 2));
  button(0, true);
  moveTo(Eigen::Vector2d(500, 698));  // the left half of the view
  button(0, false);
  const std::vector<int> picked = state.selection.indices();
  ASSERT_FALSE(picked.empty());
  for (int i : picked) EXPECT_LT(handle(i).x(), 500.0);
  EXPECT_LT(picked.size(), 20u);
}

TEST_F(InputHarness, DraggingAHandleMovesTheSelectionAndUndoes) {
  const Eigen::MatrixXd before = state.pose;
  const int v = someVertex();
  moveTo(handle(v));
  button(0, true);
  moveTo(handle(v) + Eigen::Vector2d(60, -30));
  button(0, false);
  EXPECT_GT((state.pose.row(v) - before.row(v)).norm(), 0.05);
  for (int i = 0; i < state.pose.rows(); ++i) {
    if (i != v) {
      EXPECT_EQ(state.pose.row(i), before.row(i));
    }
  }
  ASSERT_TRUE(state.history.canUndo());
  ImGui::GetIO().KeyCtrl = true;
  key(GLFW_KEY_Z);
  EXPECT_EQ(state.pose, before);
  ImGui::GetIO().KeyShift = true;
  key(GLFW_KEY_Z);  // Ctrl+Shift+Z redoes
  EXPECT_NE(state.pose, before);
  ImGui::GetIO().KeyCtrl = ImGui::GetIO().KeyShift = false;
}

TEST_F(InputHarness, GrabWithAxisConfirmsWithEnterAndCancelsWithEscape) {
  key(GLFW_KEY_A);  // select all
  EXPECT_EQ(state.selection.count(), 20);
  const Eigen::MatrixXd before = state.pose;
  moveTo(Eigen::Vector2d(500, 350));
  key(GLFW_KEY_G);
  key(GLFW_KEY_Y);
  moveTo(Eigen::Vector2d(530, 300));
  EXPECT_EQ(state.pose.col(0), before.col(0));  // constrained to y
  EXPECT_EQ(state.pose.col(2), before.col(2));
  EXPECT_GT((state.pose.col(1) - before.col(1)).minCoeff(), 0.0);  // everything moved up
  key(GLFW_KEY_ENTER);
  EXPECT_TRUE(state.history.canUndo());
  const Eigen::MatrixXd grabbed = state.pose;

  key(GLFW_KEY_S);
  moveTo(Eigen::Vector2d(700, 200));
  EXPECT_NE(state.pose, grabbed);
  key(GLFW_KEY_ESCAPE);
  EXPECT_EQ(state.pose, grabbed);
  EXPECT_EQ(state.history.cursor(), 1u);  // one step (the grab) above the original

  key(GLFW_KEY_R);
  moveTo(Eigen::Vector2d(600, 500));
  button(1, true);  // right click cancels
  button(1, false);
  EXPECT_EQ(state.pose, grabbed);

  ImGui::GetIO().KeyAlt = true;
  key(GLFW_KEY_A);  // Alt+A: select none
  ImGui::GetIO().KeyAlt = false;
  EXPECT_TRUE(state.selection.empty());
  key(GLFW_KEY_G);  // nothing selected: no transform starts
  EXPECT_EQ(state.interaction.mode, Interaction::Mode::Idle);
}

TEST_F(InputHarness, WheelZoomsAndMiddleDragOrbits) {
  const CameraState before = state.camera.state();
  moveTo(Eigen::Vector2d(500, 350));
  ImGui::GetIO().MouseWheel = 2.0f;
  frame();
  ImGui::GetIO().MouseWheel = 0.0f;
  EXPECT_LT(state.camera.state().distance, before.distance);
  button(2, true);
  moveTo(Eigen::Vector2d(560, 350));
  button(2, false);
  EXPECT_NE(state.camera.state().yaw, before.yaw);
  key(GLFW_KEY_F);  // frame all restores a sensible distance
  EXPECT_GT(state.camera.state().distance, 0.0);
}
