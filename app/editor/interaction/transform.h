// Blender-style modal transforms of the selected cage vertices (G grab, R rotate, S scale, with an optional
// X/Y/Z axis constraint), and the plain handle drag. Pure math on the camera and the mouse, no GL.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "interaction/camera.h"

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
  std::vector<int> indices;      // the vertices that move
  Eigen::MatrixXd original;      // #V by d (2 or 3) positions at the start
  Eigen::Vector3d pivot;         // centroid of the moving vertices (z = 0 in 2D)
  Eigen::Vector2d startMouse;    // pixels in the viewport
  Eigen::Vector2d viewportSize;  // width, height in pixels
  std::string typed;             // a value typed during the transform ("2", "-90", "0.5"); "" = follow the mouse
  bool fine = false;             // Shift: a tenth of the mouse motion
  bool snap = false;             // Ctrl: grid steps, 15 degrees, scale steps of 0.1
  double gridStep = 0.1;         // world units of a grab snap (from the cage's size)
  // Scale from a gizmo square (> 0): the factor is 1 + (the mouse's travel away from the pivot, along the line from
  // the pivot to the press) / scalePixels, so a drag scales the same wherever the square sits (its distance from the
  // centre shrinks as the axis turns towards the eye: with the ratio of distances a 64-pixel drag scaled x3).
  // 0 (S): the ratio of the mouse's distances from the pivot, as Blender does.
  double scalePixels = 0;
};

// The typed value, when `typed` parses as a number (a lone "-" or "." does not).
std::optional<double> typedValue(const TransformSession& session);
// Adds a typed character (digit, '.', '-', or '\b' to erase one); false when it is not part of a number.
bool typeIntoTransform(TransformSession& session, char c);
// A round grid step (1, 2 or 5 times a power of ten) about a twentieth of `size`.
double gridStepFor(double size);

// Starts a transform of `indices` from the mouse position in a viewport of the given size.
TransformSession beginTransform(TransformKind kind, const std::vector<int>& indices, const Eigen::MatrixXd& positions,
                                const Eigen::Vector2d& mouse, const Eigen::Vector2d& viewportSize);

// The positions (#V by d) for the mouse at `mouse`, or for the typed value (Blender's numeric input: G X 2 moves
// by 2 along x, G 2 along x too; R Z 90 rotates by 90 degrees about z, R 90 about the view axis; S 0.5 scales by
// 0.5, along the axis when one is set). In 2D (d = 2) rotations are about z and Z constraints are ignored.
Eigen::MatrixXd applyTransform(const TransformSession& session, const OrbitCamera& camera,
                               const Eigen::Vector2d& mouse);

// The header text shown while transforming, e.g. "Rotate Z: 32.0 deg".
std::string describeTransform(const TransformSession& session, const OrbitCamera& camera, const Eigen::Vector2d& mouse);

// The signed angle in radians from screen vector a to b, counter-clockwise as seen on screen (y down).
double screenAngle(const Eigen::Vector2d& a, const Eigen::Vector2d& b);

}  // namespace somicage::editor
