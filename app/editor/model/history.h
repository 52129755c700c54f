// Undo history as in Blender: a list of document states, each named by the command that produced it, and a
// cursor on the current one. Undo / redo move the cursor by one step; the Undo History panel jumps to any step.
// A command commits the state it produced (after-state); the state before it is the step below. Whole
// snapshots: a cage has tens to hundreds of vertices, so they are cheap, exact and simple. Pure, no GL.
//
// The history also knows which step was last saved, so "unsaved changes" is "the cursor is not on the saved
// step" (undoing back to the saved state makes the document clean again, as in Blender and most editors).
//
// Its revision counts the changes of the current state (each commit, undo, redo, jump or reset), so that work begun
// at one state can tell whether the user changed the document since (a session being read: pollSessionRead).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/document.h"

namespace somicage::editor {

struct HistoryStep {
  std::string name;  // the command that produced this state ("Grab", "Reset pose", "nu", ...); "Original" first
  Document state;
};

class History {
 public:
  explicit History(std::size_t capacity = 256) : capacity_(capacity < 2 ? 2 : capacity) {}

  // Starts a new history whose only step is `original` (a scene was loaded). `clean`: nothing is lost by
  // discarding that state (a session just opened, a scene opened from its files, a demo); false for a state that
  // exists nowhere else (a crashed run's restored autosave).
  void reset(Document original, std::string name, bool clean);

  // Records the state a command produced. Returns false (no step) when it equals the current state (or the
  // history is empty: then it becomes the original). Drops the redo steps, and the oldest step beyond the
  // capacity.
  bool commit(const std::string& name, Document after);

  bool empty() const { return steps_.empty(); }
  bool canUndo() const { return cursor_ > 0; }
  bool canRedo() const { return cursor_ + 1 < steps_.size(); }
  // Move the cursor and return the state to restore. Call only when canUndo() / canRedo() / index < size().
  const Document& undo();
  const Document& redo();
  const Document& jumpTo(std::size_t index);

  std::size_t size() const { return steps_.size(); }
  std::size_t cursor() const { return cursor_; }
  const HistoryStep& step(std::size_t index) const { return steps_[index]; }
  const Document& current() const { return steps_[cursor_].state; }
  // Bumps whenever the current state changes: a commit that adds a step, undo, redo, a jump, a reset. An undo and
  // its redo are two changes (the state is the same again, but the step undone could have been another's redo).
  std::uint64_t revision() const { return revision_; }

  // The current step is what is on disk now.
  void markSaved() { saved_ = cursor_; }
  // True when the current state differs from the saved one (or nothing was ever saved and the document changed
  // since it was opened, or the saved step was dropped).
  bool unsaved() const { return !steps_.empty() && saved_ != cursor_; }

 private:
  std::size_t capacity_;
  std::vector<HistoryStep> steps_;
  std::size_t cursor_ = 0;
  std::optional<std::size_t> saved_;  // none: the saved state is no step of this history
  std::uint64_t revision_ = 0;
};

}  // namespace somicage::editor
