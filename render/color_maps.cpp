// Colour maps for per-vertex scalars (mesh_renderer.h): piecewise-linear through published control points.
#include <algorithm>
#include <array>
#include <cmath>

#include "mesh_renderer.h"

namespace somicage::render {

namespace {

using Stops = std::array<std::array<float, 3>, 9>;  // evenly spaced over [0, 1], 0-255

// Moreland, "Diverging Color Maps for Scientific Visualization" (2009), cool-warm, centre grey (221, 221, 221).
constexpr Stops kCoolWarm{{{59, 76, 192},
                           {98, 130, 234},
                           {141, 176, 254},
                           {184, 208, 249},
                           {221, 221, 221},
                           {245, 196, 173},
                           {244, 154, 123},
                           {222, 96, 77},
                           {180, 4, 38}}};
// matplotlib's viridis at t = k / 8.
constexpr Stops kViridis{{{68, 1, 84},
                          {71, 44, 122},
                          {59, 82, 139},
                          {44, 114, 142},
                          {33, 145, 140},
                          {40, 174, 128},
                          {94, 201, 98},
                          {173, 220, 48},
                          {253, 231, 37}}};

}  // namespace

Eigen::Vector3f colorMapColor(int row, float t) {
  const Stops& stops = row == kDivergingMap ? kCoolWarm : kViridis;
  const float x = std::clamp(t, 0.0f, 1.0f) * 8.0f;
  const int i = std::min(7, static_cast<int>(std::floor(x)));
  const float f = x - static_cast<float>(i);
  Eigen::Vector3f c;
  for (int k = 0; k < 3; ++k) c[k] = ((1 - f) * stops[i][k] + f * stops[i + 1][k]) / 255.0f;
  return c;
}

}  // namespace somicage::render
