// The File > Make cage... dialog (ImGui 1.86) over CageMaker (cage_maker.h): face-count and margin sliders that
// regenerate the preview as they move, the generation's progress with Stop, the candidate's numbers, Accept and
// Cancel. The preview itself is drawn by the renderer (editor_renderer.h).
#pragma once

#include "model/app_state.h"

namespace somicage::editor {

void drawCageMakerDialog(AppState& state);

}  // namespace somicage::editor
