// Keyboard, character, mouse-button and scroll events from the GLFW callbacks, kept in order until the frame
// loop hands them to Dear ImGui. ImGui 1.86 keeps one state per key and button per frame, so a press and its
// release inside one frame would cancel out (a quick tap at 8 FPS was lost 7 times in 8). takeFrame() gives each
// frame the events up to, not including, the first one that would change a key or button a second time, or
// release one after a press (a chord's modifier released before its key): a tap then spans two frames and always
// acts, with the modifiers it was typed with, at any frame rate, in the order typed. Pure, no GLFW calls.
#pragma once

#include <cstddef>
#include <deque>
#include <vector>

namespace somicage::editor {

struct InputEvent {
  enum class Type { Key, Char, MouseButton, Scroll };
  Type type = Type::Key;
  int code = 0;               // Key: GLFW key; MouseButton: button; Char: code point
  int scancode = 0;           // Key
  int action = 0;             // Key, MouseButton: GLFW_RELEASE 0, GLFW_PRESS 1, GLFW_REPEAT 2
  int mods = 0;               // Key, MouseButton
  double dx = 0.0, dy = 0.0;  // Scroll

  static InputEvent key(int key, int scancode, int action, int mods) {
    return {Type::Key, key, scancode, action, mods, 0.0, 0.0};
  }
  static InputEvent character(unsigned codepoint) {
    return {Type::Char, static_cast<int>(codepoint), 0, 0, 0, 0.0, 0.0};
  }
  static InputEvent mouseButton(int button, int action, int mods) {
    return {Type::MouseButton, button, 0, action, mods, 0.0, 0.0};
  }
  static InputEvent scroll(double dx, double dy) { return {Type::Scroll, 0, 0, 0, 0, dx, dy}; }
};

class InputEventQueue {
 public:
  void push(const InputEvent& event) { events_.push_back(event); }
  bool empty() const { return events_.empty(); }
  std::size_t size() const { return events_.size(); }
  // This frame's events, in order (see above); the rest stay queued for the next frames. `typing`: a text field
  // has the keyboard (ImGui's WantTextInput), which reads characters, not key states: printable keys then do not
  // split frames, so typed text goes in at one frame per burst instead of two frames per letter.
  std::vector<InputEvent> takeFrame(bool typing = false);

 private:
  std::deque<InputEvent> events_;
};

}  // namespace somicage::editor
