// Vertex / edge / face selection modes (keys 1 / 2 / 3, as in Blender's edit mode): which cage element is under
// the mouse, and its vertices, which are what a click selects (cage handles are vertices; an edge or a face
// selects the vertices it joins). Screen-space, on projected points (selection.h). Pure, no GL.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "model/selection.h"

namespace somicage::editor {

enum class ElementMode { Vertex, Edge, Face };
const char* elementModeName(ElementMode mode);  // "vertices", "edges", "faces"

// The unique edges of a cage's faces (#F by d: triangles in 3D, segments in 2D), each as (a, b) with a < b.
std::vector<std::pair<int, int>> cageEdges(const Eigen::MatrixXi& faces);
// The edges whose two vertices are selected (`selected`: a flag per cage vertex), drawn highlighted.
std::vector<std::pair<int, int>> selectedEdges(const Eigen::MatrixXi& faces, const std::vector<bool>& selected);

// The vertices of the element under `mouse`: the nearest vertex within `radius`; the nearest edge within
// `radius` of its segment; the front-most face (triangle) containing the mouse (in 2D, where faces are
// segments, faces pick like edges). Empty when nothing is there.
std::vector<int> pickElement(ElementMode mode, const std::vector<ScreenPoint>& points, const Eigen::MatrixXi& faces,
                             const Eigen::Vector2d& mouse, double radius);

}  // namespace somicage::editor
