#include "coordinates/bem_system.h"

#include <algorithm>
#include <cmath>
#include <list>
#include <mutex>
#include <string>
#include <vector>

#include "base/errors.h"

namespace somicage {

void validateBemPoissonRatio(double nu) {
  if (nu == 0.5)
    throw InputError("nu", -1, "the boundary element method cannot use nu = 0.5 (incompressible)",
                     "the pressure is undetermined there and the boundary matrix is singular: use nu <= 0.49");
  if (std::isnan(nu) || (!std::isinf(nu) && (nu <= -1 || nu > 0.5)))
    throw InputError("nu", -1, "Poisson ratio " + std::to_string(nu) + " is out of range",
                     "use a value in (-1, 0.5), or inf / -inf for the limit");
}

BemSystem::BemSystem(const Cage& restCage, int threads, const ProgressCallback& progress)
    : rest_(restCage),
      areas_(faceAreas(restCage, restCage.vertices)),
      lengthScale_(cageDiameter(restCage.vertices)),
      cache_(std::make_shared<FactorizationCache>()) {
  const int d = rest_.dim();
  centroids_ = Eigen::MatrixXd::Zero(rest_.numFaces(), d);
  std::vector<int> own(static_cast<std::size_t>(rest_.numFaces()));
  for (int j = 0; j < rest_.numFaces(); ++j) {
    for (int k = 0; k < d; ++k) centroids_.row(j) += rest_.vertices.row(rest_.faces(j, k)) / d;
    own[static_cast<std::size_t>(j)] = j;
  }
  integrals_ = integrateBemLayers(rest_, centroids_, own, threads, progress);
  if (!(lengthScale_ > 0)) lengthScale_ = 1;
}

struct BemSystem::FactorizationCache {
  std::mutex mutex;
  std::list<std::shared_ptr<const BemFactorization>> recent;  // most recently used first
  std::size_t made = 0;
};

std::shared_ptr<const BemFactorization> BemSystem::factorization(double nu) const {
  std::lock_guard<std::mutex> lock(cache_->mutex);
  auto& recent = cache_->recent;
  // nu compares exactly (the views' and the sweep's values repeat bitwise); +-inf equal themselves.
  const auto hit = std::find_if(recent.begin(), recent.end(), [nu](const auto& f) { return f->nu == nu; });
  if (hit != recent.end()) {
    recent.splice(recent.begin(), recent, hit);
    return recent.front();
  }
  recent.push_front(factor(nu));
  ++cache_->made;
  const std::size_t n = static_cast<std::size_t>(recent.front()->lu.rows());
  const std::size_t bytes = sizeof(double) * n * (n + static_cast<std::size_t>(recent.front()->dataOperator.cols()));
  const std::size_t capacity = std::max<std::size_t>(1, std::min(kCachedFactorizations, kCacheBytes / bytes));
  while (recent.size() > capacity) recent.pop_back();
  return recent.front();
}

std::size_t BemSystem::factorizationsMade() const {
  std::lock_guard<std::mutex> lock(cache_->mutex);
  return cache_->made;
}

std::shared_ptr<const BemFactorization> BemSystem::factor(double nu) const {
  validateBemPoissonRatio(nu);
  const int d = rest_.dim(), F = rest_.numFaces(), V = rest_.numVertices(), n = d * F + d;
  // Rows: the collocation equations (d per face), then the balance. Columns: t_j (d per face), then omega / L.
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, n);
  auto factorization = std::make_shared<BemFactorization>();
  factorization->nu = nu;
  Eigen::MatrixXd& data = factorization->dataOperator;
  data = Eigen::MatrixXd::Zero(n, d * V);
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(d, d);
  for (int c = 0; c < F; ++c) {
    for (int j = 0; j < F; ++j) G.block(d * c, d * j, d, d) = integrals_.faceKelvinlet(c, j, nu);
    G.block(d * c, d * F, d, d) = lengthScale_ * I;
    // u(x_c) - sum_i T_i(x_c-) u_i, with u(x_c) the mean of the face's corners (u is linear on the face).
    for (int i = 0; i < V; ++i) data.block(d * c, d * i, d, d) = -integrals_.vertexCoordinate(c, i, nu);
    for (int k = 0; k < d; ++k) data.block(d * c, d * rest_.faces(c, k), d, d) += I / d;
  }
  for (int j = 0; j < F; ++j) G.block(d * F, d * j, d, d) = (areas_(j) / lengthScale_) * I;
  factorization->lu.compute(G);
  return factorization;
}

BemSolution BemSystem::solve(const BemFactorization& factorization, const Eigen::MatrixXd& displacement) const {
  const int d = rest_.dim(), F = rest_.numFaces();
  SOMICAGE_ASSERT(displacement.rows() == rest_.numVertices() && displacement.cols() == d,
                  "one displacement per rest cage vertex");
  const Eigen::MatrixXd uRows = displacement.transpose();  // column-major d by #V: u_i blocks in order
  const Eigen::VectorXd u = Eigen::Map<const Eigen::VectorXd>(uRows.data(), uRows.size());
  const Eigen::VectorXd x = factorization.lu.solve(factorization.dataOperator * u);
  BemSolution solution;
  solution.tractions = Eigen::Map<const Eigen::MatrixXd>(x.data(), d, F).transpose();
  solution.omega = lengthScale_ * x.tail(d);
  return solution;
}

}  // namespace somicage
