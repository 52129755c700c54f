// Mouse and keyboard in the viewports (ImGui IO, GLFW key codes): camera, selection, handle drags,
// G/R/S transforms, undo/redo, shortcuts. The math is in camera.h, selection.h and transform.h.
#pragma once

#include <vector>

#include "app_state.h"
#include "layout.h"

namespace somicage::editor {

// Call once per frame inside the ImGui frame, after the panels; ignores the mouse and keyboard while ImGui
// wants them. Draws the selection box and the transform header into the foreground draw list.
void handleInput(AppState& state, const std::vector<ViewRect>& views);

}  // namespace somicage::editor
