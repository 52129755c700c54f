// The undo history (history.h) and every document command through AppState: each is one step, undo restores
// the state before it exactly (bitwise), redo the state after it, the Undo History jumps to any step, and the
// unsaved-changes state follows the saved step.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>

#include "editor_test_support.h"
#include "io/obj_io.h"
#include "job_waiting.h"
#include "methods/method_descriptors.h"
#include "model/app_state.h"
#include "model/history.h"
#include "model/pose_clear.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

Document doc(double x) {
  Document d;
  d.pose = Eigen::MatrixXd::Constant(2, 3, x);
  return d;
}

// The 3D demo installed as a freshly opened scene (history: the original only).
class DocumentCommands : public ::testing::Test {
 protected:
  void SetUp() override {
    openDemoScene(state);
    rest = state.document.pose;
  }
  // Runs a command and checks: one new step named `name`, undo gives back the state before exactly, redo the
  // state after exactly.
  void expectOneUndoableStep(const std::string& name, const std::function<void()>& command) {
    const Document before = currentDocument(state);
    const std::size_t steps = state.document.history.cursor();
    command();
    const Document after = currentDocument(state);
    ASSERT_NE(after, before) << name << " changed nothing";
    ASSERT_EQ(state.document.history.cursor(), steps + 1) << name;
    EXPECT_EQ(state.document.history.step(state.document.history.cursor()).name, name);
    undo(state);
    EXPECT_EQ(currentDocument(state), before) << "undo " << name;
    EXPECT_EQ(state.status.message, "undo " + name);
    redo(state);
    EXPECT_EQ(currentDocument(state), after) << "redo " << name;
    EXPECT_EQ(state.status.message, "redo " + name);
  }
  Eigen::MatrixXd moved(double dy) const {
    Eigen::MatrixXd p = rest;
    p(0, 1) += dy;
    p(5, 0) -= 0.5 * dy;
    return p;
  }

  AppState state;
  Eigen::MatrixXd rest;
};

}  // namespace

TEST(EditorHistory, UndoRedoAndJumpWalkTheSteps) {
  History h;
  h.reset(doc(0), "Original", true);
  EXPECT_FALSE(h.canUndo());
  for (double x : {1.0, 2.0, 3.0}) EXPECT_TRUE(h.commit("move", doc(x)));
  EXPECT_EQ(h.size(), 4u);
  EXPECT_EQ(h.undo().pose(0, 0), 2.0);
  EXPECT_EQ(h.undo().pose(0, 0), 1.0);
  EXPECT_EQ(h.redo().pose(0, 0), 2.0);
  EXPECT_TRUE(h.canUndo());
  EXPECT_TRUE(h.canRedo());
  EXPECT_EQ(h.jumpTo(0).pose(0, 0), 0.0);
  EXPECT_EQ(h.jumpTo(3).pose(0, 0), 3.0);
  EXPECT_FALSE(h.canRedo());
}

TEST(EditorHistory, NoChangeIsNoStepAndANewStepDropsRedo) {
  History h;
  h.reset(doc(0), "Original", true);
  EXPECT_FALSE(h.commit("nothing", doc(0)));
  EXPECT_EQ(h.size(), 1u);
  h.commit("a", doc(1));
  h.commit("b", doc(2));
  h.undo();
  h.undo();
  EXPECT_TRUE(h.commit("c", doc(5)));
  EXPECT_FALSE(h.canRedo());
  EXPECT_EQ(h.size(), 2u);
  EXPECT_EQ(h.step(1).name, "c");
}

// The revision changes with each change of the current state (a commit that adds a step, undo, redo, a jump to
// another step, a reset; undo and redo back are two changes) and with nothing else (a commit of the same state, a
// jump to the current step, saving, reading).
TEST(EditorHistory, TheRevisionCountsTheChangesOfTheCurrentState) {
  History h;
  std::uint64_t seen = h.revision();
  const auto changed = [&h, &seen] {
    const bool moved = h.revision() != seen;
    seen = h.revision();
    return moved;
  };
  h.reset(doc(0), "Original", true);
  EXPECT_TRUE(changed());
  EXPECT_FALSE(h.commit("nothing", doc(0)));
  h.markSaved();
  h.jumpTo(h.cursor());
  (void)h.current();
  EXPECT_FALSE(changed());
  h.commit("a", doc(1));
  EXPECT_TRUE(changed());
  h.undo();
  EXPECT_TRUE(changed());
  h.redo();
  EXPECT_TRUE(changed());
  h.jumpTo(0);
  EXPECT_TRUE(changed());
  History capped(2);
  capped.reset(doc(0), "Original", true);
  for (int i = 1; i < 4; ++i) {
    const std::uint64_t before = capped.revision();
    capped.commit("move", doc(i));  // the oldest step goes too
    EXPECT_NE(capped.revision(), before) << i;
  }
}

TEST(EditorHistory, CapacityDropsTheOldestStep) {
  History h(3);
  h.reset(doc(0), "Original", true);
  for (int i = 1; i < 10; ++i) h.commit("move", doc(i));
  EXPECT_EQ(h.size(), 3u);
  EXPECT_EQ(h.current().pose(0, 0), 9.0);
  EXPECT_EQ(h.step(0).state.pose(0, 0), 7.0);
  EXPECT_TRUE(h.unsaved());  // the saved (original) state was dropped
}

TEST(EditorHistory, UnsavedFollowsTheSavedStep) {
  History h;
  h.reset(doc(0), "Original", true);
  EXPECT_FALSE(h.unsaved());
  h.commit("a", doc(1));
  EXPECT_TRUE(h.unsaved());
  h.undo();
  EXPECT_FALSE(h.unsaved());  // back at the saved state
  h.redo();
  h.markSaved();
  EXPECT_FALSE(h.unsaved());
  h.undo();
  EXPECT_TRUE(h.unsaved());
  h.commit("b", doc(2));  // the saved step was a redo step: gone
  h.undo();
  EXPECT_TRUE(h.unsaved());
  h.reset(doc(0), "Restored", false);  // a crashed run's autosave exists nowhere else
  EXPECT_TRUE(h.unsaved());
}

TEST_F(DocumentCommands, EveryCommandIsOneExactUndoableStep) {
  expectOneUndoableStep("Grab", [&] {
    setPose(state, moved(0.4));
    commitEdit(state, "Grab");
  });
  expectOneUndoableStep("Reset pose", [&] { resetPose(state); });
  EXPECT_EQ(state.document.pose, rest);
  undo(state);  // the case: drag, Reset pose, Ctrl+Z gives the dragged pose back
  EXPECT_EQ(state.document.pose, moved(0.4));

  const auto param = [&](const char* name, auto change) {
    expectOneUndoableStep(name, [&] {
      DeformParams p = state.document.params;
      change(p);
      setParams(state, p);
      commitEdit(state, name);
    });
  };
  param("nu", [](DeformParams& p) { p.nu = 0.3; });
  param("nu", [](DeformParams& p) { p.nu = std::numeric_limits<double>::infinity(); });
  param("gamma", [](DeformParams& p) { p.gamma = 1.5; });
  param("blend", [](DeformParams& p) { p.blend = 0.25; });
  param("Local variant", [](DeformParams& p) { p.blend = 1.0; });
  param("Traction fix", [](DeformParams& p) { p.tractionCorrection = !p.tractionCorrection; });
  expectOneUndoableStep("Method", [&] {
    setMethod(state, methods::green());
    commitEdit(state, "Method");
  });

  state.input.selection.setIndices({0, 1, 2, 3});
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (ClearKind kind : {ClearKind::Location, ClearKind::Rotation, ClearKind::Scale}) {
    Eigen::MatrixXd p = state.document.pose;  // rotate, scale and move the four handles: every clear has work to do
    for (int i : {0, 1, 2, 3})
      p.row(i) = (2.0 * turn * p.row(i).transpose()).transpose() + Eigen::RowVector3d(0.1, 0.2, 0);
    setPose(state, p);
    commitEdit(state, "Grab");
    expectOneUndoableStep(clearKindName(kind), [&] {
      setPose(state, clearTransform(kind, rest, state.document.pose, state.input.selection.indices()));
      commitEdit(state, clearKindName(kind));
    });
  }

  const std::string posedPath = ::testing::TempDir() + "somicage_history_posed.obj";
  saveObj(posedPath, moved(-0.3), cageTopology(state.model.scene->restCage));
  expectOneUndoableStep("Load posed cage", [&] {
    ASSERT_TRUE(loadPosedCage(state, posedPath));
    waitUntilDone(state.jobs.posedCage);  // read on its job, applied by the poll
    ASSERT_TRUE(pollPosedCage(state));
  });
  EXPECT_LT((state.document.pose - moved(-0.3)).cwiseAbs().maxCoeff(), 1e-9);
  std::filesystem::remove(posedPath);
}

TEST_F(DocumentCommands, JumpingInTheHistoryRestoresThatStep) {
  setPose(state, moved(0.2));
  commitEdit(state, "Grab");
  DeformParams p = state.document.params;
  p.nu = 0.25;
  setParams(state, p);
  commitEdit(state, "nu");
  resetPose(state);
  ASSERT_EQ(state.document.history.size(), 4u);
  jumpToStep(state, 1);
  EXPECT_EQ(state.document.pose, moved(0.2));
  EXPECT_EQ(state.document.params.nu, 0.0);
  jumpToStep(state, 0);
  EXPECT_EQ(state.document.pose, rest);
  jumpToStep(state, 3);
  EXPECT_EQ(state.document.pose, rest);
  EXPECT_EQ(state.document.params.nu, 0.25);
  jumpToStep(state, 2);
  EXPECT_EQ(state.document.pose, moved(0.2));
  EXPECT_EQ(state.document.params.nu, 0.25);
}

TEST_F(DocumentCommands, NoChangeMakesNoStepAndUndoAtTheStartSaysSo) {
  resetPose(state);  // already at rest
  EXPECT_EQ(state.document.history.size(), 1u);
  EXPECT_EQ(state.status.message, "the pose is at rest already");
  undo(state);
  EXPECT_EQ(state.status.message, "nothing to undo");
}

TEST_F(DocumentCommands, TitleShowsTheDocumentAndAStarWhenUnsaved) {
  EXPECT_EQ(windowTitle(state), state.model.scene->name + " - SomiCage");
  setPose(state, moved(0.2));
  commitEdit(state, "Grab");
  EXPECT_EQ(windowTitle(state), state.model.scene->name + "* - SomiCage");
  const std::string path = ::testing::TempDir() + "somicage_title_session.json";
  ASSERT_TRUE(saveSessionFile(state, path));
  EXPECT_EQ(windowTitle(state), "somicage_title_session - SomiCage");
  undo(state);
  EXPECT_EQ(windowTitle(state), "somicage_title_session* - SomiCage");
  std::filesystem::remove(path);
}
