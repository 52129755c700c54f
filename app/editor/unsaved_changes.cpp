#include "unsaved_changes.h"

#include <utility>

#include "app_state.h"

namespace somicage::editor {

void guardUnsaved(AppState& state, std::string what, std::function<void(AppState&)> run) {
  if (!hasUnsavedChanges(state)) {
    run(state);
    return;
  }
  state.unsaved.asking = DiscardingAction{std::move(what), std::move(run)};
}

void answerUnsaved(AppState& state, UnsavedChoice choice) {
  if (!state.unsaved.asking) return;
  DiscardingAction action = std::move(*state.unsaved.asking);
  state.unsaved.asking.reset();
  switch (choice) {
    case UnsavedChoice::Cancel:
      state.statusMessage = "cancelled: " + action.what;
      return;
    case UnsavedChoice::DontSave:
      action.run(state);
      return;
    case UnsavedChoice::Save:
      if (state.documentPath.empty()) {
        state.unsaved.afterSave = std::move(action);
        openFileDialog(state, FileDialogPurpose::SaveSession);
        return;
      }
      if (saveSessionFile(state, state.documentPath)) action.run(state);
      return;
  }
}

void sessionDialogFinished(AppState& state, bool saved) {
  if (!state.unsaved.afterSave) return;
  DiscardingAction action = std::move(*state.unsaved.afterSave);
  state.unsaved.afterSave.reset();
  if (saved) action.run(state);
}

void requestQuit(AppState& state) {
  guardUnsaved(state, "quit", [](AppState& s) { s.quitRequested = true; });
}

}  // namespace somicage::editor
