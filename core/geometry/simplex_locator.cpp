#include "geometry/simplex_locator.h"

#include <algorithm>
#include <cmath>

namespace somicage {

SimplexLocator::SimplexLocator(const VolumeMesh& mesh) : mesh_(mesh), gradients_(barycentricGradients(mesh)) {
  const int d = mesh.dim(), count = mesh.numSimplices();
  lower_ = mesh.vertices.colwise().minCoeff().transpose();
  const Eigen::VectorXd extent = mesh.vertices.colwise().maxCoeff().transpose() - lower_;
  // About one simplex per cell: #S^(1/d) cells per axis, at least one.
  const int perAxis = std::max(1, static_cast<int>(std::ceil(std::pow(static_cast<double>(count), 1.0 / d))));
  cells_ = Eigen::VectorXi::Constant(d, perAxis);
  cellSize_ = (extent / perAxis).cwiseMax(1e-300);
  buckets_.resize(static_cast<std::size_t>(cells_.prod()));
  for (int s = 0; s < count; ++s) {
    Eigen::VectorXd lo = Eigen::VectorXd::Constant(d, INFINITY), hi = Eigen::VectorXd::Constant(d, -INFINITY);
    for (int k = 0; k <= d; ++k) {
      lo = lo.cwiseMin(mesh.vertices.row(mesh.simplices(s, k)).transpose());
      hi = hi.cwiseMax(mesh.vertices.row(mesh.simplices(s, k)).transpose());
    }
    Eigen::VectorXi from(d), to(d);
    for (int a = 0; a < d; ++a) {
      // Widened by a cell's millionth so that a point on a cell border finds the simplices of both cells.
      from(a) = std::clamp(static_cast<int>(std::floor((lo(a) - lower_(a)) / cellSize_(a) - 1e-6)), 0, cells_(a) - 1);
      to(a) = std::clamp(static_cast<int>(std::floor((hi(a) - lower_(a)) / cellSize_(a) + 1e-6)), 0, cells_(a) - 1);
    }
    Eigen::VectorXi cell = from;
    while (true) {
      buckets_[static_cast<std::size_t>(cellIndex(cell))].push_back(s);
      int a = 0;
      while (a < d && cell(a) == to(a)) cell(a) = from(a), ++a;
      if (a == d) break;
      ++cell(a);
    }
  }
}

int SimplexLocator::cellIndex(const Eigen::VectorXi& cell) const {
  int index = 0;
  for (int a = static_cast<int>(cell.size()) - 1; a >= 0; --a) index = index * cells_(a) + cell(a);
  return index;
}

Eigen::VectorXd SimplexLocator::barycentric(int s, const Eigen::VectorXd& x) const {
  const int d = mesh_.dim();
  Eigen::VectorXd lambda(d + 1);
  lambda.tail(d) = gradients(s).bottomRows(d) * (x - mesh_.vertices.row(mesh_.simplices(s, 0)).transpose());
  lambda(0) = 1 - lambda.tail(d).sum();
  return lambda;
}

SimplexLocator::Location SimplexLocator::locate(const Eigen::VectorXd& x) const {
  const int d = mesh_.dim();
  Location best;
  Eigen::VectorXi cell(d);
  for (int a = 0; a < d; ++a) {
    const double t = std::floor((x(a) - lower_(a)) / cellSize_(a));
    if (!(t >= -1 && t <= cells_(a))) return best;  // outside the mesh's box (or not finite)
    cell(a) = std::clamp(static_cast<int>(t), 0, cells_(a) - 1);
  }
  double deepest = -kTolerance;
  for (int s : buckets_[static_cast<std::size_t>(cellIndex(cell))]) {
    Eigen::VectorXd lambda = barycentric(s, x);
    if (lambda.minCoeff() >= deepest) {
      deepest = lambda.minCoeff();
      best.simplex = s;
      best.barycentric = std::move(lambda);
    }
  }
  return best;
}

}  // namespace somicage
