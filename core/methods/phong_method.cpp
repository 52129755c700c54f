// The Phong deformer of the paper's Fig. 8 (James 2020) as a deformation method (method.h), over a volume mesh
// of the rest cage (volume_mesh.h; docs/engine.md, "Phong"). A frame: the posed cage fixes the mesh's cage
// vertices, its Steiner vertices on the cage's faces follow those faces linearly, the interior ones minimise the
// linear-elastic energy (elastic_steiner_solve.h, reading nu); then F_t and F_v (phong_interpolation.h) make W and
// C W gives the points. C's row for a point X in simplex s with barycentrics l_k, vertex v_k:
//   column (v_k, 0) = l_k,   column (v_k, 1 + a) = 1/2 l_k (X - X_v_k)_a
// and W's rows for vertex v: x_v, then the columns of F_v: sum_k l_k x_k + 1/2 sum_k l_k F_k (X - X_k), which is
// phi(X) of phong_interpolation.h. Points in no simplex (outside the cage) follow the exterior rule. C is stored
// as sparse rows (coordinate_layout.h): a row has (d + 1)^2 nonzeros of (d + 1) #N + d + 1 columns.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "base/errors.h"
#include "coordinates/elastic_steiner_solve.h"
#include "coordinates/phong_interpolation.h"
#include "deform/boundary_conditions.h"
#include "deform/deformer.h"
#include "deform/exterior_points.h"
#include "geometry/simplex_locator.h"
#include "methods/method_descriptors.h"

namespace somicage {

namespace {

// C = [vertex v term k at k #N + v (k = 0: l_v, k = 1 + a: 1/2 l_v (X - X_v)_a) | x | 1]; #N: the volume mesh's.
// Stored as sparse rows: a point's (d + 1) simplex vertices times d + 1 terms (an outside point's [x | 1] fits too).
CoordinateLayout phongLayout(int dim, int numVertices, int) {
  return {numVertices, 0, dim + 1, 0, dim + 1, 0, (dim + 1) * (dim + 1)};
}

void validatePhongParams(const DeformParams& params) {
  validateDeformParams(params);
  if (std::isinf(params.nu))
    throw InputError("nu", -1,
                     "Poisson ratio " + std::string(params.nu > 0 ? "inf" : "-inf") +
                         " leaves the Steiner vertices' elastic energy indefinite (lambda = 2 nu / (1 - 2 nu) -> -1)",
                     "phong needs a finite nu in (-1, 0.5)");
}

// A Steiner vertex on a cage face: it moves with the face's corners by these weights.
struct FaceBinding {
  int vertex;
  Eigen::VectorXi corners;  // d cage vertices
  Eigen::VectorXd weights;  // d, summing to 1
};

// The barycentric coordinates of x in cage face j (3D: a triangle, by areas; 2D: an edge).
Eigen::VectorXd faceBarycentrics(const Cage& cage, int j, const Eigen::VectorXd& x) {
  const int d = cage.dim();
  Eigen::VectorXd w(d);
  if (d == 2) {
    const Eigen::VectorXd a = cage.vertices.row(cage.faces(j, 0)).transpose(),
                          b = cage.vertices.row(cage.faces(j, 1)).transpose();
    const double t = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    w << 1 - t, t;
    return w;
  }
  const Eigen::Vector3d a = cage.vertices.row(cage.faces(j, 0)), b = cage.vertices.row(cage.faces(j, 1)),
                        c = cage.vertices.row(cage.faces(j, 2)), p = x;
  const Eigen::Vector3d n = (b - a).cross(c - a);
  w << (c - b).cross(p - b).dot(n), (a - c).cross(p - c).dot(n), (b - a).cross(p - a).dot(n);
  return w / n.squaredNorm();
}

class PhongDeformer final : public CageDeformer {
 public:
  PhongDeformer(const Cage& rest, std::shared_ptr<const VolumeMesh> mesh, const Eigen::MatrixXd& points,
                const PrecomputeOptions& options, const ProgressCallback& progress)
      : CageDeformer(FrameCoordinates{}, options.threads),
        rest_(rest),
        mesh_(std::move(mesh)),
        locator_(*mesh_),
        weights_(phongVertexWeights(*mesh_)),
        gradients_(barycentricGradients(*mesh_)),
        layout_(phongLayout(rest.dim(), mesh_->numVertices(), 0)),
        solver_(*mesh_, bindSteinerVertices()) {
    coordinates_ = buildCoordinates(points, options, progress);
  }

  Method method() const override { return methods::phong(); }
  int dim() const override { return rest_.dim(); }

  FrameWeights frameWeights(const Eigen::MatrixXd& posedVertices, const DeformParams& params) const override {
    SOMICAGE_ASSERT(posedVertices.rows() == rest_.numVertices() && posedVertices.cols() == dim(),
                    "the posed cage has the rest cage's vertex count and dimension");
    validatePhongParams(params);
    const Eigen::MatrixXd x = meshPositions(posedVertices, params.nu);
    const std::vector<Eigen::MatrixXd> vertexF = vertexGradients(weights_, simplexGradients(*mesh_, gradients_, x));
    const int d = dim(), n = mesh_->numVertices();
    FrameWeights W;
    W.outputs = d;
    W.main.resize(layout_.mainColumns(), d);
    for (int v = 0; v < n; ++v) {
      W.main.row(layout_.vertexColumn(v, 0)) = x.row(v);
      for (int a = 0; a < d; ++a)
        W.main.row(layout_.vertexColumn(v, 1 + a)) = vertexF[static_cast<std::size_t>(v)].col(a).transpose();
    }
    const Similarity fit = fitSimilarity(rest_.vertices, posedVertices);
    W.tail.resize(d + 1, d);
    W.tail.topRows(d) = (fit.scale * fit.rotation).transpose();
    W.tail.row(d) = fit.translation.transpose();
    return W;
  }

  std::shared_ptr<const VolumeMesh> volumeMesh() const override { return mesh_; }
  Eigen::MatrixXd posedVolumeMesh(const Eigen::MatrixXd& posedVertices, const DeformParams& params) const override {
    SOMICAGE_ASSERT(posedVertices.rows() == rest_.numVertices() && posedVertices.cols() == dim(),
                    "the posed cage has the rest cage's vertex count and dimension");
    validatePhongParams(params);
    return meshPositions(posedVertices, params.nu);
  }

  // d/dX_b of the row above: column (v_k, 0): g_k[b]; column (v_k, 1 + a): 1/2 (g_k[b] (X - X_v_k)_a + l_k delta_ab).
  // In C's sparse form: the same entry columns as C's point rows, zero where a point is not Inside.
  std::vector<FrameCoordinates> coordinateGradients(const Eigen::MatrixXd& points,
                                                    const ProgressCallback&) const override {
    const int d = dim(), entries = layout_.rowEntries, numPoints = static_cast<int>(points.rows());
    std::vector<CoordinateMatrix<double>> rows(static_cast<std::size_t>(d));
    for (auto& g : rows) g.setZero(numPoints, entries);
    for (int p = 0; p < numPoints; ++p) {
      const int s = pointSimplex_[static_cast<std::size_t>(p)];
      if (s < 0) continue;
      const Eigen::VectorXd X = points.row(p).transpose(), l = locator_.barycentric(s, X);
      const Eigen::MatrixXd& g = gradients_[static_cast<std::size_t>(s)];
      for (int k = 0; k <= d; ++k) {
        const Eigen::VectorXd offset = X - mesh_->vertices.row(mesh_->simplices(s, k)).transpose();
        for (int b = 0; b < d; ++b) {
          CoordinateMatrix<double>& G = rows[static_cast<std::size_t>(b)];
          G(p, entry(k, 0)) = g(k, b);
          for (int a = 0; a < d; ++a) G(p, entry(k, 1 + a)) = 0.5 * (g(k, b) * offset(a) + (a == b ? l(k) : 0.0));
        }
      }
    }
    std::vector<FrameCoordinates> frames;
    for (auto& g : rows) {
      FrameCoordinates frame = makeFrameCoordinates(std::move(g), layout_.mainColumns(), coordinates_.isFloat());
      frame.entryColumns = coordinates_.entryColumns.topRows(numPoints);
      frame.sparseColumns = layout_.columns();
      frames.push_back(std::move(frame));
    }
    return frames;
  }

 private:
  // Marks the mesh's Steiner vertices: those on its boundary are bound to the cage face they lie on (bindings_),
  // the others are free (solved for). Returns the free flags.
  std::vector<bool> bindSteinerVertices() {
    const int n = rest_.numVertices(), count = mesh_->numVertices();
    std::vector<bool> free = interiorSteinerVertices(*mesh_, n);
    const CageProximity proximity(rest_);
    for (int v = n; v < count; ++v) {
      if (free[static_cast<std::size_t>(v)]) continue;
      const Eigen::VectorXd X = mesh_->vertices.row(v).transpose();
      const int j = proximity.closest(X).face;
      FaceBinding binding{v, rest_.faces.row(j).transpose(), faceBarycentrics(rest_, j, X)};
      bindings_.push_back(std::move(binding));
    }
    return free;
  }

  // The posed positions of every mesh vertex (#N by d): the cage's, the bound ones, then the elastic solve.
  Eigen::MatrixXd meshPositions(const Eigen::MatrixXd& posed, double nu) const {
    Eigen::MatrixXd x = mesh_->vertices;
    x.topRows(rest_.numVertices()) = posed;
    for (const FaceBinding& b : bindings_) {
      x.row(b.vertex).setZero();
      for (int k = 0; k < dim(); ++k) x.row(b.vertex) += b.weights(k) * posed.row(b.corners(k));
    }
    const std::lock_guard<std::mutex> lock(solverMutex_);  // factors once per nu, for every thread's frames
    solver_.factor(nu);
    solver_.solve(x);
    return x;
  }

  FrameCoordinates buildCoordinates(const Eigen::MatrixXd& points, const PrecomputeOptions& options,
                                    const ProgressCallback& progress) {
    const int numPoints = static_cast<int>(points.rows());
    pointSimplex_.assign(static_cast<std::size_t>(numPoints), -1);
    diagnostics_.regions.assign(static_cast<std::size_t>(numPoints), PointRegion::Outside);
    diagnostics_.winding = Eigen::VectorXd::Zero(numPoints);
    const std::vector<int>& given = options.pointSimplices;
    SOMICAGE_ASSERT(given.empty() || given.size() == static_cast<std::size_t>(numPoints),
                    "a simplex per point, or none");
    for (int p = 0; p < numPoints; ++p) {
      const int simplex = given.empty() ? locator_.locate(points.row(p).transpose()).simplex
                                        : given[static_cast<std::size_t>(p)];
      SOMICAGE_ASSERT(simplex < mesh_->numSimplices(), "a given simplex is one of the mesh's");
      pointSimplex_[static_cast<std::size_t>(p)] = simplex;
      if (simplex >= 0) {
        diagnostics_.regions[static_cast<std::size_t>(p)] = PointRegion::Inside;
        diagnostics_.winding(p) = 1;
      }
      if (p % 4096 == 4095 && !progress(0.5 * p / numPoints)) throw Cancelled();
    }
    ExteriorPlan plan = planExteriorPoints(rest_, points, diagnostics_.regions, options.threads);
    const int exterior = static_cast<int>(plan.blends.size());
    FrameCoordinates frame;
    frame.mainColumns = layout_.mainColumns();
    frame.sparseColumns = layout_.columns();
    const int rows = numPoints + 2 * exterior;
    frame.entryColumns.resize(rows, layout_.rowEntries);
    // Written straight into the stored precision.
    if (options.floatStorage)
      writeRows(points, plan, frame.floats.setZero(rows, layout_.rowEntries), frame.entryColumns);
    else
      writeRows(points, plan, frame.doubles.setZero(rows, layout_.rowEntries), frame.entryColumns);
    if (!progress(1.0)) throw Cancelled();
    frame.exteriorBlends = std::move(plan.blends);
    return frame;
  }

  // A sparse row's entry for simplex vertex k's term t (the row's (d + 1)^2 entries, vertex-major).
  int entry(int k, int t) const { return k * (dim() + 1) + t; }

  // The point rows of C, then each exterior point's proxy and anchor rows (frame_evaluation.h), as sparse rows.
  template <typename Scalar>
  void writeRows(const Eigen::MatrixXd& points, ExteriorPlan& plan, CoordinateMatrix<Scalar>& values,
                 CoordinateMatrix<std::int32_t>& columns) const {
    const int numPoints = static_cast<int>(points.rows()), d = dim(), entries = layout_.rowEntries,
              width = layout_.columns();
    const auto writeSimilarity = [&](const Eigen::MatrixXd& at, int p, int row) {
      writeSimilarityEntries(at, p, values.row(row).data(), columns.row(row).data(), entries, width);
    };
    // X in simplex s (-1: the one holding X); false: X is in no simplex.
    const auto writeRow = [&](const Eigen::VectorXd& X, int row, int s) {
      if (s < 0) s = locator_.locate(X).simplex;
      if (s < 0) {
        writeSimilarity(X.transpose(), 0, row);
        return false;
      }
      const Eigen::VectorXd l = locator_.barycentric(s, X);
      for (int k = 0; k <= d; ++k) {
        const int v = mesh_->simplices(s, k);
        for (int t = 0; t <= d; ++t) columns(row, entry(k, t)) = layout_.vertexColumn(v, t);
        values(row, entry(k, 0)) = static_cast<Scalar>(l(k));
        for (int a = 0; a < d; ++a)
          values(row, entry(k, 1 + a)) = static_cast<Scalar>(0.5 * l(k) * (X(a) - mesh_->vertices(v, a)));
      }
      return true;
    };
    for (int p = 0; p < numPoints; ++p) {
      if (diagnostics_.regions[static_cast<std::size_t>(p)] == PointRegion::Inside)
        writeRow(points.row(p).transpose(), p, pointSimplex_[static_cast<std::size_t>(p)]);
      else
        writeSimilarity(points, p, p);
    }
    integrateProxies(rest_, plan, [&](const Eigen::MatrixXd& proxies, const std::vector<int>& which) {
      std::vector<bool> located(which.size());
      for (std::size_t k = 0; k < which.size(); ++k)
        located[k] = writeRow(proxies.row(static_cast<Eigen::Index>(k)).transpose(), numPoints + 2 * which[k], -1);
      return located;
    });
    for (std::size_t e = 0; e < plan.blends.size(); ++e)
      writeSimilarity(plan.proxies, static_cast<int>(e), numPoints + 2 * static_cast<int>(e) + 1);
  }

  Cage rest_;
  std::shared_ptr<const VolumeMesh> mesh_;
  SimplexLocator locator_;
  PhongVertexWeights weights_;
  std::vector<Eigen::MatrixXd> gradients_;  // per simplex, the rest barycentric gradients
  CoordinateLayout layout_;
  std::vector<FaceBinding> bindings_;
  std::vector<int> pointSimplex_;  // per point, its simplex (-1: outside)
  mutable std::mutex solverMutex_;
  mutable ElasticSteinerSolver solver_;
};

std::unique_ptr<CageDeformer> precomputePhong(const Cage& restCage, const Eigen::MatrixXd& points,
                                              const PrecomputeOptions& options, const ProgressCallback& progress) {
  assertCageAndPoints(restCage, points);
  std::shared_ptr<const VolumeMesh> mesh = volumeMeshFor(restCage, options, nullptr, progress);
  return std::make_unique<PhongDeformer>(restCage, std::move(mesh), points, options, progress);
}

// C is written in its stored (sparse) form; the per-point simplices and diagnostics are small.
std::size_t phongWorkingBytes(const CoordinateLayout&, int, std::size_t points, bool, int) {
  return points * (sizeof(int) + sizeof(double) + 1);
}

}  // namespace

namespace methods {

const MethodDescriptor& phong() {
  static const MethodDescriptor descriptor{
      "phong",
      "Phong",
      "Phong deformation (James 2020, the paper's Fig. 8) over a tetrahedral mesh of the cage: C0 across tetrahedra",
      4,
      kParamNu,
      false,
      true,
      {{"tets", "FILE",
        "a MEDIT .mesh tetrahedral mesh of the rest cage whose first vertices are the cage's "
        "(default: tetrahedralize the cage)"},
       {"tet-level", "L",
        "detail of the generated tetrahedral mesh: 0 (coarse, about the cage's vertices) to 4 "
        "(default 1)",
        [](const std::string& level) { parseTetLevel({{"tet-level", level}}); }}},
      validatePhongParams,
      phongLayout,
      phongWorkingBytes,
      precomputePhong};
  return descriptor;
}

}  // namespace methods

}  // namespace somicage
