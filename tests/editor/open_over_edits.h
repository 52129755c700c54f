// What the tests of opening another document over the open one share (editor_session_open_test.cpp: a session read;
// editor_scene_open_test.cpp: a scene loaded): the edited document opened over, one more edit, what a cancelled open
// must keep exactly, the frame loop's polls, and cores held so that a load waits for them.
#pragma once

#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "editor_test_support.h"
#include "interaction/transform.h"
#include "jobs/thread_budget.h"
#include "model/app_state.h"
#include "model/pose_keys.h"

namespace somicage::editor {

// The document open before: the 2D demo with edits (a parameter, a moved vertex, a stored pose), unsaved.
inline void openEditedDemo(AppState& state) {
  openDemoScene(state, 2);
  DeformParams params = state.document.params;
  params.gamma = 0.5;
  setParams(state, params);
  Eigen::MatrixXd pose = state.document.pose;
  pose(0, 0) -= 0.25;
  setPose(state, pose);
  commitEdit(state, "Grab");
  storeCurrentPose(state, "mine");
  ASSERT_TRUE(hasUnsavedChanges(state));
}

// One edit of the open document as the user makes it: a vertex moved, committed as "Grab".
inline void grab(AppState& state) {
  Eigen::MatrixXd pose = state.document.pose;
  pose(1, 0) += 0.125;
  setPose(state, pose);
  ASSERT_TRUE(commitEdit(state, "Grab"));
}

// Live edits under way, not committed yet: G on vertex 1 moving the cage by 0.125 in x (returns the pose before it),
// and the nu slider held at 0.125. Their ends: Enter commits the move or Esc puts the pose back; the slider's release
// commits its value (IsItemDeactivatedAfterEdit).
inline Eigen::MatrixXd beginGrab(AppState& state) {
  const Eigen::MatrixXd original = state.document.pose;
  state.input.mouse.mode = Interaction::Mode::Modal;
  state.input.mouse.transform =
      beginTransform(TransformKind::Grab, {1}, original, Eigen::Vector2d(10, 10), Eigen::Vector2d(100, 100));
  Eigen::MatrixXd moved = original;
  moved(1, 0) += 0.125;
  setPose(state, moved);
  return original;
}

inline void endGrab(AppState& state, const Eigen::MatrixXd& original, bool confirmed) {
  if (confirmed) {
    EXPECT_TRUE(commitEdit(state, "Grab"));  // Enter (confirmTransform)
  } else {
    setPose(state, original);  // Esc (cancelTransform)
  }
  state.input.mouse.transform.reset();
  state.input.mouse.mode = Interaction::Mode::Idle;
}

inline void holdNuSlider(AppState& state) {
  state.input.widgetActive = true;
  DeformParams params = state.document.params;
  params.nu = 0.125;
  setParams(state, params);
}

inline void releaseNuSlider(AppState& state) {
  EXPECT_EQ(state.document.params.nu, 0.125) << "the slider's value was replaced under the user's hand";
  EXPECT_TRUE(commitEdit(state, "nu"));
  state.input.widgetActive = false;
}

// What the user does to the open document while another one opens.
struct Meanwhile {
  std::string name;
  std::function<void(AppState&)> make;
  bool edited = false;  // (unchanged only) the document is unsaved when the open begins: openEditedDemo
};

// Changes to ask about again: an edit, an undo, an undo and its redo (the state the user agreed to discard may be
// back, but its redo step is the user's work).
inline std::vector<Meanwhile> changesMeanwhile() {
  return {{"an edit", [](AppState& s) { grab(s); }},
          {"an undo", [](AppState& s) { undo(s); }},
          {"an undo and its redo", [](AppState& s) {
             undo(s);
             redo(s);
           }}};
}

// No change to ask about: over a clean document; over an unsaved one whose user answered Don't save before (what was
// unsaved then was asked about), with a commit that changed nothing; an edit saved meanwhile (to `saved`: on disk).
inline std::vector<Meanwhile> noChangeMeanwhile(const std::string& saved) {
  return {{"clean", [](AppState&) {}, false},
          {"unsaved, answered Don't save", [](AppState& s) { EXPECT_FALSE(commitEdit(s, "Grab")); }, true},
          {"an edit saved meanwhile", [saved](AppState& s) {
             grab(s);
             ASSERT_TRUE(saveSessionFile(s, saved));
           }, true}};
}

// The document `meanwhile` starts from: edited (openEditedDemo) or the 2D demo as opened.
inline void openDocumentFor(AppState& state, const Meanwhile& meanwhile) {
  if (meanwhile.edited) {
    openEditedDemo(state);
  } else {
    openDemoScene(state, 2);
  }
}

// What a cancelled or failed open must leave as it was: the scene, its deformers, the document and its history, the
// views.
struct Kept {
  std::shared_ptr<const Scene> scene;
  DeformerSet deformers;
  Document document;
  std::size_t steps = 0, cursor = 0;
  std::string path;
  std::vector<ViewSpec> views;
};

inline Kept keep(const AppState& state) {
  return {state.model.scene,
          state.model.deformers,
          currentDocument(state),
          state.document.history.size(),
          state.document.history.cursor(),
          state.document.path,
          state.views()};
}

inline void expectKept(const AppState& state, const Kept& kept) {
  EXPECT_EQ(state.model.scene, kept.scene);
  EXPECT_EQ(state.model.deformers, kept.deformers);
  EXPECT_TRUE(currentDocument(state) == kept.document) << "the open document changed";
  EXPECT_EQ(state.document.history.size(), kept.steps);
  EXPECT_EQ(state.document.history.cursor(), kept.cursor);
  EXPECT_EQ(state.document.path, kept.path);
  EXPECT_TRUE(state.views() == kept.views) << "the views changed";
  EXPECT_TRUE(hasUnsavedChanges(state));
}

// What the frame loop polls each frame (editor.cpp, frame()): the scene's load, then the session read.
inline void frame(AppState& state) {
  pollWorker(state);
  pollSessionRead(state);
}

// Every core of the machine's budget, held by the test: a job started meanwhile waits for its cores.
struct HeldCores {
  ThreadBudget::Lease lease;
  std::atomic<bool> stop{false};
  HeldCores() { ThreadBudget::machine().acquire(lease, ThreadBudget::machine().cores(), stop); }
  ~HeldCores() { ThreadBudget::machine().release(lease); }
  HeldCores(const HeldCores&) = delete;
  HeldCores& operator=(const HeldCores&) = delete;
};

}  // namespace somicage::editor
