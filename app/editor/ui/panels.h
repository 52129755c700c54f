// The ImGui panels, each a function of AppState& (ImGui 1.86). They only read and edit the state; the frame
// loop (editor.cpp) acts on the requests they leave in it (screenshots, quitting).
#pragma once

#include <string>
#include <vector>

#include "model/app_state.h"
#include "ui/layout.h"

namespace somicage::editor {

// Width of the control panel in a window this wide: 340 pixels, narrower in small windows so that the views keep
// more than half (640 x 400 stays usable).
double panelWidth(double windowWidth);

// The tooltip of the last widget, shown also when it is disabled (then it says why).
void tooltip(const char* text);

// Heights in pixels of the main menu bar and the status bar (valid inside a frame).
double menuBarHeight();
double statusBarHeight();

void drawMainMenu(AppState& state);
void drawControlPanel(AppState& state);
// The status bar's line: the last message, then the statistics (mesh, cage, timings, the device); hovering the bar
// shows the whole message.
std::string statusBarText(const AppState& state);
void drawStatusBar(AppState& state);
void drawViewLabels(const AppState& state, const std::vector<ViewRect>& views);
// Edit > Undo History: every step, the current one highlighted; a click jumps there.
void drawHistoryPanel(AppState& state);
// Save / Don't save / Cancel while state.unsaved.asking (unsaved_changes.h).
void drawUnsavedModal(AppState& state);
// F1: every shortcut (shortcuts.h).
void drawShortcutSheet(AppState& state);
void drawErrorModal(AppState& state);
// "Restore the session from <time>?" Restore / Discard, while state.restoreOffer holds a crashed run's session.
void drawRestoreModal(AppState& state);

}  // namespace somicage::editor
