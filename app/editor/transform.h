// Blender-style modal transforms of the selected cage vertices (G grab, R rotate, S scale, with an optional
// X/Y/Z axis constraint), and the plain handle drag. Pure math on the camera and the mouse, no GL.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "camera.h"

namespace somicage::editor {

enum class TransformKind { Grab, Rotate, Scale };
enum class Axis { None, X, Y, Z };

const char* transformName(TransformKind kind);  // "Grab", "Rotate", "Scale"
const char* axisName(Axis axis);                // "", "X", "Y", "Z"

// A transform in progress. The result is always computed from the positions at its start, so moving the
// mouse back undoes the motion exactly and cancelling restores `original`.
struct TransformSession {
  TransformKind kind = TransformKind::Grab;
  Axis axis = Axis::None;
  std::vector<int> indices;        // the vertices that move
  Eigen::MatrixXd original;        // #V by d (2 or 3) positions at the start
  Eigen::Vector3d pivot;           // centroid of the moving vertices (z = 0 in 2D)
  Eigen::Vector2d startMouse;      // pixels in the viewport
  Eigen::Vector2d viewportSize;    // width, height in pixels
};

// Starts a transform of `indices` from the mouse position in a viewport of the given size.
TransformSession beginTransform(TransformKind kind, const std::vector<int>& indices, const Eigen::MatrixXd& positions,
                                const Eigen::Vector2d& mouse, const Eigen::Vector2d& viewportSize);

// The positions (#V by d) for the mouse at `mouse`. In 2D (d = 2) rotations are about z and Z constraints are
// ignored.
Eigen::MatrixXd applyTransform(const TransformSession& session, const OrbitCamera& camera, const Eigen::Vector2d& mouse);

// The header text shown while transforming, e.g. "Rotate Z: 32.0 deg".
std::string describeTransform(const TransformSession& session, const OrbitCamera& camera, const Eigen::Vector2d& mouse);

// The signed angle in radians from screen vector a to b, counter-clockwise as seen on screen (y down).
double screenAngle(const Eigen::Vector2d& a, const Eigen::Vector2d& b);

}  // namespace somicage::editor
