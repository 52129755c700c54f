// The editor's pose library and timeline: each change is undoable and redoable, a failed change records nothing,
// scrubbing shows the timeline's cage (a key's pose at its frame, the linear mean between two), and sessions keep
// the library and the keys (version 1 sessions still load, with neither).
#include <gtest/gtest.h>

#include "app_state.h"
#include "pose_keys.h"
#include "session.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

void loadDemo(AppState& state) {
  state.scene = std::make_shared<const Scene>(makeDemoScene(3));
  state.pose = state.scene->restCage.vertices;
}

TEST(EditorPoseKeys, LibraryEditsAreUndoable) {
  AppState state;
  loadDemo(state);
  const Eigen::MatrixXd rest = state.pose;
  storeCurrentPose(state, "rest");
  Eigen::MatrixXd moved = rest;
  moved.row(0) += Eigen::RowVector3d(0.5, 0, 0);
  setPose(state, moved);
  storeCurrentPose(state, "moved");
  renameNamedPose(state, "moved", "reach");
  ASSERT_NE(state.animation.poses.find("reach"), nullptr);
  applyNamedPose(state, "rest");
  EXPECT_EQ(state.pose, rest);
  deleteNamedPose(state, "rest");
  EXPECT_EQ(state.animation.poses.find("rest"), nullptr);

  undo(state);  // delete
  ASSERT_NE(state.animation.poses.find("rest"), nullptr);
  undo(state);  // apply
  EXPECT_EQ(state.pose, moved);
  undo(state);  // rename
  EXPECT_NE(state.animation.poses.find("moved"), nullptr);
  EXPECT_EQ(state.animation.poses.find("reach"), nullptr);
  redo(state);
  EXPECT_NE(state.animation.poses.find("reach"), nullptr);

  const size_t undoCount = state.history.undoCount();
  renameNamedPose(state, "reach", "rest");  // taken: an error, no edit
  EXPECT_EQ(state.history.undoCount(), undoCount);
  EXPECT_EQ(state.errors.size(), 1u);
}

TEST(EditorPoseKeys, ScrubbingShowsKeysAndTheLinearMean) {
  AppState state;
  loadDemo(state);
  const Eigen::MatrixXd rest = state.pose;
  state.animation.timeline.interpolation = Interpolation::Linear;
  state.animation.frame = 0;
  keyCurrentPose(state);
  Eigen::MatrixXd moved = rest;
  moved.col(1).array() += 0.4;
  setPose(state, moved);
  state.animation.frame = 10;
  state.animation.keyParams = true;
  state.params.gamma = 2.0;
  keyCurrentPose(state);
  ASSERT_EQ(state.animation.timeline.keys.size(), 2u);

  scrubTo(state, 0);
  EXPECT_EQ(state.pose, rest);
  scrubTo(state, 5);
  EXPECT_LE((state.pose - 0.5 * (rest + moved)).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_DOUBLE_EQ(state.params.gamma, 2.0) << "the first key sets no gamma: it takes the second's";
  undo(state);  // the second key
  EXPECT_EQ(state.animation.timeline.keys.size(), 1u);
}

TEST(EditorPoseKeys, SessionsKeepPosesAndKeysAndVersion1Loads) {
  AppState state;
  loadDemo(state);
  storeCurrentPose(state, "a");
  keyCurrentPose(state);
  const Session saved = makeSession(state);
  const Session read = sessionFromJson(sessionToJson(saved), "s.json");
  ASSERT_EQ(read.poses.poses().size(), 2u);
  EXPECT_EQ(read.poses.poses()[0].vertices, state.pose);
  ASSERT_EQ(read.timeline.keys.size(), 1u);
  EXPECT_EQ(read.timeline.keys[0].pose, state.animation.timeline.keys[0].pose);

  const std::string v1 = R"({"format": "somicage-session", "version": 1, "mesh": "", "cage": "", "demoDim": 3,
    "pose": [], "method": "green", "params": {"blend": 0, "nu": 0, "gamma": 0, "tractionCorrection": true},
    "compare": false, "compareMethods": ["green"],
    "camera": {"target": [0, 0, 0], "distance": 3, "yaw": 0, "pitch": 0}})";
  const Session old = sessionFromJson(v1, "old.json");
  EXPECT_TRUE(old.poses.poses().empty());
  EXPECT_TRUE(old.timeline.keys.empty());
}

}  // namespace
