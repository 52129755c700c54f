// Alt+G / Alt+R / Alt+S: return the selected handles' location, rotation or scale to rest, as Blender's
// Clear Location / Rotation / Scale. The selection's motion from rest is read as the affine map that fits it
// best (least squares, about the centroids), split into rotation R and stretch S by the polar decomposition
// A = R S; clearing one part keeps the others. Reset pose (app_state.h) clears all of them on every handle.
// Pure math, no GL.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace somicage::editor {

enum class ClearKind { Location, Rotation, Scale };

// The pose with `indices` moved back as `kind` says (#V by d, d = 2 or 3). Location moves the selection's
// centroid back to its rest centroid; Rotation and Scale need two handles at least (else the pose is returned
// unchanged) and leave the centroid where it is.
Eigen::MatrixXd clearTransform(ClearKind kind, const Eigen::MatrixXd& rest, const Eigen::MatrixXd& pose,
                               const std::vector<int>& indices);

const char* clearKindName(ClearKind kind);  // "Clear location", ...

}  // namespace somicage::editor
