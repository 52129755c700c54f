// The Timeline panel (a band under the viewports: play / stop, loop, fps, the frame slider with the keys marked,
// interpolation, Key pose / Delete key, the export range), the Pose library panel (a window at the right of the
// viewports: the named poses with Apply, Rename and Delete, and Store current pose), and the Export animation
// dialog with its progress bar and Cancel. ImGui 1.86; every action goes through pose_keys.h.
#pragma once

#include "model/app_state.h"

namespace somicage::editor {

// Height in pixels of the timeline band (valid inside a frame); the viewports leave it free.
double timelinePanelHeight();

void drawTimelinePanel(AppState& state, double left, double bottom);
void drawPoseLibraryPanel(AppState& state, double top);
// The File > Export animation dialog (while requested) and the progress modal (while a job runs).
void drawAnimationExportDialogs(AppState& state);

}  // namespace somicage::editor
