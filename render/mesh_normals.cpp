#include "mesh_normals.h"

#include <Eigen/Geometry>

namespace somicage::render {

RowMatrixX3f toFloat3(const Eigen::MatrixXd& positions) {
  RowMatrixX3f out = RowMatrixX3f::Zero(positions.rows(), 3);
  const Eigen::Index cols = std::min<Eigen::Index>(positions.cols(), 3);
  out.leftCols(cols) = positions.leftCols(cols).cast<float>();
  return out;
}

RowMatrixX3f vertexNormals(const Eigen::MatrixXd& positions, const Eigen::MatrixXi& triangles) {
  const Eigen::Index n = positions.rows();
  Eigen::MatrixXd acc = Eigen::MatrixXd::Zero(n, 3);
  auto point = [&](int i) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (Eigen::Index c = 0; c < std::min<Eigen::Index>(positions.cols(), 3); ++c) p[c] = positions(i, c);
    return p;
  };
  // Serial on purpose: the sum order (and so the result) must not depend on a thread count.
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    const int a = triangles(f, 0), b = triangles(f, 1), c = triangles(f, 2);
    if (a < 0 || b < 0 || c < 0 || a >= n || b >= n || c >= n) continue;
    const Eigen::Vector3d pa = point(a);
    const Eigen::Vector3d faceNormal = (point(b) - pa).cross(point(c) - pa);  // |.| = twice the area
    acc.row(a) += faceNormal.transpose();
    acc.row(b) += faceNormal.transpose();
    acc.row(c) += faceNormal.transpose();
  }
  RowMatrixX3f out(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double len = acc.row(i).norm();
    out.row(i) = (len > 0 ? Eigen::RowVector3d(acc.row(i) / len) : Eigen::RowVector3d::Zero()).cast<float>();
  }
  return out;
}

}  // namespace somicage::render
