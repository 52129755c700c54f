#include "coordinates/somigliana_coordinates.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "base/errors.h"
#include "base/point_blocks.h"
#include "coordinates/somigliana_row_kernels.h"
#include "geometry/affine_terms.h"
#include "geometry/edge_integrals.h"
#include "geometry/kelvin_kernels.h"
#include "geometry/triangle_integrals.h"
#include "geometry/triangle_quadrature.h"

namespace somicage {

NuCoefficients nuCoefficients(int dim, double nu) {
  const double a = kelvinA(dim);
  if (std::isinf(nu)) return {a, 0.0, a, 0.0};  // docs/method.md: evaluate the limit, never a huge nu
  return {a * (1 - 2 * nu) / (2 * (1 - nu)), dim * a / (2 * (1 - nu)), a * (3 - 4 * nu) / (4 * (1 - nu)),
          a / (4 * (1 - nu))};
}

// ---------------------------------------------------------------------------------------------------------------
// Assembly of T_i and K_j n_j from the stored terms
// ---------------------------------------------------------------------------------------------------------------

Eigen::MatrixXd assembleVertexCoordinate(const double* t, int dim, double nu) {
  const NuCoefficients c = nuCoefficients(dim, nu);
  if (dim == 3) {
    Eigen::Matrix3d A, B;
    A << 0, -t[3], t[2], t[3], 0, -t[1], -t[2], t[1], 0;  // omega x w
    B << t[4], t[7], t[8], t[7], t[5], t[9], t[8], t[9], t[6];
    return c.alpha * (t[0] * Eigen::Matrix3d::Identity() + A) + c.beta * B;
  }
  Eigen::Matrix2d A, B;
  A << 0, t[1], -t[1], 0;
  B << t[2], t[4], t[4], t[3];
  return c.alpha * (t[0] * Eigen::Matrix2d::Identity() + A) + c.beta * B;
}

CoordinateLayout somiglianaLayout(int dim, int numVertices, int numFaces) {
  return {numVertices, numFaces, vertexTermCount(dim), faceTermCount(dim), tailColumnCount(dim), affineTermCount(dim)};
}

void gatherVertexTerms(const CoordinateLayout& layout, const double* row, int i, double* terms) {
  for (int k = 0; k < layout.vertexTerms; ++k) terms[k] = row[layout.vertexColumn(i, k)];
}

double unityResidualOfSums(const double* termSums, int dim) {
  return (assembleVertexCoordinate(termSums, dim, 0.0) - Eigen::MatrixXd::Identity(dim, dim)).cwiseAbs().maxCoeff();
}

Eigen::MatrixXd SomiglianaCoordinates::vertexCoordinate(int p, int i, double nu) const {
  double terms[vertexTermCount(3)];
  gatherVertexTerms(layout, values.row(p).data(), i, terms);
  return assembleVertexCoordinate(terms, dim, nu);
}

Eigen::VectorXd SomiglianaCoordinates::faceCoordinateTimesNormal(int p, int j, double nu) const {
  const NuCoefficients c = nuCoefficients(dim, nu);
  const double* t = values.row(p).data() + layout.faceColumn(j, 0);
  const Eigen::Map<const Eigen::VectorXd> q(t + 1, dim);
  return c.k1 * t[0] * restNormals.row(j).transpose() + c.k2 * q;
}

Eigen::MatrixXd SomiglianaCoordinates::vertexCoordinateSum(int p, double nu) const {
  // T_i is linear in its terms: sum the terms (each a contiguous range of the row), then assemble once.
  double sums[vertexTermCount(3)] = {0};
  for (int k = 0; k < layout.vertexTerms; ++k)
    for (int i = 0; i < layout.numVertices; ++i) sums[k] += values(p, layout.vertexColumn(i, k));
  return assembleVertexCoordinate(sums, dim, nu);
}

Eigen::VectorXd partitionOfUnityResidual(const SomiglianaCoordinates& coords) {
  Eigen::VectorXd residual(coords.numPoints());
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(coords.dim, coords.dim);
  for (int p = 0; p < coords.numPoints(); ++p)
    residual(p) = (coords.vertexCoordinateSum(p, 0.0) - I).cwiseAbs().maxCoeff();
  return residual;
}

// ---------------------------------------------------------------------------------------------------------------
// Integration
// ---------------------------------------------------------------------------------------------------------------

void addVertexTerms(const TriangleIntegrals& I, const Eigen::Vector3d& n, const int corners[3],
                    const CoordinateLayout& layout, double* row) {
  const int stride = layout.numVertices;
  for (int k = 0; k < 3; ++k) {
    double* t = row + layout.vertexColumn(corners[k], 0);
    const Eigen::Vector3d omega = I.V[k].cross(n);  // (n V^T - V n^T) w = (V x n) x w
    const Eigen::Matrix3d& B = I.B[k];
    t[0] += I.D[k];
    t[stride] += omega.x(), t[2 * stride] += omega.y(), t[3 * stride] += omega.z();
    t[4 * stride] += B(0, 0), t[5 * stride] += B(1, 1), t[6 * stride] += B(2, 2);
    t[7 * stride] += B(0, 1), t[8 * stride] += B(0, 2), t[9 * stride] += B(1, 2);
  }
}

void addVertexTerms(const EdgeIntegrals& I, const int ends[2], const CoordinateLayout& layout, double* row) {
  const int stride = layout.numVertices;
  for (int k = 0; k < 2; ++k) {
    double* t = row + layout.vertexColumn(ends[k], 0);
    t[0] += I.D[k];
    t[stride] += I.A[k];
    t[2 * stride] += I.B[k](0, 0), t[3 * stride] += I.B[k](1, 1), t[4 * stride] += I.B[k](0, 1);
  }
}

std::vector<TriangleFrame> cageFrames(const Cage& cage) {
  std::vector<TriangleFrame> frames;
  frames.reserve(cage.numFaces());
  for (int j = 0; j < cage.numFaces(); ++j)
    frames.push_back(makeTriangleFrame(cage.vertices.row(cage.faces(j, 0)), cage.vertices.row(cage.faces(j, 1)),
                                       cage.vertices.row(cage.faces(j, 2))));
  return frames;
}

std::vector<PortableFace> portableFaces(const Cage& cage, const std::vector<TriangleFrame>& frames) {
  std::vector<PortableFace> faces(frames.size());
  for (std::size_t j = 0; j < frames.size(); ++j) {
    faces[j].frame = frames[j].kernel;
    for (int k = 0; k < 3; ++k) faces[j].corners[k] = cage.faces(static_cast<int>(j), k);
  }
  return faces;
}

namespace {

// Adds one triangle's integrals to the row of point x (3D terms, see vertexTermCount; in the layout of C), its
// affine terms after the main block.
void accumulateTriangle(const TriangleIntegrals& I, const Eigen::Vector3d& n, const int corners[3],
                        const CoordinateLayout& layout, int face, double* row, double& solidAngleSum) {
  addVertexTerms(I, n, corners, layout, row);
  double* f = row + layout.faceColumn(face, 0);
  const Eigen::Vector3d q = I.M * n;
  f[0] += I.S, f[1] += q.x(), f[2] += q.y(), f[3] += q.z();
  const double M[3][3] = {{I.M(0, 0), I.M(0, 1), I.M(0, 2)}, {I.M(1, 0), I.M(1, 1), I.M(1, 2)},
                          {I.M(2, 0), I.M(2, 1), I.M(2, 2)}};
  addAffineTerms<3>(M, n.data(), row + layout.mainColumns());
  solidAngleSum += I.solidAngle;
}

void accumulateEdge(const EdgeIntegrals& I, const Eigen::Vector2d& n, const int ends[2], const CoordinateLayout& layout,
                    int face, double* row, double& angleSum) {
  addVertexTerms(I, ends, layout, row);
  double* f = row + layout.faceColumn(face, 0);
  const Eigen::Vector2d q = I.M * n;
  f[0] += I.S, f[1] += q.x(), f[2] += q.y();
  const double M[2][2] = {{I.M(0, 0), I.M(0, 1)}, {I.M(1, 0), I.M(1, 1)}};
  addAffineTerms<2>(M, n.data(), row + layout.mainColumns());
  angleSum += I.angle;
}

#if SOMICAGE_SIMD_PACKS
// The closed-form 3D rows, a group of points per call of the row kernel this CPU runs (somigliana_row_kernels.h: 4
// or 8 lanes, one point each; the last group repeats the last point). Each group's rows (lanes times one row: about
// 30 KB for a 100-face cage in four lanes) stay in L1 while its faces are summed; the results are the scalar closed
// form's to a few units of rounding (simd_math.h), independent of the thread count.
void integrateSomiglianaPacks(const Cage& cage, const Eigen::MatrixXd& points, const std::vector<TriangleFrame>& frames,
                              int threads, const ProgressCallback& progress, const CoordinateGroupSink& sink) {
  const std::vector<PortableFace> faces = portableFaces(cage, frames);
  const SomiglianaRowKernels& kernels = somiglianaRowKernels();
  const int numPoints = static_cast<int>(points.rows()), lanes = kernels.lanes;
  const int columns = somiglianaLayout(3, cage.numVertices(), cage.numFaces()).integralColumns();
  forEachPointGroup(
      points, lanes, cage.numFaces(), threads, progress,
      [&] { return makePackBuffer(static_cast<std::size_t>(columns) * lanes); },
      [&](PackBuffer& packed, int first, const double* x) {
        double winding[kMaxGroupLanes];
        kernels.rows(faces.data(), cage.numFaces(), cage.numVertices(), x, packed.get(), winding);
        sink(CoordinateRowGroup{first, std::min(lanes, numPoints - first), lanes, packed.get(), winding});
      });
}
#endif

}  // namespace

void forEachRowOfGroup(const CoordinateRowGroup& group, int columns, const CoordinateRowSink& sink) {
  std::vector<double> row(static_cast<std::size_t>(columns));
  for (int l = 0; l < group.count; ++l) {
    for (int k = 0; k < columns; ++k) row[static_cast<std::size_t>(k)] = group.rows[k * group.lanes + l];
    sink(group.first + l, row.data(), group.winding[l]);
  }
}

bool integrateSomiglianaCoordinateGroups(const Cage& cage, const Eigen::MatrixXd& points,
                                         const IntegrationOptions& options, const ProgressCallback& progress,
                                         const CoordinateGroupSink& sink) {
#if SOMICAGE_SIMD_PACKS
  if (cage.dim() != 3 || options.rule == IntegrationOptions::Rule::Gauss || options.scalarKernel) return false;
  assertCageAndPoints(cage, points);
  integrateSomiglianaPacks(cage, points, cageFrames(cage), options.threads, progress, sink);
  return true;
#else
  (void)cage, (void)points, (void)options, (void)progress, (void)sink;
  return false;
#endif
}

void integrateSomiglianaCoordinates(const Cage& cage, const Eigen::MatrixXd& points, const IntegrationOptions& options,
                                    const ProgressCallback& progress, const CoordinateRowSink& sink) {
  const int dim = cage.dim();
  assertCageAndPoints(cage, points);
  const CoordinateLayout layout = somiglianaLayout(dim, cage.numVertices(), cage.numFaces());
  const int columns = layout.integralColumns();
  const auto eachRow = [columns, &sink](const CoordinateRowGroup& group) { forEachRowOfGroup(group, columns, sink); };
  if (integrateSomiglianaCoordinateGroups(cage, points, options, progress, eachRow)) return;

  const Eigen::MatrixXd normals = faceNormals(cage, cage.vertices);
  const int numPoints = static_cast<int>(points.rows());
  const std::vector<TriangleFrame> frames = dim == 3 ? cageFrames(cage) : std::vector<TriangleFrame>();
  const bool gauss = options.rule == IntegrationOptions::Rule::Gauss;
  auto rowBuffer = [columns] { return std::vector<double>(columns); };
  forEachPointInBlocks(numPoints, cage.numFaces(), options.threads, progress, rowBuffer,
                       [&](std::vector<double>& buffer, int p) {
                         std::fill(buffer.begin(), buffer.end(), 0.0);
                         double* row = buffer.data();
                         double angleSum = 0, winding;
                         if (dim == 3) {
                           const Eigen::Vector3d x = points.row(p);
                           TriangleIntegrals I;
                           for (int j = 0; j < cage.numFaces(); ++j) {
                             if (frames[j].degenerate) continue;
                             const int corners[3] = {cage.faces(j, 0), cage.faces(j, 1), cage.faces(j, 2)};
                             if (gauss)
                               integrateTriangleGauss(cage.vertices.row(corners[0]), cage.vertices.row(corners[1]),
                                                      cage.vertices.row(corners[2]), x, options.gaussPointsPerSide, I);
                             else
                               integrateTriangle(frames[j], x, I);
                             accumulateTriangle(I, frames[j].n, corners, layout, j, row, angleSum);
                           }
                           winding = -angleSum / (4 * M_PI);
                         } else {
                           const Eigen::Vector2d x = points.row(p);
                           EdgeIntegrals I;
                           for (int j = 0; j < cage.numFaces(); ++j) {
                             const int ends[2] = {cage.faces(j, 0), cage.faces(j, 1)};
                             const Eigen::Vector2d p0 = cage.vertices.row(ends[0]), p1 = cage.vertices.row(ends[1]);
                             if (isDegenerateFace(cage, j)) continue;  // zero-length edges contribute nothing
                             if (gauss)
                               integrateEdgeGauss(p0, p1, x, 1, options.gaussPointsPerSide, I);
                             else
                               integrateEdge(p0, p1, x, I);
                             accumulateEdge(I, normals.row(j), ends, layout, j, row, angleSum);
                           }
                           winding = -angleSum / (2 * M_PI);
                         }
                         sink(p, row, winding);
                       });
}

SomiglianaCoordinates computeSomiglianaCoordinates(const Cage& cage, const Eigen::MatrixXd& points,
                                                   const IntegrationOptions& options,
                                                   const ProgressCallback& progress) {
  SomiglianaCoordinates coords;
  coords.dim = cage.dim();
  coords.layout = somiglianaLayout(cage.dim(), cage.numVertices(), cage.numFaces());
  coords.restNormals = faceNormals(cage, cage.vertices);
  const int columns = coords.layout.mainColumns();
  coords.values.resize(points.rows(), columns);
  coords.winding.resize(points.rows());
  integrateSomiglianaCoordinates(cage, points, options, progress, [&](int p, const double* row, double winding) {
    coords.values.row(p) = Eigen::Map<const Eigen::RowVectorXd>(row, columns);
    coords.winding(p) = winding;
  });
  return coords;
}

}  // namespace somicage
