#include "interaction/camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace somicage::editor {

void OrbitCamera::setMode2D(bool on) {
  mode2D_ = on;
  if (on) state_.yaw = state_.pitch = 0.0;
}

void OrbitCamera::setState(const CameraState& state) {
  state_ = state;
  state_.distance = std::max(state_.distance, 1e-9);
  state_.pitch = std::clamp(state_.pitch, -kMaxPitch, kMaxPitch);
  if (mode2D_) state_.yaw = state_.pitch = 0.0;
}

Eigen::Vector3d OrbitCamera::forward() const {
  const double cp = std::cos(state_.pitch);
  return -Eigen::Vector3d(cp * std::sin(state_.yaw), std::sin(state_.pitch), cp * std::cos(state_.yaw));
}

Eigen::Vector3d OrbitCamera::eye() const { return state_.target - state_.distance * forward(); }

Eigen::Vector3d OrbitCamera::right() const { return Eigen::Vector3d(std::cos(state_.yaw), 0.0, -std::sin(state_.yaw)); }

Eigen::Vector3d OrbitCamera::up() const { return right().cross(forward()); }

Eigen::Matrix4d OrbitCamera::viewMatrix() const {
  const Eigen::Vector3d r = right(), u = up(), f = forward(), e = eye();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = r.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -r.dot(e);
  m(1, 3) = -u.dot(e);
  m(2, 3) = f.dot(e);
  return m;
}

double OrbitCamera::halfHeightAt(double depth) const {
  // In 2D the visible height does not depend on depth: it is what the perspective shows at the target.
  return (mode2D_ ? state_.distance : depth) * std::tan(0.5 * kFovY);
}

Eigen::Matrix4d OrbitCamera::projectionMatrix(double aspect) const {
  aspect = std::max(aspect, 1e-6);
  const double d = state_.distance;
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  if (mode2D_) {
    const double h = halfHeightAt(d), w = h * aspect, nearZ = 1e-3 * d, farZ = 1e3 * d;
    p(0, 0) = 1.0 / w;
    p(1, 1) = 1.0 / h;
    p(2, 2) = -2.0 / (farZ - nearZ);
    p(2, 3) = -(farZ + nearZ) / (farZ - nearZ);
    p(3, 3) = 1.0;
  } else {
    const double nearZ = 0.01 * d, farZ = 100.0 * d, t = std::tan(0.5 * kFovY);
    p(0, 0) = 1.0 / (t * aspect);
    p(1, 1) = 1.0 / t;
    p(2, 2) = -(farZ + nearZ) / (farZ - nearZ);
    p(2, 3) = -2.0 * farZ * nearZ / (farZ - nearZ);
    p(3, 2) = -1.0;
  }
  return p;
}

void OrbitCamera::orbit(double dxPixels, double dyPixels) {
  if (mode2D_) return;
  state_.yaw -= 0.008 * dxPixels;
  state_.pitch = std::clamp(state_.pitch + 0.008 * dyPixels, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(double dxPixels, double dyPixels, double viewportHeight) {
  const double wpp = worldPerPixel(state_.target, viewportHeight);
  state_.target += (-dxPixels * right() + dyPixels * up()) * wpp;
}

void OrbitCamera::zoom(double steps) { state_.distance = std::max(state_.distance * std::pow(0.85, steps), 1e-9); }

void OrbitCamera::frame(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double aspect) {
  FrameRoom room;
  room.width = std::clamp(aspect, 1e-3, 1e3);
  frame(lo, hi, room);
}

namespace {
// A pane too small for its overlays and the gizmo: the camera moves back at most to 1 / kLeastShare times the
// distance without them (the scene a third of its size there), and they cover part of it.
constexpr double kLeastShare = 1.0 / 3.0;
}  // namespace

void OrbitCamera::frame(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const FrameRoom& room) {
  state_.target = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * (hi - lo).norm(), 1e-9);
  const double cx = 0.5 * std::max(room.width, 1e-9), cy = 0.5 * std::max(room.height, 1e-9);
  const double tanV = std::tan(0.5 * kFovY), tanMin = tanV * std::min(cx / cy, 1.0);
  // The pane: the box's circumscribed sphere, larger by a margin, fits it (orbiting keeps it in view).
  const double fitted = mode2D_ ? 1.05 * radius / tanMin  // orthographic: the visible half-height is distance * tanV
                                : 1.1 * radius / std::sin(std::atan(tanMin));
  // A point's offset from the pane's centre in pixels at a distance (right, down): focal * offset / depth, or in 2D
  // offset * cy / (distance * tanV).
  const double focal = cy / tanV;
  const auto perPixel = [&](const Eigen::Vector3d& rel, double distance) {  // world length of a pixel there
    return mode2D_ ? distance * tanV / cy : (distance + rel.dot(forward())) / focal;
  };
  const double farthest = fitted / kLeastShare;
  double distance = fitted;
  if (room.hasPoint) {  // the point at least pointPixels inside each edge: its offset shrinks as the distance grows
    const Eigen::Vector3d rel = room.point - state_.target;
    const double depth = mode2D_ ? 0.0 : rel.dot(forward());
    const double x = std::abs(rel.dot(right())), y = std::abs(rel.dot(up()));
    const double scale = mode2D_ ? cy / tanV : focal;  // offset = scale * x / (distance [2D] or distance + depth)
    if (cx > room.pointPixels) distance = std::max(distance, scale * x / (cx - room.pointPixels) - depth);
    if (cy > room.pointPixels) distance = std::max(distance, scale * y / (cy - room.pointPixels) - depth);
  }
  // The overlays: the projected bounding box of the box's corners, 5 % larger about the centre, must miss each one
  // (but one over the pane's centre, which nothing can miss). It shrinks towards the centre as the distance grows,
  // so the least distance that clears them is found by bisection.
  const auto clear = [&](double d) {
    double minX = 1e300, maxX = -1e300, minY = 1e300, maxY = -1e300;  // pixels from the centre, right and down
    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector3d corner((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(), (k & 4) ? hi.z() : lo.z());
      const Eigen::Vector3d rel = corner - state_.target;
      const double pixel = perPixel(rel, d), x = 1.05 * rel.dot(right()) / pixel, y = -1.05 * rel.dot(up()) / pixel;
      minX = std::min(minX, x);
      maxX = std::max(maxX, x);
      minY = std::min(minY, y);
      maxY = std::max(maxY, y);
    }
    for (const ViewRect& r : room.keepClear) {
      const double x0 = r.x - cx, x1 = r.x + r.width - cx, y0 = r.y - cy, y1 = r.y + r.height - cy;
      const bool overCentre = x0 <= 0 && x1 >= 0 && y0 <= 0 && y1 >= 0;
      if (!overCentre && minX < x1 && maxX > x0 && minY < y1 && maxY > y0) return false;
    }
    return true;
  };
  distance = std::min(distance, farthest);
  if (!clear(distance)) {
    double near = distance, far = farthest;
    if (clear(far)) {
      for (int i = 0; i < 60; ++i) (clear(0.5 * (near + far)) ? far : near) = 0.5 * (near + far);
    }
    distance = far;
  }
  state_.distance = distance;
}

double OrbitCamera::worldPerPixel(const Eigen::Vector3d& point, double viewportHeight) const {
  const double depth = std::max((point - eye()).dot(forward()), 1e-9);
  return 2.0 * halfHeightAt(depth) / std::max(viewportHeight, 1.0);
}

bool OrbitCamera::project(const Eigen::Vector3d& world, double width, double height, Eigen::Vector2d& screen,
                          double* depth) const {
  const Eigen::Vector3d rel = world - eye();
  const double z = rel.dot(forward());
  if (depth) *depth = z;
  if (!mode2D_ && z <= 1e-12) return false;
  const double h = halfHeightAt(z), w = h * width / std::max(height, 1.0);
  const double ndcX = rel.dot(right()) / w, ndcY = rel.dot(up()) / h;
  screen = Eigen::Vector2d(0.5 * (ndcX + 1.0) * width, 0.5 * (1.0 - ndcY) * height);
  return true;
}

Eigen::Vector3d OrbitCamera::unproject(const Eigen::Vector2d& screen, double depth, double width, double height) const {
  const double h = halfHeightAt(depth), w = h * width / std::max(height, 1.0);
  const double ndcX = 2.0 * screen.x() / std::max(width, 1.0) - 1.0;
  const double ndcY = 1.0 - 2.0 * screen.y() / std::max(height, 1.0);
  return eye() + depth * forward() + ndcX * w * right() + ndcY * h * up();
}

}  // namespace somicage::editor
