#include "ui/layout.h"

#include <algorithm>
#include <cmath>

namespace somicage::editor {

std::vector<ViewRect> layoutViews(double windowWidth, double windowHeight, double leftPanel, double topBar,
                                  double bottomBar, int count) {
  count = std::max(count, 1);
  const double x0 = std::floor(leftPanel), y0 = std::floor(topBar);
  const double total = std::max(std::floor(windowWidth) - x0, static_cast<double>(count));
  const double height = std::max(std::floor(windowHeight - y0 - bottomBar), 1.0);
  const double each = std::floor(total / count);
  std::vector<ViewRect> views;
  for (int i = 0; i < count; ++i) {
    ViewRect r;
    r.x = x0 + i * each;
    r.y = y0;
    r.width = (i + 1 == count) ? total - i * each : each;
    r.height = height;
    views.push_back(r);
  }
  return views;
}

int viewAt(const std::vector<ViewRect>& views, const Eigen::Vector2d& p) {
  for (std::size_t i = 0; i < views.size(); ++i) {
    if (views[i].contains(p)) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace somicage::editor
