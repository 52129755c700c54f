#include "event_queue.h"

#include <algorithm>
#include <utility>

namespace somicage::editor {

namespace {

// GLFW's printable keys: GLFW_KEY_SPACE (32) to GLFW_KEY_WORLD_2 (162).
bool printable(const InputEvent& e) { return e.type == InputEvent::Type::Key && e.code >= 32 && e.code <= 162; }

}  // namespace

std::vector<InputEvent> InputEventQueue::takeFrame(bool typing) {
  std::vector<InputEvent> frame;
  std::vector<std::pair<InputEvent::Type, int>> changed;  // keys and buttons this frame already changed
  bool pressed = false;
  while (!events_.empty()) {
    const InputEvent& e = events_.front();
    const bool transition =
        (e.type == InputEvent::Type::Key || e.type == InputEvent::Type::MouseButton) && !(typing && printable(e));
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
