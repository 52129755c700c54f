#include "model/pose_clear.h"

#include <Eigen/Dense>
#include <algorithm>

namespace somicage::editor {

namespace {

Eigen::VectorXd centroid(const Eigen::MatrixXd& m, const std::vector<int>& indices) {
  Eigen::VectorXd c = Eigen::VectorXd::Zero(m.cols());
  for (int i : indices) c += m.row(i).transpose();
  return c / static_cast<double>(indices.size());
}

}  // namespace

const char* clearKindName(ClearKind kind) {
  switch (kind) {
    case ClearKind::Location:
      return "Clear location";
    case ClearKind::Rotation:
      return "Clear rotation";
    case ClearKind::Scale:
      return "Clear scale";
  }
  return "?";
}

Eigen::MatrixXd clearTransform(ClearKind kind, const Eigen::MatrixXd& rest, const Eigen::MatrixXd& pose,
                               const std::vector<int>& indices) {
  Eigen::MatrixXd out = pose;
  if (indices.empty()) return out;
  const Eigen::VectorXd cRest = centroid(rest, indices), cPose = centroid(pose, indices);
  if (kind == ClearKind::Location) {
    for (int i : indices) out.row(i) += (cRest - cPose).transpose();
    return out;
  }
  if (indices.size() < 2) return out;
  const Eigen::Index d = pose.cols();
  Eigen::MatrixXd cross = Eigen::MatrixXd::Zero(d, d), gram = Eigen::MatrixXd::Zero(d, d);
  for (int i : indices) {
    const Eigen::VectorXd p = pose.row(i).transpose() - cPose, r = rest.row(i).transpose() - cRest;
    cross += p * r.transpose();
    gram += r * r.transpose();
  }
  // A = cross gram^+ (the pseudo-inverse: flat or collinear selections fit in their own span).
  const Eigen::MatrixXd a = cross * gram.completeOrthogonalDecomposition().pseudoInverse();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::MatrixXd u = svd.matrixU();
  Eigen::VectorXd sigma = svd.singularValues();
  const Eigen::MatrixXd& v = svd.matrixV();
  if ((u * v.transpose()).determinant() < 0) {  // a reflection is no rotation: keep det R = +1
    u.col(d - 1) *= -1.0;
    sigma[d - 1] *= -1.0;
  }
  const Eigen::MatrixXd rotation = u * v.transpose();
  const double tiny = 1e-9 * std::max(1.0, sigma.cwiseAbs().maxCoeff());
  for (Eigen::Index k = 0; k < d; ++k) {
    if (std::abs(sigma[k]) < tiny) sigma[k] = 1.0;  // no extent in this direction: no scale to clear
  }
  // Rotation: x' = c + R^T (x - c). Scale: A = R S with S = V Sigma V^T, so x' = c + R S^-1 R^T (x - c).
  const Eigen::MatrixXd map =
      kind == ClearKind::Rotation
          ? Eigen::MatrixXd(rotation.transpose())
          : Eigen::MatrixXd(rotation * v * sigma.cwiseInverse().asDiagonal() * v.transpose() * rotation.transpose());
  for (int i : indices) out.row(i) = (cPose + map * (pose.row(i).transpose() - cPose)).transpose();
  return out;
}

}  // namespace somicage::editor
