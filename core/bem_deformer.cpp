#include "bem_deformer.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <utility>
#include <vector>

#include "bem_layer_integrals.h"
#include "bem_system.h"
#include "boundary_conditions.h"
#include "coordinate_gradients.h"
#include "errors.h"
#include "exterior_points.h"

namespace somicage {

namespace {

// Where a point's BEM integrals can be used: finite and reproducing constants (sum_i T_i = I, Eq. 9).
bool reliableRow(const BemLayerIntegrals& integrals, int p) {
  const int d = integrals.dim, terms = vertexTermCount(d);
  double sums[vertexTermCount(3)] = {0};
  const double* row = integrals.values.row(p).data();
  for (int i = 0; i < integrals.numVertices; ++i)
    for (int k = 0; k < terms; ++k) sums[k] += row[i * terms + k];
  return integrals.values.row(p).allFinite() && unityResidualOfSums(sums, d) <= kUnreliableResidual;
}

// C: the points' rows [integrals | x | 1 | 0] (inside) or [0 | x | 1] (exterior_points.h), then two rows per
// exterior point: its proxy's, and the proxy's anchor [0 | x_in | 1].
FrameCoordinates bemFrameCoordinates(const Cage& cage, const Eigen::MatrixXd& points, const PrecomputeOptions& options,
                                     const ProgressCallback& progress, PrecomputeDiagnostics& diagnostics) {
  const int d = cage.dim(), numPoints = static_cast<int>(points.rows());
  const BemLayerIntegrals integrals = integrateBemLayers(cage, points, {}, options.threads, progress);
  const int main = integrals.columns() + d + 1, columns = main + d + 1;
  diagnostics.winding = integrals.winding;
  diagnostics.regions.resize(static_cast<std::size_t>(numPoints));
  for (int p = 0; p < numPoints; ++p)
    diagnostics.regions[static_cast<std::size_t>(p)] = classifyPoint(integrals.winding(p), reliableRow(integrals, p));
  ExteriorPlan plan = planExteriorPoints(cage, points, diagnostics.regions, options.threads);
  const int exterior = static_cast<int>(plan.blends.size());
  CoordinateMatrix<double> C(numPoints + 2 * exterior, columns);
  auto writeRow = [&](const BemLayerIntegrals& from, const Eigen::MatrixXd& at, int p, bool inside, int row) {
    if (inside)
      C.row(row) << from.values.row(p), at.row(p), 1.0, Eigen::RowVectorXd::Zero(d + 1);
    else
      writeSimilarityRow(at, p, C.row(row).data(), columns);
  };
  for (int p = 0; p < numPoints; ++p)
    writeRow(integrals, points, p, diagnostics.regions[static_cast<std::size_t>(p)] == PointRegion::Inside, p);
  integrateProxies(cage, plan, [&](const Eigen::MatrixXd& proxies, const std::vector<int>& which) {
    const BemLayerIntegrals proxyIntegrals = integrateBemLayers(cage, proxies, {}, options.threads);
    std::vector<bool> reliable(which.size());
    for (std::size_t k = 0; k < which.size(); ++k) {
      reliable[k] = reliableRow(proxyIntegrals, static_cast<int>(k));
      writeRow(proxyIntegrals, proxies, static_cast<int>(k), reliable[k], numPoints + 2 * which[k]);
    }
    return reliable;
  });
  // A proxy that failed everywhere holds [0 | x_in | 1] like its anchor: its point follows S alone.
  for (int e = 0; e < exterior; ++e) writeRow(integrals, plan.proxies, e, false, numPoints + 2 * e + 1);
  FrameCoordinates frame = makeFrameCoordinates(std::move(C), main, options.floatStorage);
  frame.exteriorBlends = std::move(plan.blends);
  return frame;
}

class BemDeformer final : public CageDeformer {
 public:
  BemDeformer(const Cage& rest, const Eigen::MatrixXd& points, const PrecomputeOptions& options,
              const ProgressCallback& progress)
      : CageDeformer(FrameCoordinates{}, options.threads), system_(rest, options.threads) {
    // Progress is the points' integration: the collocation rows (F^2 pairs) are a small fraction of it.
    coordinates_ = bemFrameCoordinates(rest, points, options, progress, diagnostics_);
  }

  Method method() const override { return Method::Bem; }
  int dim() const override { return system_.restCage().dim(); }

  // C's inside rows are [integrals | x | 1 | 0]: their gradients [d integrals | e_a | 0 | 0]; zero elsewhere.
  std::vector<FrameCoordinates> coordinateGradients(const Eigen::MatrixXd& points,
                                                    const ProgressCallback& progress) const override {
    const int d = dim(), columns = coordinates_.columns(), main = coordinates_.mainColumns;
    const int integralColumns = main - d - 1;
    std::vector<CoordinateMatrix<double>> gradients(static_cast<std::size_t>(d));
    for (auto& g : gradients) g.setZero(points.rows(), columns);
    integrateBemLayerGradients(system_.restCage(), points, threads_, progress, [&](int p, const double* const* rows) {
      if (diagnostics_.regions[static_cast<std::size_t>(p)] != PointRegion::Inside) return;
      for (int a = 0; a < d; ++a) {
        std::copy(rows[a], rows[a] + integralColumns, gradients[static_cast<std::size_t>(a)].row(p).data());
        gradients[static_cast<std::size_t>(a)](p, integralColumns + a) = 1;
      }
    });
    std::vector<FrameCoordinates> frames;
    for (auto& g : gradients) frames.push_back(makeFrameCoordinates(std::move(g), main, coordinates_.isFloat()));
    return frames;
  }

  FrameWeights frameWeights(const Eigen::MatrixXd& posed, const DeformParams& params) const override {
    validateBemPoissonRatio(params.nu);
    const Cage& rest = system_.restCage();
    const int d = dim(), terms = vertexTermCount(d), faceTerms = bemFaceTermCount(d);
    SOMICAGE_ASSERT(posed.rows() == rest.numVertices() && posed.cols() == d, "posed cage matches the rest cage");

    // ---- Corotation: the displacement without the best-fit rotation --------------------------------------------
    const Similarity fit = fitSimilarity(rest.vertices, posed);
    const Eigen::RowVectorXd restCentre = rest.vertices.colwise().mean(), posedCentre = posed.colwise().mean();
    Eigen::MatrixXd R = Eigen::MatrixXd::Identity(d, d);
    Eigen::MatrixXd u = posed - rest.vertices;
    if (params.corotational) {
      R = fit.rotation;
      u = ((posed.rowwise() - posedCentre) * R).rowwise() + restCentre - rest.vertices;
    }
    const BemSolution solution = system_.solve(*factorization(params.nu), u);

    // ---- W: every stored term's weight is the matrix it carries (T_i, K_j are linear in them) times its data ----
    FrameWeights W;
    W.outputs = d;
    W.main = Eigen::MatrixXd::Zero(coordinates_.mainColumns, d);
    std::vector<double> unit(static_cast<std::size_t>(std::max(terms, faceTerms)), 0.0);
    for (int k = 0; k < terms; ++k) {
      unit[static_cast<std::size_t>(k)] = 1;
      const Eigen::MatrixXd E = R * assembleVertexCoordinate(unit.data(), d, params.nu);
      unit[static_cast<std::size_t>(k)] = 0;
      for (int i = 0; i < rest.numVertices(); ++i) W.main.row(i * terms + k) = (E * u.row(i).transpose()).transpose();
    }
    const int faceStart = rest.numVertices() * terms;
    for (int k = 0; k < faceTerms; ++k) {
      unit[static_cast<std::size_t>(k)] = 1;
      const Eigen::MatrixXd E = R * assembleFaceKelvinlet(unit.data(), d, params.nu);
      unit[static_cast<std::size_t>(k)] = 0;
      for (int j = 0; j < rest.numFaces(); ++j)
        W.main.row(faceStart + j * faceTerms + k) = (E * solution.tractions.row(j).transpose()).transpose();
    }
    const int xStart = faceStart + rest.numFaces() * faceTerms;
    W.main.middleRows(xStart, d) = R.transpose();  // row a: R e_a
    const Eigen::VectorXd shift = params.corotational
                                      ? Eigen::VectorXd(posedCentre.transpose() - R * restCentre.transpose())
                                      : Eigen::VectorXd::Zero(d);
    W.main.row(xStart + d) = (shift + R * solution.omega).transpose();
    // Rows [0 | x | 1] (exterior points): the similarity S(x) = s R x + t.
    W.tail.resize(d + 1, d);
    W.tail.topRows(d) = (fit.scale * fit.rotation).transpose();
    W.tail.row(d) = fit.translation.transpose();
    return W;
  }

 private:
  // The factored boundary matrix at nu, kept for the last nu (a slider change re-factors, a pose change does not).
  std::shared_ptr<const BemFactorization> factorization(double nu) const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!factorization_ || !(factorization_->nu == nu)) factorization_ = system_.factor(nu);
    return factorization_;
  }

  BemSystem system_;
  mutable std::mutex mutex_;
  mutable std::shared_ptr<const BemFactorization> factorization_;
};

}  // namespace

std::unique_ptr<CageDeformer> makeBemDeformer(const Cage& restCage, const Eigen::MatrixXd& points,
                                              const PrecomputeOptions& options, const ProgressCallback& progress) {
  return std::make_unique<BemDeformer>(restCage, points, options, progress);
}

}  // namespace somicage
