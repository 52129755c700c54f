// The editor side of view_quantity.h: measuring the views when the pose settles, the Show choice, and what is drawn
// over each view (its numbers under the label, and the legend of the shared colour range). ImGui, no GL.
#pragma once

#include <vector>

#include "app_state.h"
#include "layout.h"

namespace somicage::editor {

// Measures the views for the shown quantity once the pose settles (no interaction running): the J evaluation costs
// several frames, so it never runs per drag step. Errors go to state.errors and turn the quantity off.
void measureViews(AppState& state);
// The shared colour range of the shown quantity over the views (view_quantity.h: sharedRange).
ColorRange shownRange(const AppState& state);
// Volume change, fold-over count and p95 distortion under each view's label, and the legend in the last view.
void drawQuantityOverlay(const AppState& state, const std::vector<ViewRect>& views);
// The Show combo of the control panel.
void drawShowChoice(AppState& state);
// Sweeps nu over (-0.95, 0.49) in 25 steps for the current pose of the Somigliana view (its gradients made for
// the call when no J-based quantity is shown); errors go to state.errors.
void sweepNuNow(AppState& state);
// Somigliana: a "Sweep nu" button and the plot of volume change against nu for the current pose, the current nu
// marked; a click on the plot sets nu (one undo step), hovering shows the value there.
void drawNuPlot(AppState& state);

}  // namespace somicage::editor
