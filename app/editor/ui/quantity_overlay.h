// The editor side of view_quantity.h: measuring the views on the worker (measure_worker.h), the Show choice per
// view with its range, and what is drawn over each view (its numbers under the label, the legends, the value under
// the cursor). ImGui, no GL.
#pragma once

#include <vector>

#include "jobs/measure_worker.h"
#include "model/app_state.h"
#include "model/view_quantity.h"
#include "ui/layout.h"

namespace somicage::editor {

// What the worker should measure now (the views' deformers, quantities, the selected element, the pose; for a
// difference the other view's deformer and parameters).
MeasureRequest measureRequest(const AppState& state);
// Every frame: installs a finished outcome whose key is still current (drops a stale one), starts the worker on the
// current pose when the installed measurements are not of it and frees the gradients when no view uses them.
// Errors go to state.errors and turn the quantities off. Never blocks, never deforms.
void measureViews(AppState& state);
// Measures (measureViews) and says whether the views' measurements and a requested sweep are all installed (or
// failed): nothing more is to come from the measurement job. Never blocks: a scripted screenshot asks it each time
// a job wakes the loop.
bool measurementsSettled(AppState& state);
// The colour range of a quantity as drawn: fixed when typed, else shared by the views that show it.
ColorRange shownRange(const AppState& state, int quantity);
// The value under the cursor: view -1 and vertex -1 when none is shown.
struct HoverReadout {
  int view = -1, vertex = -1;
  const char* quantity = "";  // the quantity's id
  double value = 0;
};
// Volume change, fold-over count and p95 distortion under each view's label, one legend per shown quantity (in the
// last view that shows it) and, on hover, the value under the cursor, which it returns.
HoverReadout drawQuantityOverlay(const AppState& state, const std::vector<ViewRect>& views);
// --log-actions: prints "hover view V vertex I QUANTITY VALUE" (full precision) or "hover none" when the readout
// changes (the GUI tests read it).
void logHoverReadout(AppState& state, const HoverReadout& hover);
// The Show choices of the control panel (one per view in the compare view), the range, the worker's progress and
// Cancel.
void drawShowChoice(AppState& state);
// Asks the worker for the nu sweep over (-0.95, 0.49) in 25 steps for the current pose of the panel's method
// (Somigliana: each variant's too).
void sweepNuNow(AppState& state);
// Whether the plotted sweep is of the current pose, method and parameters (every one but nu, which it sweeps).
bool nuSweepCurrent(const AppState& state);
// A "Sweep nu" button and the plot of volume change and fold-over count against nu for the current pose, one
// fold-over line per Somigliana variant with a legend, the current nu marked; a click on the plot sets nu (one
// undo step), hovering shows the values there.
void drawNuPlot(AppState& state);

}  // namespace somicage::editor
