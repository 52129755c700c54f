// Green coordinates as a deformation method (method.h): its layout, precompute, frame weights and descriptor.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "base/errors.h"
#include "coordinates/coordinate_gradients.h"
#include "coordinates/green_coordinates.h"
#include "deform/boundary_conditions.h"
#include "deform/deformer.h"
#include "deform/exterior_points.h"
#include "methods/method_descriptors.h"

namespace somicage {

namespace {

// C = [phi (#V) | psi (#F) | x | 1].
CoordinateLayout greenLayout(int dim, int numVertices, int numFaces) { return {numVertices, numFaces, 1, 1, dim + 1}; }

// Whether a point's Green coordinates can be used: finite, and reproducing constants (sum_i phi_i = 1).
bool reliableGreenRow(const GreenCoordinates& coords, int p) {
  return coords.phi.row(p).allFinite() && coords.psi.row(p).allFinite() &&
         std::abs(coords.phi.row(p).sum() - 1) <= kUnreliableResidual;
}

// C = [phi | psi | x | 1] (#P + 2 #E by #V + #F + d + 1); W = [v~ ; s_j n~_j ; (s R)^T ; t^T]:
// x~ = sum_i phi_i v~_i + sum_j psi_j s_j n~_j inside the cage. Outside it the coordinates reproduce nothing
// (sum_i phi_i = 0 there), so, as for the Somigliana deformer, such points (and points on the cage) get the row
// [0 | x | 1] and the two exterior rows of exterior_points.h: their proxy's coordinates and its anchor.
FrameCoordinates greenFrameCoordinates(const Cage& cage, const GreenCoordinates& coords, const Eigen::MatrixXd& points,
                                       const PrecomputeOptions& options, PrecomputeDiagnostics& diagnostics) {
  const int numPoints = static_cast<int>(points.rows());
  diagnostics.winding = coords.phi.rowwise().sum();  // the double layer of the hats sums to the winding number
  diagnostics.regions.resize(static_cast<std::size_t>(numPoints));
  for (int p = 0; p < numPoints; ++p) {
    diagnostics.regions[static_cast<std::size_t>(p)] =
        classifyPoint(diagnostics.winding(p), reliableGreenRow(coords, p));
  }
  ExteriorPlan plan = planExteriorPoints(cage, points, diagnostics.regions, options.threads);
  const int exterior = static_cast<int>(plan.blends.size());
  const CoordinateLayout layout = greenLayout(cage.dim(), cage.numVertices(), cage.numFaces());
  const int main = layout.mainColumns(), columns = layout.columns();
  CoordinateMatrix<double> C(numPoints + 2 * exterior, columns);
  auto writeRow = [&](const GreenCoordinates& from, const Eigen::MatrixXd& at, int p, bool useCoordinates, int row) {
    if (useCoordinates) {
      C.row(row) << from.phi.row(p), from.psi.row(p), Eigen::RowVectorXd::Zero(columns - main);
    } else {
      writeSimilarityRow(at, p, C.row(row).data(), columns);
    }
  };
  for (int p = 0; p < numPoints; ++p)
    writeRow(coords, points, p, diagnostics.regions[static_cast<std::size_t>(p)] == PointRegion::Inside, p);
  integrateProxies(cage, plan, [&](const Eigen::MatrixXd& proxies, const std::vector<int>& which) {
    const GreenCoordinates proxyCoords = computeGreenCoordinates(cage, proxies, options.threads);
    std::vector<bool> reliable(which.size());
    for (std::size_t k = 0; k < which.size(); ++k) {
      const int e = which[k];
      reliable[k] = reliableGreenRow(proxyCoords, static_cast<int>(k));
      writeRow(proxyCoords, proxies, static_cast<int>(k), reliable[k], numPoints + 2 * e);
    }
    return reliable;
  });
  // A proxy that failed everywhere holds [0 | x_in | 1] like its anchor: its point follows S alone.
  for (int e = 0; e < exterior; ++e) writeRow(coords, plan.proxies, e, false, numPoints + 2 * e + 1);
  FrameCoordinates frame = makeFrameCoordinates(std::move(C), main, options.floatStorage);
  frame.exteriorBlends = std::move(plan.blends);
  return frame;
}

class GreenDeformer : public CageDeformer {
 public:
  GreenDeformer(const Cage& restCage, const GreenCoordinates& coords, const Eigen::MatrixXd& points,
                const PrecomputeOptions& options)
      : CageDeformer(FrameCoordinates{}, options.threads), rest_(restCage) {
    coordinates_ = greenFrameCoordinates(restCage, coords, points, options, diagnostics_);
  }

  Method method() const override { return methods::green(); }
  int dim() const override { return rest_.dim(); }

  // C's rows are [phi | psi | x | 1]: their gradients [dphi | dpsi | 0 | 0] (coordinate_gradients.h).
  std::vector<FrameCoordinates> coordinateGradients(const Eigen::MatrixXd& points,
                                                    const ProgressCallback& progress) const override {
    const int columns = coordinates_.columns(), main = coordinates_.mainColumns;
    std::vector<CoordinateMatrix<double>> gradients(static_cast<std::size_t>(dim()));
    for (auto& g : gradients) g.setZero(points.rows(), columns);
    integrateGreenGradients(rest_, points, threads_, progress, [&](int p, const double* const* rows) {
      if (diagnostics_.regions[static_cast<std::size_t>(p)] != PointRegion::Inside) return;
      for (int a = 0; a < dim(); ++a)
        std::copy(rows[a], rows[a] + main, gradients[static_cast<std::size_t>(a)].row(p).data());
    });
    std::vector<FrameCoordinates> frames;
    for (auto& g : gradients) frames.push_back(makeFrameCoordinates(std::move(g), main, coordinates_.isFloat()));
    return frames;
  }

  FrameWeights frameWeights(const Eigen::MatrixXd& posedVertices, const DeformParams&) const override {
    SOMICAGE_ASSERT(posedVertices.rows() == rest_.numVertices() && posedVertices.cols() == rest_.dim(),
                    "the posed cage has the rest cage's vertex count and dimension");
    const Eigen::VectorXd scales = greenFaceScales(rest_, posedVertices);
    Eigen::MatrixXd scaledNormals = faceNormals(rest_, posedVertices);
    for (int j = 0; j < rest_.numFaces(); ++j) {
      // A posed face of zero area has no normal (normalized() gave 0 or NaN); its term is dropped.
      if (!scaledNormals.row(j).allFinite() || scales(j) == 0) scaledNormals.row(j).setZero();
      scaledNormals.row(j) *= scales(j);
    }
    FrameWeights W;
    W.outputs = dim();
    W.main.resize(rest_.numVertices() + rest_.numFaces(), dim());
    W.main << posedVertices, scaledNormals;
    const Similarity fit = fitSimilarity(rest_.vertices, posedVertices);
    W.tail.resize(dim() + 1, dim());
    W.tail.topRows(dim()) = (fit.scale * fit.rotation).transpose();
    W.tail.row(dim()) = fit.translation.transpose();
    return W;
  }

 private:
  Cage rest_;
};

std::unique_ptr<CageDeformer> precomputeGreen(const Cage& restCage, const Eigen::MatrixXd& points,
                                              const PrecomputeOptions& options, const ProgressCallback& progress) {
  GreenCoordinates coords = computeGreenCoordinates(restCage, points, options.threads, progress);
  return std::make_unique<GreenDeformer>(restCage, coords, points, options);
}

// phi and psi in double stay alive while C is assembled in double (and then converted to float), with the
// winding numbers.
std::size_t greenWorkingBytes(const CoordinateLayout& layout, int, std::size_t points, bool floatStorage, int) {
  return points * static_cast<std::size_t>(layout.mainColumns()) * sizeof(double) +
         (floatStorage ? layout.bytes(points, false) : 0) + points * sizeof(double);
}

}  // namespace

namespace methods {

const MethodDescriptor& green() {
  static const MethodDescriptor descriptor{"green",
                                           "Green",
                                           "Green coordinates (Lipman et al. 2008): shape-preserving, conformal in 2D",
                                           1,
                                           0,
                                           false,
                                           false,
                                           {},
                                           validateDeformParams,
                                           greenLayout,
                                           greenWorkingBytes,
                                           precomputeGreen};
  return descriptor;
}

}  // namespace methods

}  // namespace somicage
