// Where the viewports go in the window. Pure, no GL.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace somicage::editor {

// A viewport in window pixels, top-left origin (GLFW / ImGui convention).
struct ViewRect {
  double x = 0, y = 0, width = 1, height = 1;
  bool contains(const Eigen::Vector2d& p) const {
    return p.x() >= x && p.x() < x + width && p.y() >= y && p.y() < y + height;
  }
  Eigen::Vector2d size() const { return {width, height}; }
  Eigen::Vector2d origin() const { return {x, y}; }
};

// `count` side-by-side viewports of equal width (the last takes the rounding remainder) filling the window
// minus a left panel and top/bottom bars. Widths and heights are whole pixels, at least 1.
std::vector<ViewRect> layoutViews(double windowWidth, double windowHeight, double leftPanel, double topBar,
                                  double bottomBar, int count);

// Index of the view containing p, or -1.
int viewAt(const std::vector<ViewRect>& views, const Eigen::Vector2d& p);

}  // namespace somicage::editor
