#include "ui/unsaved_changes.h"

#include <utility>

#include "model/app_state.h"
#include "ui/file_dialog.h"

namespace somicage::editor {

namespace {

// Carries out the action, or, when the answer did not let it run, what it leaves to do when dropped.
void finish(AppState& state, DiscardingAction& action, bool run) {
  if (run) {
    action.run(state);
  } else if (action.dropped) {
    action.dropped(state);
  }
}

}  // namespace

void guardUnsaved(AppState& state, std::string what, std::function<void(AppState&)> run,
                  std::function<void(AppState&)> dropped) {
  const std::optional<DiscardingAction>& open =
      state.document.unsaved.asking ? state.document.unsaved.asking : state.document.unsaved.afterSave;
  if (open) {  // replacing it would drop the action the user is answering about, unseen
    state.status.message = "not done: " + what + " (finish the open question first: " + open->what + ")";
    if (dropped) dropped(state);
    return;
  }
  if (!hasUnsavedChanges(state)) {
    run(state);
    return;
  }
  state.document.unsaved.asking = DiscardingAction{std::move(what), std::move(run), std::move(dropped)};
}

void answerUnsaved(AppState& state, UnsavedChoice choice) {
  if (!state.document.unsaved.asking) return;
  DiscardingAction action = std::move(*state.document.unsaved.asking);
  state.document.unsaved.asking.reset();
  switch (choice) {
    case UnsavedChoice::Cancel:
      state.status.message = "cancelled: " + action.what;
      finish(state, action, false);
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
      finish(state, action, saveSessionFile(state, state.document.path));
      return;
  }
}

void sessionDialogFinished(AppState& state, bool saved) {
  if (!state.document.unsaved.afterSave) return;
  DiscardingAction action = std::move(*state.document.unsaved.afterSave);
  state.document.unsaved.afterSave.reset();
  finish(state, action, saved);
}

bool changedSince(const AppState& state, std::uint64_t from) {
  return state.document.history.revision() != from && hasUnsavedChanges(state);
}

bool documentBusy(const AppState& state) {
  return state.document.unsaved.asking || state.document.unsaved.afterSave || state.input.mouse.transform ||
         state.input.widgetActive;
}

void requestQuit(AppState& state) {
  guardUnsaved(state, "quit", [](AppState& s) { s.document.quitRequested = true; });
}

}  // namespace somicage::editor
