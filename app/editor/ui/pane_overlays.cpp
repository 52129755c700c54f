#include "ui/pane_overlays.h"

#include <algorithm>

#include "model/app_state.h"
#include "model/view_quantities.h"
#include "model/view_quantity.h"

namespace somicage::editor {

double textWidth(const std::string& text) {
  std::size_t longest = 0, start = 0;
  for (std::size_t end = 0; end <= text.size(); ++end)
    if (end == text.size() || text[end] == '\n') {
      longest = std::max(longest, end - start);
      start = end + 1;
    }
  return kGlyphWidth * static_cast<double>(longest);
}

ViewRect legendBox(const ViewRect& pane, double contentWidth, bool beyondLine) {
  const double width = std::max(contentWidth, kLegendBarWidth) + 2 * kLegendPadding;
  const double height = 74.0 + (beyondLine ? 18.0 : 0.0);  // title, bar, its numbers, the fold-over / grey note
  return {pane.x + pane.width - kLegendRightMargin - width, pane.y + pane.height - kLegendBottomMargin - height, width,
          height};
}

ViewRect labelBox(const ViewRect& pane, double labelWidth) {
  if (labelWidth <= 0) return {pane.x, pane.y, 0, 0};
  return {pane.x + kLabelLeft - 4, pane.y + kLabelTop - 2, labelWidth + 8, kFontHeight + 4};
}

ViewRect numbersBox(const ViewRect& pane, double numbersWidth, int lines) {
  if (lines <= 0) return {pane.x, pane.y, 0, 0};
  return {pane.x + kLabelLeft - 4, pane.y + kNumbersTop - 2, numbersWidth + 8, lines * kFontHeight + 4};
}

namespace {
// The numbers under a label (quantity_overlay.cpp, viewNumbers): their lines, and a width no text of them exceeds
// ("field: views of Somigliana or BEM only", "max 0.1234, median 0.1234 diameters" and the like).
int numberLines(QuantitySource source) {
  switch (source) {
    case QuantitySource::None: return 0;
    case QuantitySource::Jacobian: return 3;
    case QuantitySource::Difference: return 2;
    case QuantitySource::Field: return 1;
  }
  return 0;
}
constexpr double kNumbersWidth = 40 * kGlyphWidth;
}  // namespace

std::string legendTitle(const QuantityDescriptor& d, bool fixed) {
  return std::string(d.name) + (d.scale == ColorScale::LogDiverging ? "  (log scale)" : "") + (fixed ? "  fixed" : "");
}

const char* legendNote(const QuantityDescriptor& d) {
  return d.source == QuantitySource::Jacobian ? "    fold-over (det J <= 0)" : "grey: undefined (outside the cage)";
}

std::vector<ViewRect> paneOverlayBoxes(const AppState& state, const std::vector<ViewRect>& panes) {
  std::vector<ViewRect> boxes;
  const std::size_t n = std::min(panes.size(), state.views().size());
  const ViewQuantities& q = state.view.quantities;
  for (std::size_t v = 0; v < n; ++v) {
    const ViewRect local{0, 0, panes[v].width, panes[v].height};
    if (!state.view.hideUi) boxes.push_back(labelBox(local, textWidth(viewLabel(state, v))));
    const int quantity = q.show.view(v).quantity;
    if (quantity <= 0) continue;
    const QuantityDescriptor& d = quantityDescriptor(quantity);
    boxes.push_back(numbersBox(local, kNumbersWidth, numberLines(d.source)));
    if (!q.show.drawsLegend(v, n)) continue;
    const double content = std::max({textWidth(legendTitle(d, true)), textWidth(legendNote(d)),
                                     textWidth("9999999 vertices beyond the ends"),
                                     18 + textWidth("fold-over (det J <= 0)")});
    boxes.push_back(legendBox(local, content, true));
  }
  boxes.erase(std::remove_if(boxes.begin(), boxes.end(), [](const ViewRect& r) { return r.width <= 0; }), boxes.end());
  return boxes;
}

}  // namespace somicage::editor
