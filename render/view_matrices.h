// What every draw call needs to know about the view. No GL types.
#pragma once

#include <Eigen/Core>

namespace somicage::render {

// A rectangle of the framebuffer in pixels, GL convention: (x, y) is the bottom-left corner.
struct ViewportRect {
  int x = 0, y = 0, width = 1, height = 1;
};

// Column-vector convention: clip = projection * view * world.
struct ViewMatrices {
  Eigen::Matrix4f view = Eigen::Matrix4f::Identity();
  Eigen::Matrix4f projection = Eigen::Matrix4f::Identity();
  bool orthographic = false;  // lighting uses a constant view direction when true
};

}  // namespace somicage::render
