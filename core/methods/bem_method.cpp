// The boundary element reference method (bem_system.h): the linear-elastic solution of the pose, and its method
// descriptor (method.h).
//
// Precompute: the boundary system of the rest cage and, per point x, the integrals T_i(x), K_j(x)
// (bem_layer_integrals.h). A frame: the displacement u = posed - rest at the cage vertices, the tractions t_j
// from one triangular solve (the LU of the boundary matrix is kept per nu), and the interior displacement
//   x~ = x + sum_i T_i(x) u_i + sum_j K_j(x) t_j + omega                        (Somigliana identity, Eq. 2)
// as one product C W (frame_evaluation.h) with C = [vertex terms | face terms (S, M) | x | 1 | x | 1] (bemLayout):
// the integrals and the tail's first [x | 1] are the interior formula, the tail's last d + 1 columns the similarity
// row of exterior points (exterior_points.h).
//
// DeformParams::corotational removes the cage's best-fit rotation R (Umeyama, as the global Somigliana variant
// fits it) before the solve and applies it after: u'_i = R^T (v~_i - m~) + m - v_i about the rest and posed
// centroids m, m~, and x~ = m~ + R (x + u'(x) - m). Rigid motions are then exact; without it a large rotation of
// the cage shears and inflates the mesh, as linear elasticity does. Off by default. DeformParams::nu is the Poisson
// ratio (validateBemPoissonRatio); blend, gamma and tractionCorrection are ignored.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "base/errors.h"
#include "coordinates/bem_layer_integrals.h"
#include "coordinates/bem_system.h"
#include "coordinates/coordinate_gradients.h"
#include "deform/boundary_conditions.h"
#include "deform/deformer.h"
#include "deform/exterior_points.h"
#include "methods/method_descriptors.h"

namespace somicage {

namespace {

// C = [integrals (bemLayerLayout) | x | 1 | x | 1]: the tail's first d + 1 columns are the interior formula's, the
// last d + 1 the exterior similarity's.
CoordinateLayout bemLayout(int dim, int numVertices, int numFaces) {
  CoordinateLayout layout = bemLayerLayout(dim, numVertices, numFaces);
  layout.tailColumns = 2 * (dim + 1);
  return layout;
}

// DeformParams' ranges, and nu = 0.5 refused with its reason (bem_system.h).
void validateBemParams(const DeformParams& params) {
  validateBemPoissonRatio(params.nu);
  validateDeformParams(params);
}

// Where a point's BEM integrals can be used: finite and reproducing constants (sum_i T_i = I, Eq. 9).
bool reliableRow(const BemLayerIntegrals& integrals, int p) {
  const CoordinateLayout& layout = integrals.layout;
  double sums[vertexTermCount(3)] = {0};
  const double* row = integrals.values.row(p).data();
  for (int k = 0; k < layout.vertexTerms; ++k)
    for (int i = 0; i < layout.numVertices; ++i) sums[k] += row[layout.vertexColumn(i, k)];
  return integrals.values.row(p).allFinite() && unityResidualOfSums(sums, integrals.dim) <= kUnreliableResidual;
}

// C (bemLayout): the points' rows [integrals | x | 1 | 0] (inside) or [0 | x | 1] (exterior_points.h), then two
// rows per exterior point: its proxy's, and the proxy's anchor [0 | x_in | 1].
FrameCoordinates bemFrameCoordinates(const Cage& cage, const Eigen::MatrixXd& points, const PrecomputeOptions& options,
                                     const ProgressCallback& progress, PrecomputeDiagnostics& diagnostics) {
  const int d = cage.dim(), numPoints = static_cast<int>(points.rows());
  const BemLayerIntegrals integrals = integrateBemLayers(cage, points, {}, options.threads, progress);
  const CoordinateLayout layout = bemLayout(d, cage.numVertices(), cage.numFaces());
  const int main = layout.mainColumns(), columns = layout.columns();
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
      : CageDeformer(FrameCoordinates{}, options.threads),
        system_(rest, options.threads),
        layout_(bemLayout(rest.dim(), rest.numVertices(), rest.numFaces())) {
    // Progress is the points' integration: the collocation rows (F^2 pairs) are a small fraction of it.
    coordinates_ = bemFrameCoordinates(rest, points, options, progress, diagnostics_);
  }

  Method method() const override { return methods::bem(); }
  int dim() const override { return system_.restCage().dim(); }

  // C's inside rows are [integrals | x | 1 | 0]: their gradients [d integrals | e_a | 0 | 0]; zero elsewhere.
  std::vector<FrameCoordinates> coordinateGradients(const Eigen::MatrixXd& points,
                                                    const ProgressCallback& progress) const override {
    const int d = dim(), main = layout_.mainColumns();
    std::vector<CoordinateMatrix<double>> gradients(static_cast<std::size_t>(d));
    for (auto& g : gradients) g.setZero(points.rows(), layout_.columns());
    integrateBemLayerGradients(system_.restCage(), points, threads_, progress, [&](int p, const double* const* rows) {
      if (diagnostics_.regions[static_cast<std::size_t>(p)] != PointRegion::Inside) return;
      for (int a = 0; a < d; ++a) {
        std::copy(rows[a], rows[a] + main, gradients[static_cast<std::size_t>(a)].row(p).data());
        gradients[static_cast<std::size_t>(a)](p, layout_.tailColumn(a)) = 1;
      }
    });
    std::vector<FrameCoordinates> frames;
    for (auto& g : gradients) frames.push_back(makeFrameCoordinates(std::move(g), main, coordinates_.isFloat()));
    return frames;
  }

  FrameWeights frameWeights(const Eigen::MatrixXd& posed, const DeformParams& params) const override {
    validateBemParams(params);
    const Cage& rest = system_.restCage();
    const int d = dim(), terms = layout_.vertexTerms, faceTerms = layout_.faceTerms;
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
    const BemSolution solution = system_.solve(*system_.factorization(params.nu), u);

    // ---- W: every stored term's weight is the matrix it carries (T_i, K_j are linear in them) times its data ----
    FrameWeights W;
    W.outputs = d;
    W.main = Eigen::MatrixXd::Zero(layout_.mainColumns(), d);
    std::vector<double> unit(static_cast<std::size_t>(std::max(terms, faceTerms)), 0.0);
    for (int k = 0; k < terms; ++k) {
      unit[static_cast<std::size_t>(k)] = 1;
      const Eigen::MatrixXd E = R * assembleVertexCoordinate(unit.data(), d, params.nu);
      unit[static_cast<std::size_t>(k)] = 0;
      for (int i = 0; i < rest.numVertices(); ++i)
        W.main.row(layout_.vertexColumn(i, k)) = (E * u.row(i).transpose()).transpose();
    }
    for (int k = 0; k < faceTerms; ++k) {
      unit[static_cast<std::size_t>(k)] = 1;
      const Eigen::MatrixXd E = R * assembleFaceKelvinlet(unit.data(), d, params.nu);
      unit[static_cast<std::size_t>(k)] = 0;
      for (int j = 0; j < rest.numFaces(); ++j)
        W.main.row(layout_.faceColumn(j, k)) = (E * solution.tractions.row(j).transpose()).transpose();
    }
    // The tail's interior [x | 1]: R x + shift + R omega.
    W.tail.resize(layout_.tailColumns, d);
    W.tail.topRows(d) = R.transpose();  // row a: R e_a
    const Eigen::VectorXd shift = params.corotational
                                      ? Eigen::VectorXd(posedCentre.transpose() - R * restCentre.transpose())
                                      : Eigen::VectorXd::Zero(d);
    W.tail.row(d) = (shift + R * solution.omega).transpose();
    // The tail's exterior [x | 1] (rows [0 | x | 1] of exterior points): the similarity S(x) = s R x + t.
    W.tail.middleRows(d + 1, d) = (fit.scale * fit.rotation).transpose();
    W.tail.row(2 * d + 1) = fit.translation.transpose();
    return W;
  }

 private:
  BemSystem system_;  // with its factorizations per nu (bem_system.h: a pose change never re-factors)
  CoordinateLayout layout_;
};

std::unique_ptr<CageDeformer> precomputeBem(const Cage& restCage, const Eigen::MatrixXd& points,
                                            const PrecomputeOptions& options, const ProgressCallback& progress) {
  return std::make_unique<BemDeformer>(restCage, points, options, progress);
}

// The integrals in double while C is assembled (and converted to float), the winding numbers, and the boundary
// matrix of n = d (#F + 1) unknowns with its LU and data operator (bem_system.h).
std::size_t bemWorkingBytes(const CoordinateLayout& layout, int dim, std::size_t points, bool floatStorage, int) {
  const std::size_t n = static_cast<std::size_t>(dim) * (static_cast<std::size_t>(layout.numFaces) + 1);
  return points * static_cast<std::size_t>(layout.mainColumns()) * sizeof(double) +
         (floatStorage ? layout.bytes(points, false) : 0) + points * sizeof(double) +
         (3 * n + static_cast<std::size_t>(dim) * static_cast<std::size_t>(layout.numVertices)) * n * sizeof(double);
}

}  // namespace

namespace methods {

const MethodDescriptor& bem() {
  static const MethodDescriptor descriptor{
      "bem",
      "BEM",
      "The linear-elastic solution of each pose by boundary elements (Eq. 2): the reference, slow",
      3,
      kParamNu | kParamCorotational,
      false,
      false,
      {},
      validateBemParams,
      bemLayout,
      bemWorkingBytes,
      precomputeBem,
      FrameFinish::Linear,
      kFieldVertex | kFieldFace};  // its layers are Somigliana's Kelvin kernels at its nu
  return descriptor;
}

}  // namespace methods

}  // namespace somicage
