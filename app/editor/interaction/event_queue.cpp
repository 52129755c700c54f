#include "interaction/event_queue.h"

#include <algorithm>
#include <utility>

namespace somicage::editor {

namespace {

// GLFW_MOD_CONTROL, GLFW_MOD_ALT and GLFW_MOD_SUPER: a printable key held with one is a shortcut, not text.
constexpr int kShortcutMods = 0x0002 | 0x0004 | 0x0008;

// GLFW's printable keys (GLFW_KEY_SPACE (32) to GLFW_KEY_WORLD_2 (162)) typed as text, without Ctrl, Alt or Super.
// Ctrl+A in a text field is a key state ImGui reads (select all): it must get its own frames like any chord, or its
// press and release cancel out (issue 24, row 6: Ctrl+A after clicking into a path field did not select).
bool printable(const InputEvent& e) {
  return e.type == InputEvent::Type::Key && e.code >= 32 && e.code <= 162 && (e.mods & kShortcutMods) == 0;
}

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
