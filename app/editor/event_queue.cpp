#include "event_queue.h"

#include <algorithm>
#include <utility>

namespace somicage::editor {

std::vector<InputEvent> InputEventQueue::takeFrame() {
  std::vector<InputEvent> frame;
  std::vector<std::pair<InputEvent::Type, int>> changed;  // keys and buttons this frame already changed
  bool pressed = false;
  while (!events_.empty()) {
    const InputEvent& e = events_.front();
    const bool transition = e.type == InputEvent::Type::Key || e.type == InputEvent::Type::MouseButton;
    if (transition) {
      const std::pair<InputEvent::Type, int> id{e.type, e.code};
      if (std::find(changed.begin(), changed.end(), id) != changed.end()) break;
      // A release after a press waits for the next frame: `xdotool key ctrl+s` releases Ctrl before S, and S must
      // be seen with Ctrl still held.
      if (e.action == 0 && pressed) break;
      pressed |= e.action != 0;
      changed.push_back(id);
    }
    frame.push_back(e);
    events_.pop_front();
  }
  return frame;
}

}  // namespace somicage::editor
