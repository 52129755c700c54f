// The real input handler (input.cpp) driven through ImGui without a window or GL, as in ImGui's
// examples/example_null (1.86: build the font atlas and set DisplaySize by hand): clicks, Shift+click,
// box selection, handle drags, G/R/S with Enter/Esc, A / Alt+A, undo/redo shortcuts, Esc cancelling a precompute,
// Space playing the timeline.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>
#include <imgui.h>

#include <atomic>
#include <cstdio>
#include <thread>

#include "headless_imgui.h"
#include "interaction/input.h"
#include "job_waiting.h"
#include "model/app_state.h"
#include "model/pose_keys.h"
#include "ui/layout.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

class InputHarness : public ::testing::Test {
 protected:
  void SetUp() override {
    createHeadlessImGui(1000, 700);
    views = layoutViews(1000, 700, 0, 0, 0, 1);
    state.view.panes = views;
    requestDemo(state, 3);
    std::optional<PrecomputeOutcome> out = waitForOutcome(state.jobs.precompute);
    ASSERT_TRUE(out.has_value());
    installOutcome(state, std::move(*out));
    ASSERT_TRUE(state.model.scene);
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
    state.view.camera.project(state.document.pose.row(i).transpose(), views[0].width, views[0].height, s);
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
  EXPECT_EQ(state.input.selection.indices(), (std::vector<int>{3}));
  ImGui::GetIO().KeyShift = true;
  click(handle(5));
  EXPECT_EQ(state.input.selection.indices(), (std::vector<int>{3, 5}));
  click(handle(3));
  EXPECT_EQ(state.input.selection.indices(), (std::vector<int>{5}));
  ImGui::GetIO().KeyShift = false;
  click(Eigen::Vector2d(3, 3));  // background click clears
  EXPECT_TRUE(state.input.selection.empty());
  EXPECT_FALSE(state.document.history.canUndo());  // selecting is not a pose edit
}

TEST_F(InputHarness, BoxDragSelectsTheHandlesInside) {
  moveTo(Eigen::Vector2d(2, 2));
  button(0, true);
  moveTo(Eigen::Vector2d(500, 698));  // the left half of the view
  button(0, false);
  const std::vector<int> picked = state.input.selection.indices();
  ASSERT_FALSE(picked.empty());
  for (int i : picked) EXPECT_LT(handle(i).x(), 500.0);
  EXPECT_LT(picked.size(), 20u);
}

TEST_F(InputHarness, DraggingAHandleMovesTheSelectionAndUndoes) {
  const Eigen::MatrixXd before = state.document.pose;
  const int v = someVertex();
  moveTo(handle(v));
  button(0, true);
  moveTo(handle(v) + Eigen::Vector2d(60, -30));
  button(0, false);
  EXPECT_GT((state.document.pose.row(v) - before.row(v)).norm(), 0.05);
  for (int i = 0; i < state.document.pose.rows(); ++i) {
    if (i != v) {
      EXPECT_EQ(state.document.pose.row(i), before.row(i));
    }
  }
  ASSERT_TRUE(state.document.history.canUndo());
  ImGui::GetIO().KeyCtrl = true;
  key(GLFW_KEY_Z);
  EXPECT_EQ(state.document.pose, before);
  ImGui::GetIO().KeyShift = true;
  key(GLFW_KEY_Z);  // Ctrl+Shift+Z redoes
  EXPECT_NE(state.document.pose, before);
  ImGui::GetIO().KeyCtrl = ImGui::GetIO().KeyShift = false;
}

TEST_F(InputHarness, GrabWithAxisConfirmsWithEnterAndCancelsWithEscape) {
  key(GLFW_KEY_A);  // select all
  EXPECT_EQ(state.input.selection.count(), 20);
  const Eigen::MatrixXd before = state.document.pose;
  moveTo(Eigen::Vector2d(500, 350));
  key(GLFW_KEY_G);
  key(GLFW_KEY_Y);
  moveTo(Eigen::Vector2d(530, 300));
  EXPECT_EQ(state.document.pose.col(0), before.col(0));  // constrained to y
  EXPECT_EQ(state.document.pose.col(2), before.col(2));
  EXPECT_GT((state.document.pose.col(1) - before.col(1)).minCoeff(), 0.0);  // everything moved up
  key(GLFW_KEY_ENTER);
  EXPECT_TRUE(state.document.history.canUndo());
  const Eigen::MatrixXd grabbed = state.document.pose;

  key(GLFW_KEY_S);
  moveTo(Eigen::Vector2d(700, 200));
  EXPECT_NE(state.document.pose, grabbed);
  key(GLFW_KEY_ESCAPE);
  EXPECT_EQ(state.document.pose, grabbed);
  EXPECT_EQ(state.document.history.cursor(), 1u);  // one step (the grab) above the original

  key(GLFW_KEY_R);
  moveTo(Eigen::Vector2d(600, 500));
  button(1, true);  // right click cancels
  button(1, false);
  EXPECT_EQ(state.document.pose, grabbed);

  ImGui::GetIO().KeyAlt = true;
  key(GLFW_KEY_A);  // Alt+A: select none
  ImGui::GetIO().KeyAlt = false;
  EXPECT_TRUE(state.input.selection.empty());
  key(GLFW_KEY_G);  // nothing selected: no transform starts
  EXPECT_EQ(state.input.mouse.mode, Interaction::Mode::Idle);
}

TEST_F(InputHarness, WheelZoomsAndMiddleDragOrbits) {
  const CameraState before = state.view.camera.state();
  moveTo(Eigen::Vector2d(500, 350));
  ImGui::GetIO().MouseWheel = 2.0f;
  frame();
  ImGui::GetIO().MouseWheel = 0.0f;
  EXPECT_LT(state.view.camera.state().distance, before.distance);
  button(2, true);
  moveTo(Eigen::Vector2d(560, 350));
  button(2, false);
  EXPECT_NE(state.view.camera.state().yaw, before.yaw);
  key(GLFW_KEY_F);  // frame all restores a sensible distance
  EXPECT_GT(state.view.camera.state().distance, 0.0);
}

// Esc cancels a running precompute (before, only the panel's Cancel button did): a load held until the key has been
// handled ends cancelled, and the scene on screen stays.
TEST_F(InputHarness, EscapeCancelsARunningPrecompute) {
  const std::shared_ptr<const Scene> shown = state.model.scene;
  std::atomic<bool> loading{false}, release{false};
  PrecomputeRequest request;
  request.loadScene = [&] {
    loading = true;
    while (!release) std::this_thread::yield();
    return makeDemoScene(2);
  };
  request.methods = {state.document.method};
  state.jobs.load.emplace();
  state.jobs.precompute.start(std::move(request));
  while (!loading) std::this_thread::yield();
  moveTo(Eigen::Vector2d(500, 350));
  key(GLFW_KEY_ESCAPE);
  release = true;
  std::optional<PrecomputeOutcome> out = waitForOutcome(state.jobs.precompute);
  ASSERT_TRUE(out.has_value());
  EXPECT_TRUE(out->cancelled) << "Esc did not cancel the precompute";
  installOutcome(state, std::move(*out));
  EXPECT_EQ(state.model.scene, shown);
  EXPECT_FALSE(state.loadingScene());
}

// Space plays the timeline from the cursor and stops it (before, only the panel's Play button did); without keys
// it says why nothing plays.
TEST_F(InputHarness, SpacePlaysAndStopsTheTimeline) {
  key(GLFW_KEY_SPACE);
  EXPECT_FALSE(state.animation.playing);
  EXPECT_NE(state.status.message.find("nothing to play"), std::string::npos) << state.status.message;

  state.animation.timeline.interpolation = Interpolation::Linear;
  state.animation.timeline.fps = 24;
  keyCurrentPose(state);  // frame 0: rest
  Eigen::MatrixXd moved = state.document.pose;
  moved.col(1).array() += 0.5;
  setPose(state, moved);
  state.animation.frame = 48;
  keyCurrentPose(state);
  state.animation.frame = 0;
  key(GLFW_KEY_SPACE);
  ASSERT_TRUE(state.animation.playing);
  tickPlayback(state, 100.0);  // the clock starts at the first tick after the key
  EXPECT_EQ(state.animation.frame, 0.0);
  tickPlayback(state, 101.0);  // one second at 24 fps: frame 24, half-way between the keys
  EXPECT_EQ(state.animation.frame, 24.0);
  EXPECT_LE((state.document.pose.col(1) - (moved.col(1).array() - 0.25).matrix()).cwiseAbs().maxCoeff(), 1e-12);
  key(GLFW_KEY_SPACE);
  EXPECT_FALSE(state.animation.playing);
}

// Issue 24, row 12: dragging a handle (or the gizmo) showed no numbers, where G / R / S do. The header reads the
// displacement the drag made (to its 4 printed digits), and goes with the release.
TEST_F(InputHarness, DraggingAHandleShowsItsDisplacement) {
  const Eigen::MatrixXd before = state.document.pose;
  const int v = someVertex();
  moveTo(handle(v));
  button(0, true);
  EXPECT_EQ(transformHeader(state, views), "") << "a press is no drag yet";
  moveTo(handle(v) + Eigen::Vector2d(60, -30));
  const std::string header = transformHeader(state, views);
  double x = 0, y = 0, z = 0;
  ASSERT_EQ(std::sscanf(header.c_str(), "Grab: (%lf, %lf, %lf)", &x, &y, &z), 3) << header;
  const Eigen::Vector3d moved = (state.document.pose.row(v) - before.row(v)).transpose();
  EXPECT_GT(moved.norm(), 0.05);
  EXPECT_LE((Eigen::Vector3d(x, y, z) - moved).cwiseAbs().maxCoeff(), 1e-3 * moved.norm()) << header;
  EXPECT_EQ(header.find('['), std::string::npos) << "a drag takes no keys: " << header;
  button(0, false);
  EXPECT_EQ(transformHeader(state, views), "");
}
