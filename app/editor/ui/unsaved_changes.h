// "Save changes before ...?" Actions that would discard the document (quit, close the window, New, Open, a
// demo, a session, a recent or dropped file; and work begun before the document changed, asked about again: a
// session whose file was read, pollSessionRead, and a scene that has loaded, pollWorker) go through guardUnsaved:
// with no unsaved changes they run at once; otherwise the editor asks Save / Don't save / Cancel (drawn by
// panels.cpp) and answerUnsaved carries out the answer. Save writes the session to its file, or opens the Save session
// dialog first and runs the action once that save succeeded. One question at a time: an action guarded while one is
// open (or its Save dialog) is refused with a status message, not put in its place. The quit action only sets
// quitRequested: the frame loop removes the autosave after it ends, i.e. only after the user's choice has been carried
// out, never on Cancel. Pure logic, no GL.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace somicage::editor {

struct AppState;

struct DiscardingAction {
  std::string what;  // "quit", "open the 3D demo", ... (for the question)
  std::function<void(AppState&)> run;
  // Runs instead when the action is dropped: Cancel, the Save session dialog cancelled, the save failed, or refused
  // because another question was open. Empty: nothing to undo (the action had not begun).
  std::function<void(AppState&)> dropped;
};

struct UnsavedPrompt {
  std::optional<DiscardingAction> asking;     // the question is shown
  std::optional<DiscardingAction> afterSave;  // runs once the Save session dialog has saved
};

enum class UnsavedChoice { Save, DontSave, Cancel };

void guardUnsaved(AppState& state, std::string what, std::function<void(AppState&)> run,
                  std::function<void(AppState&)> dropped = {});
void answerUnsaved(AppState& state, UnsavedChoice choice);
// The Save session dialog finished: saved (the session is on disk now) or cancelled.
void sessionDialogFinished(AppState& state, bool saved);

// Work begun at the history's revision `from` (History::revision()) that would now replace the document: it asks again
// only when the document changed since (an edit, undo, redo) and is unsaved; what was unsaved before was asked about.
bool changedSince(const AppState& state, std::uint64_t from);
// Such work, finished, waits while the document is busy: a question is open (or its Save session dialog), or a live edit
// is under way (a handle or G / R / S moving the cage, a panel's widget held): committed when it ends, it then counts.
bool documentBusy(const AppState& state);

// The guarded quit (Ctrl+Q, File > Quit, closing the window).
void requestQuit(AppState& state);

}  // namespace somicage::editor
