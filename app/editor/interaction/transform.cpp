#include "interaction/transform.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace somicage::editor {

namespace {

Eigen::Vector3d axisVector(Axis axis) {
  switch (axis) {
    case Axis::X:
      return Eigen::Vector3d::UnitX();
    case Axis::Y:
      return Eigen::Vector3d::UnitY();
    case Axis::Z:
      return Eigen::Vector3d::UnitZ();
    case Axis::None:
      break;
  }
  return Eigen::Vector3d::Zero();
}

Eigen::Vector3d row3(const Eigen::MatrixXd& m, Eigen::Index i) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (Eigen::Index c = 0; c < std::min<Eigen::Index>(m.cols(), 3); ++c) p[c] = m(i, c);
  return p;
}

Axis effectiveAxis(const TransformSession& s) {
  return (s.original.cols() == 2 && s.axis == Axis::Z) ? Axis::None : s.axis;
}

Eigen::Vector2d pivotOnScreen(const TransformSession& s, const OrbitCamera& camera) {
  Eigen::Vector2d p = 0.5 * s.viewportSize;
  camera.project(s.pivot, s.viewportSize.x(), s.viewportSize.y(), p);
  return p;
}

constexpr double kPi = 3.14159265358979323846;

double snapTo(double x, double step) { return step > 0 ? std::round(x / step) * step : x; }

// Shift: a tenth of the motion from the start.
Eigen::Vector2d effectiveMouse(const TransformSession& s, const Eigen::Vector2d& mouse) {
  return s.fine ? Eigen::Vector2d(s.startMouse + 0.1 * (mouse - s.startMouse)) : mouse;
}

// World translation for a grab.
Eigen::Vector3d grabTranslation(const TransformSession& s, const OrbitCamera& camera, const Eigen::Vector2d& rawMouse) {
  if (const std::optional<double> v = typedValue(s)) {
    const Axis axis = effectiveAxis(s);
    return *v * axisVector(axis == Axis::None ? Axis::X : axis);
  }
  const Eigen::Vector2d mouse = effectiveMouse(s, rawMouse);
  const Eigen::Vector2d delta = mouse - s.startMouse;
  const double wpp = camera.worldPerPixel(s.pivot, s.viewportSize.y());
  const Eigen::Vector3d free = (delta.x() * camera.right() - delta.y() * camera.up()) * wpp;
  const Axis axis = effectiveAxis(s);
  if (axis == Axis::None) return free;
  // Constrained: move along the axis by the mouse motion projected on the axis' screen direction.
  const Eigen::Vector3d a = axisVector(axis);
  const Eigen::Vector2d screenAxis(a.dot(camera.right()), -a.dot(camera.up()));  // pixels per (world / wpp)
  const double len2 = screenAxis.squaredNorm();
  if (len2 < 1e-4) return a * a.dot(free);  // axis points at the eye: fall back to the view-plane component
  const double along = delta.dot(screenAxis) / len2 * wpp;
  return a * (s.snap ? snapTo(along, s.gridStep) : along);
}

Eigen::Vector3d snappedFree(const TransformSession& s, Eigen::Vector3d t) {
  if (s.snap && effectiveAxis(s) == Axis::None)
    for (int c = 0; c < 3; ++c) t[c] = snapTo(t[c], s.gridStep);
  return t;
}

double rotationAngle(const TransformSession& s, const OrbitCamera& camera, const Eigen::Vector2d& rawMouse) {
  if (const std::optional<double> v = typedValue(s)) return *v * kPi / 180.0;
  const Eigen::Vector2d mouse = effectiveMouse(s, rawMouse);
  const Eigen::Vector2d c = pivotOnScreen(s, camera);
  const double angle = screenAngle(s.startMouse - c, mouse - c);
  return s.snap ? snapTo(angle, 15.0 * kPi / 180.0) : angle;
}

double scaleFactor(const TransformSession& s, const OrbitCamera& camera, const Eigen::Vector2d& rawMouse) {
  if (const std::optional<double> v = typedValue(s)) return *v;
  const Eigen::Vector2d mouse = effectiveMouse(s, rawMouse);
  const Eigen::Vector2d c = pivotOnScreen(s, camera);
  const double r0 = (s.startMouse - c).norm();
  double f = 1.0;
  if (s.scalePixels > 0) {
    const Eigen::Vector2d away = r0 < 1e-9 ? Eigen::Vector2d(1, 0) : Eigen::Vector2d((s.startMouse - c) / r0);
    f = 1.0 + (mouse - s.startMouse).dot(away) / s.scalePixels;
  } else if (r0 >= 1e-9) {
    f = (mouse - c).norm() / r0;
  }
  return s.snap ? snapTo(f, 0.1) : f;
}

}  // namespace

const char* transformName(TransformKind kind) {
  switch (kind) {
    case TransformKind::Grab:
      return "Grab";
    case TransformKind::Rotate:
      return "Rotate";
    case TransformKind::Scale:
      return "Scale";
  }
  return "?";
}

const char* axisName(Axis axis) {
  switch (axis) {
    case Axis::X:
      return "X";
    case Axis::Y:
      return "Y";
    case Axis::Z:
      return "Z";
    case Axis::None:
      break;
  }
  return "";
}

double screenAngle(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  // Flip y so that counter-clockwise on screen is positive.
  const double cross = a.x() * (-b.y()) - (-a.y()) * b.x();
  const double dot = a.dot(b);
  return std::atan2(cross, dot);
}

TransformSession beginTransform(TransformKind kind, const std::vector<int>& indices, const Eigen::MatrixXd& positions,
                                const Eigen::Vector2d& mouse, const Eigen::Vector2d& viewportSize) {
  TransformSession s;
  s.kind = kind;
  s.indices = indices;
  s.original = positions;
  s.startMouse = mouse;
  s.viewportSize = viewportSize;
  s.pivot.setZero();
  for (int i : indices) s.pivot += row3(positions, i);
  if (!indices.empty()) s.pivot /= static_cast<double>(indices.size());
  return s;
}

Eigen::MatrixXd applyTransform(const TransformSession& s, const OrbitCamera& camera, const Eigen::Vector2d& mouse) {
  Eigen::MatrixXd out = s.original;
  const int dim = static_cast<int>(s.original.cols());
  const Axis axis = effectiveAxis(s);
  Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  switch (s.kind) {
    case TransformKind::Grab:
      translation =
          typedValue(s) ? grabTranslation(s, camera, mouse) : snappedFree(s, grabTranslation(s, camera, mouse));
      break;
    case TransformKind::Rotate: {
      const double angle = rotationAngle(s, camera, mouse);
      const Eigen::Vector3d toViewer = -camera.forward();
      Eigen::Vector3d a = (dim == 2) ? Eigen::Vector3d::UnitZ() : (axis == Axis::None ? toViewer : axisVector(axis));
      // Counter-clockwise on screen is a positive rotation about the axis pointing at the viewer.
      // A typed angle turns right-handedly about the named axis (+z in 2D), as in Blender.
      if (a.dot(toViewer) < 0 && !(typedValue(s) && (axis != Axis::None || dim == 2))) a = -a;
      linear = Eigen::AngleAxisd(angle, a).toRotationMatrix();
      break;
    }
    case TransformKind::Scale: {
      const double f = scaleFactor(s, camera, mouse);
      if (axis == Axis::None) {
        linear = f * Eigen::Matrix3d::Identity();
      } else {
        const Eigen::Vector3d a = axisVector(axis);
        linear += (f - 1.0) * a * a.transpose();
      }
      if (dim == 2) linear(2, 2) = 1.0;
      break;
    }
  }
  for (int i : s.indices) {
    if (i < 0 || i >= out.rows()) continue;
    const Eigen::Vector3d p = s.pivot + linear * (row3(s.original, i) - s.pivot) + translation;
    for (int c = 0; c < dim; ++c) out(i, c) = p[c];
  }
  return out;
}

std::string describeTransform(const TransformSession& s, const OrbitCamera& camera, const Eigen::Vector2d& mouse) {
  char buf[160];
  const Axis axis = effectiveAxis(s);
  const char* sep = axis == Axis::None ? "" : " ";
  switch (s.kind) {
    case TransformKind::Grab: {
      Eigen::Vector3d t =
          typedValue(s) ? grabTranslation(s, camera, mouse) : snappedFree(s, grabTranslation(s, camera, mouse));
      // -0 (a typed -0.3 times an axis' zero) and rounding noise read as 0: "(0, 0, -0.3)", not "(-0, -0, -0.3)".
      const double noise = 1e-12 * std::max(1.0, t.cwiseAbs().maxCoeff());
      for (int k = 0; k < 3; ++k) t[k] = std::abs(t[k]) <= noise ? 0.0 : t[k];
      std::snprintf(buf, sizeof buf, "Grab%s%s: (%.4g, %.4g, %.4g)", sep, axisName(axis), t.x(), t.y(), t.z());
      break;
    }
    case TransformKind::Rotate:
      std::snprintf(buf, sizeof buf, "Rotate%s%s: %.1f deg", sep, axisName(axis),
                    rotationAngle(s, camera, mouse) * 180.0 / kPi);
      break;
    case TransformKind::Scale:
      std::snprintf(buf, sizeof buf, "Scale%s%s: %.3f", sep, axisName(axis), scaleFactor(s, camera, mouse));
      break;
  }
  std::string text = buf;
  if (!s.typed.empty()) text += "   typed: " + s.typed;
  return text + "   [X/Y/Z axis, type a value, Shift fine, Ctrl snap, Enter/click confirm, Esc/right-click cancel]";
}

std::optional<double> typedValue(const TransformSession& s) {
  if (s.typed.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(s.typed.c_str(), &end);
  if (end != s.typed.c_str() + s.typed.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

bool typeIntoTransform(TransformSession& s, char c) {
  if (c == '\b') {
    if (!s.typed.empty()) s.typed.pop_back();
    return true;
  }
  if (c == '-') {  // as in Blender: minus toggles the sign, wherever it is typed
    s.typed = !s.typed.empty() && s.typed[0] == '-' ? s.typed.substr(1) : "-" + s.typed;
    return true;
  }
  if (c == '.' && s.typed.find('.') != std::string::npos) return false;
  if (!(c == '.' || (c >= '0' && c <= '9'))) return false;
  s.typed += c;
  return true;
}

double gridStepFor(double size) {
  if (!(size > 0) || !std::isfinite(size)) return 0.1;
  const double target = size / 20.0;
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * decade >= target * 0.75) return m * decade;
  }
  return 10.0 * decade;
}

}  // namespace somicage::editor
