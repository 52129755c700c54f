// Mouse and keyboard in the viewports (ImGui IO, GLFW key codes): camera, selection, handle drags,
// G/R/S transforms, undo/redo, shortcuts. The math is in camera.h, selection.h and transform.h.
#pragma once

#include <string>
#include <vector>

#include "model/app_state.h"
#include "ui/layout.h"

namespace somicage::editor {

// Call once per frame inside the ImGui frame, after the panels; ignores the mouse and keyboard while ImGui
// wants them. Draws the selection box and the transform header into the foreground draw list.
void handleInput(AppState& state, const std::vector<ViewRect>& views);

// The header over the view while a transform runs ("Grab X: (0.5, 0, 0)" and, for G / R / S, the keys it takes): for
// G / R / S and for a drag of a handle or the gizmo once it has moved; "" otherwise. Inside an ImGui frame.
std::string transformHeader(const AppState& state, const std::vector<ViewRect>& views);

}  // namespace somicage::editor
