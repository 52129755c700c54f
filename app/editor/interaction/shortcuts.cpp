#include "interaction/shortcuts.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstring>

#include "model/app_state.h"
#include "model/pose_keys.h"
#include "ui/file_dialog.h"
#include "ui/screenshot.h"
#include "ui/unsaved_changes.h"

namespace somicage::editor {

void saveDocument(AppState& state) {
  if (state.document.path.empty()) {
    openFileDialog(state, FileDialogPurpose::SaveSession);
  } else {
    saveSessionFile(state, state.document.path);
  }
}

void cancelPrecompute(AppState& state) {
  if (state.jobs.session.busy()) {  // a session being read: the open document stays
    state.jobs.session.cancel();
    state.status.message = "cancelling opening the session...";
    return;
  }
  if (!state.jobs.precompute.busy()) return;
  state.jobs.precompute.cancel();  // the worker stops at its next progress report; the outcome says "cancelled"
  state.status.message = "cancelling the precomputation...";
}

void newDocument(AppState& state) {
  guardUnsaved(state, "start a new document (the 3D demo)", [](AppState& s) { requestDemo(s, 3); });
}

const std::vector<Shortcut>& shortcuts() {
  static const std::vector<Shortcut> kTable = {
      {"new", GLFW_KEY_N, kCtrl, "Ctrl+N", "New: the 3D demo (asks about unsaved changes)", newDocument},
      {"open", GLFW_KEY_O, kCtrl, "Ctrl+O", "Open a mesh and its cage",
       [](AppState& s) { openFileDialog(s, FileDialogPurpose::OpenScene); }},
      {"open_session", GLFW_KEY_O, kCtrl | kShift, "Ctrl+Shift+O", "Open a session",
       [](AppState& s) { openFileDialog(s, FileDialogPurpose::OpenSession); }},
      {"save", GLFW_KEY_S, kCtrl, "Ctrl+S", "Save the session (asks for a file the first time)", saveDocument},
      {"save_as", GLFW_KEY_S, kCtrl | kShift, "Ctrl+Shift+S", "Save the session as a new file",
       [](AppState& s) { openFileDialog(s, FileDialogPurpose::SaveSession); }},
      {"export", GLFW_KEY_E, kCtrl, "Ctrl+E", "Export the deformed mesh (.obj)",
       [](AppState& s) { openFileDialog(s, FileDialogPurpose::ExportMesh); }},
      {"undo", GLFW_KEY_Z, kCtrl, "Ctrl+Z", "Undo", undo},
      {"redo", GLFW_KEY_Z, kCtrl | kShift, "Ctrl+Shift+Z", "Redo", redo},
      {"redo_y", GLFW_KEY_Y, kCtrl, "Ctrl+Y", "Redo", redo},
      {"history", GLFW_KEY_H, kCtrl, "Ctrl+H", "Show the Undo History",
       [](AppState& s) { s.view.showHistoryPanel = !s.view.showHistoryPanel; }},
      {"quit", GLFW_KEY_Q, kCtrl, "Ctrl+Q", "Quit (asks about unsaved changes)", requestQuit},
      {"shortcuts", GLFW_KEY_F1, kNoMods, "F1", "This sheet of shortcuts",
       [](AppState& s) { s.view.showShortcuts = !s.view.showShortcuts; }},
      {"screenshot", GLFW_KEY_F12, kNoMods, "F12", "Screenshot into the current folder",
       [](AppState& s) { s.view.screenshotRequest = defaultScreenshotName(); }},
      {"frame", GLFW_KEY_F, kNoMods, "F", "Frame everything (posed cage included)", frameAll},
      {"cancel", GLFW_KEY_ESCAPE, kNoMods, "Esc",
       "Cancel the running precomputation (a session, a scene or a method loading); the current scene stays",
       cancelPrecompute},
      {"play", GLFW_KEY_SPACE, kNoMods, "Space", "Play the timeline from the cursor, or stop", togglePlayback},
      {"reset_pose", GLFW_KEY_R, kAlt | kShift, "Alt+Shift+R", "Reset pose: every handle back to rest", resetPose},
      {"grab", GLFW_KEY_G, kNoMods, "G", "Grab the selection; then X/Y/Z, a typed value, Enter", nullptr},
      {"rotate", GLFW_KEY_R, kNoMods, "R", "Rotate the selection; then X/Y/Z, degrees, Enter", nullptr},
      {"scale", GLFW_KEY_S, kNoMods, "S", "Scale the selection; then X/Y/Z, a factor, Enter", nullptr},
      {"clear_location", GLFW_KEY_G, kAlt, "Alt+G", "Selected handles: location back to rest", nullptr},
      {"clear_rotation", GLFW_KEY_R, kAlt, "Alt+R", "Selected handles: rotation back to rest", nullptr},
      {"clear_scale", GLFW_KEY_S, kAlt, "Alt+S", "Selected handles: scale back to rest", nullptr},
      {"pick_vertices", GLFW_KEY_1, kNoMods, "1", "A click selects vertices (cage handles)", nullptr},
      {"pick_edges", GLFW_KEY_2, kNoMods, "2", "A click selects an edge's two vertices", nullptr},
      {"pick_faces", GLFW_KEY_3, kNoMods, "3", "A click selects a face's vertices", nullptr},
      {"select_all", GLFW_KEY_A, kNoMods, "A", "Select all handles", nullptr},
      {"select_none", GLFW_KEY_A, kAlt, "Alt+A", "Select none", nullptr},
      {"delete", GLFW_KEY_DELETE, kNoMods, "Delete", "Nothing to delete: cage vertices cannot be removed here",
       [](AppState& s) { s.status.message = "Delete: a cage keeps all its vertices (nothing deleted)"; }},
  };
  return kTable;
}

const Shortcut* findShortcut(int key, int mods) {
  mods &= kShift | kCtrl | kAlt;
  for (const Shortcut& s : shortcuts()) {
    if (s.key == key && s.mods == mods) return &s;
  }
  return nullptr;
}

const char* shortcutLabel(const char* id) {
  for (const Shortcut& s : shortcuts()) {
    if (std::strcmp(s.id, id) == 0) return s.keys;
  }
  return nullptr;
}

void runCommand(AppState& state, const char* id) {
  for (const Shortcut& s : shortcuts()) {
    if (std::strcmp(s.id, id) == 0 && s.run) s.run(state);
  }
}

}  // namespace somicage::editor
