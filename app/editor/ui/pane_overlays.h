// Where a pane's fixed overlays sit: the title (the view's label) with the numbers under it, top left, and the
// quantity legend, bottom right. Pure, no GL, no ImGui: the overlays are drawn in these boxes (panels.cpp,
// quantity_overlay.cpp) and framing (frameAll, app_state.cpp) keeps the scene clear of the same boxes.
#pragma once

#include <string>
#include <vector>

#include "model/view_quantity.h"
#include "ui/layout.h"

namespace somicage::editor {

struct AppState;

// ImGui's default font (ProggyClean, 13 pixels, monospace), which the editor draws its text in: a text's size for
// framing, before ImGui draws it. EditorPaneOverlays.TheFontMetricsAreImGuis checks them against ImGui.
constexpr double kGlyphWidth = 7.0, kFontHeight = 13.0;
double textWidth(const std::string& text);  // the longest line's, in pixels

// The legend's box in `pane` (same coordinates): `contentWidth` wide inside (at least the 220-pixel colour bar), with
// room for the "N vertices beyond the ends" line when `beyondLine`. Its text starts at (x + kLegendPadding,
// y + kLegendPadding / 2 + 2); the colour bar at (x + kLegendPadding, y + 24).
constexpr double kLegendBarWidth = 220.0, kLegendPadding = 10.0, kLegendRightMargin = 14.0, kLegendBottomMargin = 8.0;
ViewRect legendBox(const ViewRect& pane, double contentWidth, bool beyondLine);
// The legend's title ("det J  (log scale)  fixed") and its note under the bar (the fold-over swatch's label, or
// what grey means).
std::string legendTitle(const QuantityDescriptor& d, bool fixed);
const char* legendNote(const QuantityDescriptor& d);

// The label's box (one line at (x + 10, y + 8), `labelWidth` wide; none when 0) and the numbers' box under it
// (`lines` lines, `numbersWidth` wide; none when 0 lines), in `pane`'s coordinates.
ViewRect labelBox(const ViewRect& pane, double labelWidth);
ViewRect numbersBox(const ViewRect& pane, double numbersWidth, int lines);
constexpr double kLabelLeft = 10.0, kLabelTop = 8.0, kNumbersTop = kLabelTop + 17.0 + 2.0;  // 17: a line with spacing

// Every fixed overlay of each pane that framing must keep clear of, relative to its pane's top-left corner, at the
// largest each can be drawn (the legend with its "beyond the ends" line, the numbers' longest text), so that the
// scene framed before the quantities are measured stays clear of them once drawn.
std::vector<ViewRect> paneOverlayBoxes(const AppState& state, const std::vector<ViewRect>& panes);

}  // namespace somicage::editor
