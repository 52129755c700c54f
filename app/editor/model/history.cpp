#include "model/history.h"

#include <utility>

namespace somicage::editor {

void History::reset(Document original, std::string name, bool clean) {
  steps_.clear();
  steps_.push_back({std::move(name), std::move(original)});
  cursor_ = 0;
  saved_.reset();
  if (clean) saved_ = 0;
  ++revision_;
}

bool History::commit(const std::string& name, Document after) {
  if (steps_.empty()) {
    reset(std::move(after), name, true);
    return false;
  }
  if (after == steps_[cursor_].state) return false;
  steps_.resize(cursor_ + 1);  // the redo steps go
  if (saved_ && *saved_ > cursor_) saved_.reset();
  steps_.push_back({name, std::move(after)});
  ++cursor_;
  ++revision_;
  if (steps_.size() > capacity_) {
    steps_.erase(steps_.begin());
    --cursor_;
    if (saved_) saved_ = *saved_ == 0 ? std::optional<std::size_t>() : std::optional<std::size_t>(*saved_ - 1);
  }
  return true;
}

const Document& History::undo() {
  ++revision_;
  return steps_[--cursor_].state;
}
const Document& History::redo() {
  ++revision_;
  return steps_[++cursor_].state;
}
const Document& History::jumpTo(std::size_t index) {
  if (index != cursor_) ++revision_;
  cursor_ = index;
  return steps_[cursor_].state;
}

}  // namespace somicage::editor
