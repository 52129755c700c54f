#include "coordinates/elastic_steiner_solve.h"

#include <cmath>
#include <string>

#include "base/errors.h"

namespace somicage {

namespace {

// Rows and columns `rows` x `cols` of the vertex-major matrix K (d per vertex).
Eigen::SparseMatrix<double> block(const Eigen::SparseMatrix<double>& K, const std::vector<int>& rows,
                                  const std::vector<int>& cols, int d) {
  std::vector<int> colIndex(static_cast<std::size_t>(K.cols()), -1), rowIndex(static_cast<std::size_t>(K.rows()), -1);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int a = 0; a < d; ++a) rowIndex[static_cast<std::size_t>(rows[i] * d + a)] = static_cast<int>(i) * d + a;
  for (std::size_t i = 0; i < cols.size(); ++i)
    for (int a = 0; a < d; ++a) colIndex[static_cast<std::size_t>(cols[i] * d + a)] = static_cast<int>(i) * d + a;
  std::vector<Eigen::Triplet<double>> entries;
  for (int c = 0; c < K.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, c); it; ++it) {
      const int r = rowIndex[static_cast<std::size_t>(it.row())], k = colIndex[static_cast<std::size_t>(it.col())];
      if (r >= 0 && k >= 0) entries.emplace_back(r, k, it.value());
    }
  Eigen::SparseMatrix<double> out(static_cast<Eigen::Index>(rows.size()) * d,
                                  static_cast<Eigen::Index>(cols.size()) * d);
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

}  // namespace

std::vector<bool> interiorSteinerVertices(const VolumeMesh& mesh, int cageVertices) {
  std::vector<bool> interior(static_cast<std::size_t>(mesh.numVertices()), false);
  for (int v = cageVertices; v < mesh.numVertices(); ++v) interior[static_cast<std::size_t>(v)] = true;
  for (const BoundaryFace& f : boundaryFaces(mesh))
    for (int k = 0; k <= mesh.dim(); ++k)
      if (k != f.opposite) interior[static_cast<std::size_t>(mesh.simplices(f.simplex, k))] = false;
  return interior;
}

double lameLambda(double nu) { return 2 * nu / (1 - 2 * nu); }

bool elasticEnergyPositiveDefinite(double nu, int dim) {
  if (!std::isfinite(nu) || nu >= 0.5) return false;
  // mu |eps|^2 + lambda/2 tr(eps)^2 > 0 for every symmetric eps != 0 iff mu > 0 and mu + d lambda / 2 > 0 (eps = I).
  return 1 + dim * lameLambda(nu) / 2 > 0;
}

ElasticSteinerSolver::ElasticSteinerSolver(const VolumeMesh& rest, const std::vector<bool>& free)
    : rest_(rest.vertices) {
  const int d = rest.dim(), n = rest.numVertices();
  for (int v = 0; v < n; ++v) (free[static_cast<std::size_t>(v)] ? freeVertices_ : knownVertices_).push_back(v);
  // Element stiffness of E_t = V (mu eps:eps + lambda/2 tr(eps)^2) with grad u = sum_i u_i g_i^T (g_i the
  // barycentric gradients): d2E/du_ia du_jb = V (mu (delta_ab g_i.g_j + g_ib g_ja) + lambda g_ia g_jb).
  std::vector<Eigen::Triplet<double>> mu, lambda;
  const std::vector<Eigen::MatrixXd> gradients = barycentricGradients(rest);
  for (int s = 0; s < rest.numSimplices(); ++s) {
    const double volume = std::abs(signedSimplexMeasure(rest, s));
    const Eigen::MatrixXd& g = gradients[static_cast<std::size_t>(s)];
    for (int i = 0; i <= d; ++i)
      for (int j = 0; j <= d; ++j)
        for (int a = 0; a < d; ++a)
          for (int b = 0; b < d; ++b) {
            const int row = rest.simplices(s, i) * d + a, col = rest.simplices(s, j) * d + b;
            mu.emplace_back(row, col, volume * ((a == b ? g.row(i).dot(g.row(j)) : 0.0) + g(i, b) * g(j, a)));
            lambda.emplace_back(row, col, volume * g(i, a) * g(j, b));
          }
  }
  kMu_.resize(n * d, n * d);
  kMu_.setFromTriplets(mu.begin(), mu.end());
  kLambda_.resize(n * d, n * d);
  kLambda_.setFromTriplets(lambda.begin(), lambda.end());
  freeFreeMu_ = block(kMu_, freeVertices_, freeVertices_, d);
  freeFreeLambda_ = block(kLambda_, freeVertices_, freeVertices_, d);
  freeKnownMu_ = block(kMu_, freeVertices_, knownVertices_, d);
  freeKnownLambda_ = block(kLambda_, freeVertices_, knownVertices_, d);
}

Eigen::SparseMatrix<double> ElasticSteinerSolver::stiffness(double nu) const {
  return kMu_ + lameLambda(nu) * kLambda_;
}

void ElasticSteinerSolver::factor(double nu) {
  if (factored_ && nu == nu_) return;
  const int d = static_cast<int>(rest_.cols());
  if (!elasticEnergyPositiveDefinite(nu, d))
    throw InputError("nu", -1,
                     "Poisson ratio " + std::to_string(nu) +
                         " makes the elastic energy of the Steiner vertices "
                         "indefinite (lambda = 2 nu / (1 - 2 nu) needs mu + " +
                         std::to_string(d) + " lambda / 2 > 0), so they would have no resting place",
                     d == 3 ? "use a finite nu in (-1, 0.5)" : "use a finite nu below 0.5");
  freeKnown_ = freeKnownMu_ + lameLambda(nu) * freeKnownLambda_;
  factor_ = std::make_unique<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>();
  if (freeCount() > 0) {
    factor_->compute(freeFreeMu_ + lameLambda(nu) * freeFreeLambda_);
    if (factor_->info() != Eigen::Success || !(factor_->vectorD().minCoeff() > 0))
      throw InputError("nu", -1, "the elastic system of the Steiner vertices is singular at nu = " + std::to_string(nu),
                       "the volume mesh may have flat elements: mesh the cage again");
  }
  nu_ = nu;
  factored_ = true;
}

void ElasticSteinerSolver::solve(Eigen::MatrixXd& positions) const {
  SOMICAGE_ASSERT(factored_, "the solver is factored before a solve");
  if (freeVertices_.empty()) return;
  const int d = static_cast<int>(rest_.cols());
  Eigen::VectorXd known(static_cast<Eigen::Index>(knownVertices_.size()) * d);
  for (std::size_t i = 0; i < knownVertices_.size(); ++i)
    known.segment(static_cast<Eigen::Index>(i) * d, d) =
        (positions.row(knownVertices_[i]) - rest_.row(knownVertices_[i])).transpose();
  // The editor asks twice per frame (the points' weights, the tetrahedra's wireframe): the same pose is solved once.
  if (!(lastNu_ == nu_ && known.size() == lastKnown_.size() && known == lastKnown_)) {
    lastU_ = factor_->solve(-(freeKnown_ * known));
    lastKnown_ = std::move(known);
    lastNu_ = nu_;
    ++solves_;
  }
  const Eigen::VectorXd& u = lastU_;
  for (std::size_t i = 0; i < freeVertices_.size(); ++i)
    positions.row(freeVertices_[i]) =
        rest_.row(freeVertices_[i]) + u.segment(static_cast<Eigen::Index>(i) * d, d).transpose();
}

}  // namespace somicage
