#include "ui/unsaved_changes.h"

#include <utility>

#include "model/app_state.h"
#include "ui/file_dialog.h"

namespace somicage::editor {

void guardUnsaved(AppState& state, std::string what, std::function<void(AppState&)> run) {
  if (!hasUnsavedChanges(state)) {
    run(state);
    return;
  }
  state.document.unsaved.asking = DiscardingAction{std::move(what), std::move(run)};
}

void answerUnsaved(AppState& state, UnsavedChoice choice) {
  if (!state.document.unsaved.asking) return;
  DiscardingAction action = std::move(*state.document.unsaved.asking);
  state.document.unsaved.asking.reset();
  switch (choice) {
    case UnsavedChoice::Cancel:
      state.status.message = "cancelled: " + action.what;
      return;
    case UnsavedChoice::DontSave:
      action.run(state);
      return;
    case UnsavedChoice::Save:
      if (state.document.path.empty()) {
        state.document.unsaved.afterSave = std::move(action);
        openFileDialog(state, FileDialogPurpose::SaveSession);
        return;
      }
      if (saveSessionFile(state, state.document.path)) action.run(state);
      return;
  }
}

void sessionDialogFinished(AppState& state, bool saved) {
  if (!state.document.unsaved.afterSave) return;
  DiscardingAction action = std::move(*state.document.unsaved.afterSave);
  state.document.unsaved.afterSave.reset();
  if (saved) action.run(state);
}

void requestQuit(AppState& state) {
  guardUnsaved(state, "quit", [](AppState& s) { s.document.quitRequested = true; });
}

}  // namespace somicage::editor
