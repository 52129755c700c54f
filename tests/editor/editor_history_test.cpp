// Undo/redo of snapshots, and the AppState edit functions that use it.
#include <gtest/gtest.h>

#include "app_state.h"
#include "history.h"

using namespace somicage;
using namespace somicage::editor;

namespace {
EditSnapshot snap(double x, const std::string& label = "") {
  EditSnapshot s;
  s.pose = Eigen::MatrixXd::Constant(2, 3, x);
  s.label = label;
  return s;
}
}  // namespace

TEST(EditorHistory, UndoRedoWalksBackAndForth) {
  UndoHistory h;
  EditSnapshot current = snap(0);
  for (double x : {1.0, 2.0, 3.0}) {
    h.record(current);
    current = snap(x, "move");
  }
  current = h.undo(current);
  EXPECT_EQ(current.pose(0, 0), 2.0);
  current = h.undo(current);
  EXPECT_EQ(current.pose(0, 0), 1.0);
  current = h.redo(current);
  EXPECT_EQ(current.pose(0, 0), 2.0);
  EXPECT_TRUE(h.canUndo());
  EXPECT_TRUE(h.canRedo());
}

TEST(EditorHistory, NewEditClearsRedo) {
  UndoHistory h;
  h.record(snap(0));
  EditSnapshot current = h.undo(snap(1));
  EXPECT_TRUE(h.canRedo());
  h.record(current);
  EXPECT_FALSE(h.canRedo());
}

TEST(EditorHistory, CapacityDropsTheOldest) {
  UndoHistory h(3);
  for (int i = 0; i < 10; ++i) h.record(snap(i));
  EXPECT_EQ(h.undoCount(), 3u);
  EXPECT_EQ(h.undo(snap(10)).pose(0, 0), 9.0);
}

TEST(EditorHistory, AppStateUndoRestoresPoseAndParams) {
  AppState state;
  state.scene = std::make_shared<const Scene>(makeDemoScene(3));
  state.pose = state.scene->restCage.vertices;
  const Eigen::MatrixXd rest = state.pose;

  recordEdit(state, "Grab");
  Eigen::MatrixXd moved = rest;
  moved(0, 0) += 0.5;
  setPose(state, moved);
  recordEdit(state, "nu");
  DeformParams p = state.params;
  p.nu = 0.3;
  setParams(state, p);
  resetPose(state);
  EXPECT_EQ(state.pose, rest);

  undo(state);  // reset
  EXPECT_EQ(state.pose, moved);
  EXPECT_EQ(state.params.nu, 0.3);
  undo(state);  // nu
  EXPECT_EQ(state.params.nu, 0.0);
  EXPECT_EQ(state.pose, moved);
  undo(state);  // grab
  EXPECT_EQ(state.pose, rest);
  EXPECT_FALSE(state.history.canUndo());
  redo(state);
  redo(state);
  EXPECT_EQ(state.pose, moved);
  EXPECT_EQ(state.params.nu, 0.3);
}
