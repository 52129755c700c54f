// The orbit camera: pure math, no GL. Y is up; screen coordinates are pixels inside a viewport, x to the
// right and y downwards from its top-left corner (the convention of GLFW and ImGui).
#pragma once

#include <Eigen/Core>

#include <vector>

#include "engine/camera_state.h"
#include "ui/layout.h"

namespace somicage::editor {

// The pane a framing is for: its size in pixels, the boxes drawn over it that the framed box must stay clear of (pane
// pixels, ui/pane_overlays.h), and a world point that must stay `pointPixels` inside the pane's edges (the gizmo's ring
// around the selection, gizmo.h). A box that covers the pane's centre cannot be kept clear and is let be.
struct FrameRoom {
  double width = 1.0, height = 1.0;
  std::vector<ViewRect> keepClear;
  bool hasPoint = false;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  double pointPixels = 0.0;
};

class OrbitCamera {
 public:
  static constexpr double kFovY = 0.6108652381980153;  // 35 degrees
  static constexpr double kMaxPitch = 1.55;

  // mode2D: looks down -z with an orthographic projection; orbiting is disabled.
  void setMode2D(bool on);
  bool mode2D() const { return mode2D_; }
  const CameraState& state() const { return state_; }
  void setState(const CameraState& state);

  Eigen::Vector3d eye() const;
  Eigen::Vector3d forward() const;  // unit, from the eye to the target
  Eigen::Vector3d right() const;    // unit, screen +x
  Eigen::Vector3d up() const;       // unit, screen -y

  // Column-vector matrices (clip = projection * view * world), single precision for upload.
  Eigen::Matrix4d viewMatrix() const;
  Eigen::Matrix4d projectionMatrix(double aspect) const;

  // Dragging by (dx, dy) pixels; pan keeps the point under the cursor (at the target's depth) under it.
  void orbit(double dxPixels, double dyPixels);
  void pan(double dxPixels, double dyPixels, double viewportHeight);
  // Wheel steps (positive = closer), multiplicative.
  void zoom(double steps);
  // Fits the box [lo, hi] in a viewport of the given aspect (width / height), keeping the direction.
  void frame(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double aspect = 1.0);
  // Frames it in the room's pane as frame(lo, hi, aspect) does (the target at the box's centre, its bounding sphere
  // in view, so orbiting keeps it there), then, if need be, farther: until the room's point is inside and the
  // projected bounding box of [lo, hi] misses the room's boxes (not farther than 3 times: a pane too small for them).
  void frame(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const FrameRoom& room);

  // World length of one pixel at the depth of `point` for a viewport `viewportHeight` pixels high.
  double worldPerPixel(const Eigen::Vector3d& point, double viewportHeight) const;

  // Screen position (pixels) of a world point in a width x height viewport; depth = distance along forward().
  // Returns false when the point is behind the eye.
  bool project(const Eigen::Vector3d& world, double width, double height, Eigen::Vector2d& screen,
               double* depth = nullptr) const;
  // The world point at screen position `screen` and the given depth along forward().
  Eigen::Vector3d unproject(const Eigen::Vector2d& screen, double depth, double width, double height) const;

 private:
  double halfHeightAt(double depth) const;  // half the visible world height at a depth
  CameraState state_;
  bool mode2D_ = false;
};

}  // namespace somicage::editor
