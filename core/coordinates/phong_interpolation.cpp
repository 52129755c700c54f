#include "coordinates/phong_interpolation.h"

#include <Eigen/LU>

namespace somicage {

PhongVertexWeights phongVertexWeights(const VolumeMesh& rest) {
  const int d = rest.dim(), n = rest.numVertices();
  std::vector<std::vector<int>> incident(static_cast<std::size_t>(n));
  for (int s = 0; s < rest.numSimplices(); ++s)
    for (int k = 0; k <= d; ++k) incident[static_cast<std::size_t>(rest.simplices(s, k))].push_back(s);
  PhongVertexWeights out;
  out.start.push_back(0);
  for (int v = 0; v < n; ++v) {
    const std::vector<int>& star = incident[static_cast<std::size_t>(v)];
    Eigen::MatrixXd directions(d, static_cast<Eigen::Index>(star.size()));
    Eigen::VectorXd lengths(static_cast<Eigen::Index>(star.size()));
    for (std::size_t t = 0; t < star.size(); ++t) {
      Eigen::VectorXd centroid = Eigen::VectorXd::Zero(d);
      for (int k = 0; k <= d; ++k) centroid += rest.vertices.row(rest.simplices(star[t], k)).transpose();
      const Eigen::VectorXd r = centroid / (d + 1) - rest.vertices.row(v).transpose();
      lengths(static_cast<Eigen::Index>(t)) = r.norm();
      directions.col(static_cast<Eigen::Index>(t)) = r / r.norm();
    }
    const Eigen::MatrixXd M = Eigen::MatrixXd::Identity(d, d) + directions * directions.transpose();
    const Eigen::VectorXd a = M.partialPivLu().solve(-directions.rowwise().sum());
    double sum = 0;
    const std::size_t first = out.weight.size();
    for (std::size_t t = 0; t < star.size(); ++t) {
      const double w =
          (1 + a.dot(directions.col(static_cast<Eigen::Index>(t)))) / lengths(static_cast<Eigen::Index>(t));
      out.simplex.push_back(star[t]);
      out.weight.push_back(w);
      sum += w;
    }
    for (std::size_t k = first; k < out.weight.size(); ++k) out.weight[k] /= sum;
    out.start.push_back(static_cast<int>(out.weight.size()));
  }
  return out;
}

std::vector<Eigen::MatrixXd> simplexGradients(const VolumeMesh& rest, const std::vector<Eigen::MatrixXd>& gradients,
                                              const Eigen::MatrixXd& positions) {
  const int d = rest.dim();
  std::vector<Eigen::MatrixXd> out(static_cast<std::size_t>(rest.numSimplices()), Eigen::MatrixXd::Zero(d, d));
  for (int s = 0; s < rest.numSimplices(); ++s)
    for (int k = 0; k <= d; ++k)
      out[static_cast<std::size_t>(s)] +=
          positions.row(rest.simplices(s, k)).transpose() * gradients[static_cast<std::size_t>(s)].row(k);
  return out;
}

std::vector<Eigen::MatrixXd> vertexGradients(const PhongVertexWeights& weights,
                                             const std::vector<Eigen::MatrixXd>& simplexF) {
  const std::size_t n = weights.start.size() - 1;
  const Eigen::Index d = simplexF.empty() ? 0 : simplexF.front().rows();
  std::vector<Eigen::MatrixXd> out(n, Eigen::MatrixXd::Zero(d, d));
  for (std::size_t v = 0; v < n; ++v)
    for (int k = weights.start[v]; k < weights.start[v + 1]; ++k)
      out[v] += weights.weight[static_cast<std::size_t>(k)] *
                simplexF[static_cast<std::size_t>(weights.simplex[static_cast<std::size_t>(k)])];
  return out;
}

}  // namespace somicage
