// Cage vertex selection: screen-space picking, box selection and the selected set. Pure, no GL.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "interaction/camera.h"

namespace somicage::editor {

struct ScreenPoint {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // pixels in the viewport, y down
  double depth = 0.0;                                  // along the view direction
  bool visible = false;                                // in front of the eye
};

// Projects #V by 2 or 3 points (2D points lie in z = 0) into a width x height viewport.
std::vector<ScreenPoint> projectPoints(const OrbitCamera& camera, const Eigen::MatrixXd& points, double width,
                                       double height);

// The point nearest to `mouse` within `radius` pixels, ties (within a pixel) going to the nearer one in depth;
// -1 when none.
int pickPoint(const std::vector<ScreenPoint>& points, const Eigen::Vector2d& mouse, double radius);

// Distance in pixels from p to the segment a-b.
double segmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

// Indices of the visible points inside the rectangle spanned by two corners (any order), inclusive.
std::vector<int> pointsInRect(const std::vector<ScreenPoint>& points, const Eigen::Vector2d& cornerA,
                              const Eigen::Vector2d& cornerB);

// A set of cage vertices.
class Selection {
 public:
  enum class Mode { Replace, Add, Toggle };

  void resize(int count);  // clears
  int size() const { return static_cast<int>(flags_.size()); }
  bool isSelected(int i) const { return i >= 0 && i < size() && flags_[static_cast<std::size_t>(i)]; }
  int count() const;
  bool empty() const { return count() == 0; }
  const std::vector<bool>& flags() const { return flags_; }
  std::vector<int> indices() const;

  void clear();
  void selectAll();
  // Click semantics: Replace selects only i (or nothing for i = -1), Toggle flips i, Add adds i.
  void click(int i, Mode mode);
  // Box semantics: Replace selects exactly `indices`, Add adds them, Toggle flips each.
  void apply(const std::vector<int>& indices, Mode mode);
  void setIndices(const std::vector<int>& indices);

  // Mean of the selected rows of positions (#V by d); zero when nothing is selected.
  Eigen::VectorXd centroid(const Eigen::MatrixXd& positions) const;

 private:
  std::vector<bool> flags_;
};

}  // namespace somicage::editor
