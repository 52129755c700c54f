// The control panel's deformation parameters, one widget per row of the parameter table
// (core/deform/parameter_schema.h, issue 23): a Number row is a slider over its range (with a "= infinity" box when it
// takes +-inf), a Switch a checkbox, a Choice radio buttons (a combo box when they do not fit the panel). Labels,
// tooltips, ranges and which methods read a row come from the table, so a row added to it (or registered by a plug-in
// or a test) appears here with no edit of this file. parameterWidgets is the pure part (no ImGui, unit-tested);
// drawParameterWidgets draws it.
#pragma once

#include <string>
#include <vector>

#include "deform/parameter_schema.h"
#include "model/app_state.h"

namespace somicage::editor {

struct AppState;

enum class ParameterWidgetKind { Slider, Checkbox, Radio, Combo };

struct ParameterWidget {
  const ParameterSpec* spec = nullptr;
  ParameterWidgetKind kind = ParameterWidgetKind::Slider;
  std::string label;    // the widget's label: the row's key for a slider or a choice, its label for a switch
  std::string tooltip;  // the row's label and tooltip, the editor's detail where it has one, the methods reading it
  bool enabled = true;  // a shown view's method reads the row (and the row applies to the current values)
  float min = 0, max = 0;  // Slider: the span (an open range inset a little: its ends are refused)
  bool infinite = false;   // Slider of a row taking +-inf: the value is infinite (the slider gives way to a box)
};

// The span a slider of a Number row covers: its range, an open range's ends left out (they are refused).
void sliderSpan(const ParameterSpec& spec, float& min, float& max);

// One widget per row of parameterSchema(), in its order, for the state's parameters and shown views.
// `panelWidth`: the width radio buttons must fit in (pixels; <= 0: always a combo box), with `textWidth` measuring
// a label (ImGui's CalcTextSize in the panel; a fixed width per character in tests).
std::vector<ParameterWidget> parameterWidgets(const AppState& state, float panelWidth,
                                              float (*textWidth)(const char* text));

// Draws the widgets in the current ImGui window and applies a change (an undo step, or at the end of a slider drag).
void drawParameterWidgets(AppState& state);

}  // namespace somicage::editor
