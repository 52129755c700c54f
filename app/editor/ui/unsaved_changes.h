// "Save changes before ...?" Actions that would discard the document (quit, close the window, New, Open, a
// demo, a session, a recent or dropped file, and a session whose file was read while the document changed:
// pollSessionRead) go through guardUnsaved: with no unsaved changes they run at once; otherwise the editor asks
// Save / Don't save / Cancel (drawn by panels.cpp) and answerUnsaved carries out the answer. Save writes the session to its file, or opens the Save session dialog first and runs the action once
// that save succeeded. The quit action only sets quitRequested: the frame loop removes the autosave after it ends,
// i.e. only after the user's choice has been carried out, never on Cancel. Pure logic, no GL.
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace somicage::editor {

struct AppState;

struct DiscardingAction {
  std::string what;  // "quit", "open the 3D demo", ... (for the question)
  std::function<void(AppState&)> run;
};

struct UnsavedPrompt {
  std::optional<DiscardingAction> asking;     // the question is shown
  std::optional<DiscardingAction> afterSave;  // runs once the Save session dialog has saved
};

enum class UnsavedChoice { Save, DontSave, Cancel };

void guardUnsaved(AppState& state, std::string what, std::function<void(AppState&)> run);
void answerUnsaved(AppState& state, UnsavedChoice choice);
// The Save session dialog finished: saved (the session is on disk now) or cancelled.
void sessionDialogFinished(AppState& state, bool saved);

// The guarded quit (Ctrl+Q, File > Quit, closing the window).
void requestQuit(AppState& state);

}  // namespace somicage::editor
