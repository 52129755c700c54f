#include "history.h"

#include <utility>

namespace somicage::editor {

void UndoHistory::record(EditSnapshot before) {
  undo_.push_back(std::move(before));
  while (undo_.size() > capacity_) undo_.pop_front();
  redo_.clear();
}

EditSnapshot UndoHistory::undo(EditSnapshot current) {
  EditSnapshot previous = std::move(undo_.back());
  undo_.pop_back();
  current.label = previous.label;
  redo_.push_back(std::move(current));
  return previous;
}

EditSnapshot UndoHistory::redo(EditSnapshot current) {
  EditSnapshot next = std::move(redo_.back());
  redo_.pop_back();
  current.label = next.label;
  undo_.push_back(std::move(current));
  return next;
}

void UndoHistory::clear() {
  undo_.clear();
  redo_.clear();
}

}  // namespace somicage::editor
