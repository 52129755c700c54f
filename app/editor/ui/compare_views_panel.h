// The compare view's list of views in the control panel (ImGui 1.86): per pane its method and, with "own nu", its
// own nu (the other parameters follow the panel's sliders); "+ view" adds a pane (at most kMaxCompareViews), "x"
// removes one (at least two stay). A view setting, like the compare checkbox: not an edit, not undone.
#pragma once

#include "model/app_state.h"

namespace somicage::editor {

void drawCompareViews(AppState& state);

}  // namespace somicage::editor
