// The transform gizmo on the selection (Blender-like): an arrow per axis (drag: move along it), a square on
// each arrow (drag: scale along it), a ring (drag: rotate about the view axis) and a centre disc (drag: move in
// the view plane). Dragging a part runs the same TransformSession as G / R / S with that kind and axis, so Shift
// (fine), Ctrl (snap) and Esc / right click (cancel) work the same, and the release is one undo step.
// Screen-space geometry and hit testing only, no GL (input.cpp draws it with ImGui).
#pragma once

#include <Eigen/Core>
#include <array>

#include "interaction/camera.h"
#include "interaction/transform.h"

namespace somicage::editor {

struct GizmoPart {
  enum class Kind { None, Move, Scale, Rotate };
  Kind kind = Kind::None;
  Axis axis = Axis::None;  // Move / Scale along an axis; None = in the view plane (Move) or about it (Rotate)
  bool operator==(const GizmoPart& o) const { return kind == o.kind && axis == o.axis; }
};

struct GizmoLayout {
  static constexpr double kArrowPixels = 80.0, kRingPixels = 100.0, kCentrePixels = 9.0, kGrabPixels = 7.0;
  Eigen::Vector2d centre;                // the selection's centroid on screen (viewport pixels)
  std::array<Eigen::Vector2d, 3> tips;   // arrow ends, x y z
  std::array<Eigen::Vector2d, 3> boxes;  // scale squares, x y z (60 % along the arrows)
  std::array<bool, 3> shown{};           // an axis pointing at the eye has no usable arrow
};

// The gizmo of a selection centred at `pivot` (world) in a width x height viewport; false when the pivot is behind
// the eye. In 2D (dim = 2) there is no z arrow.
bool layoutGizmo(const OrbitCamera& camera, const Eigen::Vector3d& pivot, int dim, double width, double height,
                 GizmoLayout& layout);

// The part under `mouse` (viewport pixels): scale squares and arrow tips first, then the centre, then the ring.
GizmoPart pickGizmo(const GizmoLayout& layout, const Eigen::Vector2d& mouse);

}  // namespace somicage::editor
