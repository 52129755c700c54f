#include "animation/normal_transform.h"

#include <Eigen/Geometry>
#include <cmath>

#include "base/errors.h"

namespace somicage {

namespace {

// The 3 by 3 gradient of vertex i (a 2D map keeps z: J_zz = 1).
Eigen::Matrix3d gradientOf(const Eigen::MatrixXd& jacobians, int i) {
  const int d = jacobians.cols() == 4 ? 2 : 3;
  Eigen::Matrix3d J = Eigen::Matrix3d::Identity();
  for (int a = 0; a < d; ++a)
    for (int b = 0; b < d; ++b) J(a, b) = jacobians(i, a * d + b);
  return J;
}

// cof(J) = det(J) J^-T, column by column from cross products: defined for every J, singular ones included.
Eigen::Matrix3d cofactor(const Eigen::Matrix3d& J) {
  Eigen::Matrix3d c;
  c.col(0) = J.col(1).cross(J.col(2));
  c.col(1) = J.col(2).cross(J.col(0));
  c.col(2) = J.col(0).cross(J.col(1));
  return c;
}

}  // namespace

TransformedNormals transformNormals(const MeshDocument& document, const Eigen::MatrixXd& positions,
                                    const Eigen::MatrixXd& jacobians) {
  SOMICAGE_ASSERT(
      jacobians.rows() == document.geometry.numVertices() && (jacobians.cols() == 4 || jacobians.cols() == 9),
      "transformNormals takes one 2D or 3D gradient per mesh vertex");
  Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(document.normalCount, 3);
  std::vector<char> usable(static_cast<size_t>(document.normalCount), 1);
  const std::vector<std::vector<int>>& faces = document.geometry.faces;
  for (size_t f = 0; f < faces.size(); ++f) {
    for (size_t k = 0; k < faces[f].size(); ++k) {
      const int n = document.faceNormals[f][k];
      if (n < 0 || !usable[static_cast<size_t>(n)]) continue;
      const Eigen::Matrix3d J = gradientOf(jacobians, faces[f][k]);
      const Eigen::Vector3d moved = cofactor(J) * document.normals.row(n).transpose();
      // A vanishing result (a singular J along n) has no direction; relative to |J|^2 |n| like cof itself.
      const double scale = J.squaredNorm() * document.normals.row(n).norm();
      if (!J.allFinite() || !(moved.norm() > 1e-12 * scale)) {
        usable[static_cast<size_t>(n)] = 0;
        continue;
      }
      sums.row(n) += moved.normalized().transpose();
    }
  }
  TransformedNormals out;
  out.normals = document.normals;
  Eigen::MatrixXd recomputed;
  for (int n = 0; n < document.normalCount; ++n) {
    if (usable[static_cast<size_t>(n)] && sums.row(n).norm() > 0.0) {
      out.normals.row(n) = sums.row(n).normalized();
      continue;
    }
    if (usable[static_cast<size_t>(n)]) continue;  // named by no face (or its corners' normals cancel): kept
    if (recomputed.size() == 0) recomputed = recomputeNormals(document, positions);
    out.normals.row(n) = recomputed.row(n);
    out.recomputed += 1;
  }
  return out;
}

TransformedNormals transformNormals(const MeshDocument& document, const Eigen::MatrixXd& positions,
                                    const DeformationGradients& gradients, const Eigen::MatrixXd& posedVertices,
                                    const DeformParams& params) {
  Eigen::MatrixXd deformed, jacobians;
  gradients.evaluate(posedVertices, params, deformed, jacobians);
  return transformNormals(document, positions, jacobians);
}

}  // namespace somicage
