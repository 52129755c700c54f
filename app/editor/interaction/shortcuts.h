// The editor's commands that have a key: one table (a descriptor per command) used by the keyboard handler
// (input.cpp), the menus (their shortcut labels) and the F1 shortcut sheet. The viewport keys that need the mouse
// and the views (G / R / S, X / Y / Z, A, F, 1 / 2 / 3) are handled by input.cpp and listed here without an
// action, so that the sheet names every key. Pure logic apart from the GLFW key codes.
#pragma once

#include <vector>

namespace somicage::editor {

struct AppState;

enum ShortcutMods { kNoMods = 0, kShift = 1, kCtrl = 2, kAlt = 4 };  // the GLFW_MOD_* bits

struct Shortcut {
  const char* id;          // "save": what the menus ask for (shortcutLabel)
  int key;                 // GLFW_KEY_*
  int mods;                // ShortcutMods bits that must be held (exactly)
  const char* keys;        // "Ctrl+S"
  const char* what;        // "Save the session (asks for a file the first time)"
  void (*run)(AppState&);  // null: handled by input.cpp (needs the views)
};

const std::vector<Shortcut>& shortcuts();
// The command bound to key + exactly these mods, or null.
const Shortcut* findShortcut(int key, int mods);
// The key label of a command id ("Ctrl+S"), or null.
const char* shortcutLabel(const char* id);
// Runs a command by id (the menu items).
void runCommand(AppState& state, const char* id);

// Commands shared by keys and menus.
void saveDocument(AppState& state);      // Ctrl+S: to the session file, or Save as the first time
void newDocument(AppState& state);       // Ctrl+N: the 3D demo (asks about unsaved changes)
void cancelPrecompute(AppState& state);  // Esc: stops a session being read, else the precompute (no-op when idle)

}  // namespace somicage::editor
