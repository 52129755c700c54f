// Smooth vertex normals of a triangle mesh, recomputed every frame from the deformed positions. No GL.
#pragma once

#include <Eigen/Core>

namespace somicage::render {

using RowMatrixX3f = Eigen::Matrix<float, Eigen::Dynamic, 3, Eigen::RowMajor>;

// positions: #V by 2 or 3 (2D meshes lie in z = 0). triangles: #F by 3.
// Returns #V by 3 unit normals: the area-weighted sum of the incident face normals (zero for isolated
// vertices). Orientation follows the winding; the mesh shader lights both sides, so inward-facing meshes
// still shade correctly. 2D meshes get +-z.
RowMatrixX3f vertexNormals(const Eigen::MatrixXd& positions, const Eigen::MatrixXi& triangles);

// positions as float xyz (z = 0 for 2D), row-major for upload.
RowMatrixX3f toFloat3(const Eigen::MatrixXd& positions);

}  // namespace somicage::render
