#include "interaction/gizmo.h"

#include <cmath>

#include "model/selection.h"

namespace somicage::editor {

namespace {

constexpr Axis kAxes[3] = {Axis::X, Axis::Y, Axis::Z};

}  // namespace

bool layoutGizmo(const OrbitCamera& camera, const Eigen::Vector3d& pivot, int dim, double width, double height,
                 GizmoLayout& g) {
  if (!camera.project(pivot, width, height, g.centre)) return false;
  for (int a = 0; a < 3; ++a) {
    Eigen::Vector3d dir = Eigen::Vector3d::Zero();
    dir[a] = 1.0;
    const Eigen::Vector2d screenDir(dir.dot(camera.right()), -dir.dot(camera.up()));  // y down
    g.shown[a] = !(a == 2 && dim == 2) && screenDir.norm() > 0.2;
    const Eigen::Vector2d unit =
        screenDir.norm() > 1e-9 ? Eigen::Vector2d(screenDir.normalized()) : Eigen::Vector2d::Zero();
    g.tips[a] = g.centre + GizmoLayout::kArrowPixels * screenDir.norm() * unit;
    g.boxes[a] = g.centre + 0.6 * (g.tips[a] - g.centre);
  }
  return true;
}

GizmoPart pickGizmo(const GizmoLayout& g, const Eigen::Vector2d& mouse) {
  for (int a = 0; a < 3; ++a) {
    if (g.shown[a] && (mouse - g.boxes[a]).cwiseAbs().maxCoeff() <= GizmoLayout::kGrabPixels)
      return {GizmoPart::Kind::Scale, kAxes[a]};
  }
  for (int a = 0; a < 3; ++a) {
    if (g.shown[a] && segmentDistance(mouse, g.boxes[a], g.tips[a]) <= GizmoLayout::kGrabPixels &&
        (mouse - g.boxes[a]).norm() > GizmoLayout::kGrabPixels)
      return {GizmoPart::Kind::Move, kAxes[a]};
  }
  const double r = (mouse - g.centre).norm();
  if (r <= GizmoLayout::kCentrePixels) return {GizmoPart::Kind::Move, Axis::None};
  if (std::abs(r - GizmoLayout::kRingPixels) <= GizmoLayout::kGrabPixels) return {GizmoPart::Kind::Rotate, Axis::None};
  return {};
}

}  // namespace somicage::editor
