// Undo/redo of edits as snapshots of the edited state (the posed cage, the deformation parameters, the pose
// library and the timeline's keys).
// Pure, no GL. A cage has tens to hundreds of vertices, so whole snapshots are cheap and simple.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <deque>
#include <string>

#include "deformer.h"
#include "pose_timeline.h"

namespace somicage::editor {

struct EditSnapshot {
  Eigen::MatrixXd pose;  // #V by d posed cage vertices
  DeformParams params;
  PoseLibrary poses;  // the pose library and the keys are edits too
  Timeline timeline;
  std::string label;  // what the edit that followed this snapshot did ("Grab", "nu", ...)
};

class UndoHistory {
 public:
  explicit UndoHistory(std::size_t capacity = 256) : capacity_(capacity) {}

  // Call with the state *before* an edit; clears the redo stack.
  void record(EditSnapshot before);
  bool canUndo() const { return !undo_.empty(); }
  bool canRedo() const { return !redo_.empty(); }
  // Returns the state to restore; `current` goes onto the other stack. Call only when canUndo()/canRedo().
  EditSnapshot undo(EditSnapshot current);
  EditSnapshot redo(EditSnapshot current);
  void clear();
  std::size_t undoCount() const { return undo_.size(); }
  std::size_t redoCount() const { return redo_.size(); }
  const std::string& nextUndoLabel() const { return undo_.back().label; }
  const std::string& nextRedoLabel() const { return redo_.back().label; }

 private:
  std::size_t capacity_;
  std::deque<EditSnapshot> undo_, redo_;
};

}  // namespace somicage::editor
