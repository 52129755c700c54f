// What a session file stores about the editor's orbit camera (app/editor/interaction/camera.h). Pure data.
#pragma once

#include <Eigen/Core>

namespace somicage {

struct CameraState {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double distance = 5.0;  // eye to target
  double yaw = 0.6;       // radians about +y, 0 = looking down -z
  double pitch = 0.35;    // radians above the horizon, clamped to (-pi/2, pi/2)
};

}  // namespace somicage
