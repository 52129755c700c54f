#include "coordinates/coordinate_gradients.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/dual_number.h"
#include "base/point_blocks.h"
#include "base/simd_math.h"
#include "coordinates/bem_layer_integrals.h"
#include "coordinates/somigliana_coordinates.h"
#include "coordinates/somigliana_row_kernels.h"
#include "geometry/affine_terms.h"
#include "geometry/edge_integrals.h"
#include "geometry/triangle_integrals.h"

namespace somicage {

namespace {

template <int Dim>
using DualOf = dual::Dual<Dim>;

// The value of lane l of a double (one lane) or a pack.
inline double lane(double v, int) { return v; }
#if SOMICAGE_SIMD_PACKS
using DualPack = dual::Dual<3, simd::Pack>;
inline double lane(const simd::Pack& v, int l) { return v.v[l]; }
#endif

// Per-thread storage: a dual row (Scalar: a dual of doubles, or of packs for kLanes points) and its split into Dim
// gradient rows.
template <int Dim, typename Scalar>
struct GradientBuffers {
  std::vector<Scalar> row;
  std::vector<double> split;
  explicit GradientBuffers(int columns) : row(columns), split(static_cast<std::size_t>(Dim) * columns) {}

  void clear() { std::fill(row.begin(), row.end(), Scalar(0.0)); }
  // For each lane l (point first + l < numPoints): writes rows[a][k] = d row[k] / dx_a and hands them to the sink.
  void emit(int first, int lanes, int numPoints, const GradientRowSink& sink) {
    const std::size_t columns = row.size();
    for (int l = 0; l < lanes && first + l < numPoints; ++l) {
      const double* rows[Dim];
      for (int a = 0; a < Dim; ++a) {
        double* out = split.data() + a * columns;
        for (std::size_t k = 0; k < columns; ++k) out[k] = lane(row[k].g[a], l);
        rows[a] = out;
      }
      sink(first + l, rows);
    }
  }
};

// Calls perPoint(row, x) with x the point as dual numbers seeded with the unit vectors (every result carries d/dx_a
// in its gradient) and row its zeroed dual row (`columns` numbers), then hands the row to the sink: kLanes points at
// once (duals of packs) for a 3D cage unless scalarKernel (or a build without packs), else one at a time.
template <int Dim, typename PerPoint>
void forEachGradientRow(const Eigen::MatrixXd& points, int numFaces, int threads, const ProgressCallback& progress,
                        int columns, bool scalarKernel, const GradientRowSink& sink, PerPoint perPoint) {
  const int numPoints = static_cast<int>(points.rows());
#if SOMICAGE_SIMD_PACKS
  if constexpr (Dim == 3) {
    if (!scalarKernel)
      return forEachPointPack(
          points, numFaces, threads, progress, [columns] { return GradientBuffers<3, DualPack>(columns); },
          [&](GradientBuffers<3, DualPack>& buffers, int first, const simd::Pack x[3]) {
            buffers.clear();
            const DualPack xd[3] = {DualPack::variable(x[0], 0), DualPack::variable(x[1], 1),
                                    DualPack::variable(x[2], 2)};
            perPoint(buffers.row.data(), xd);
            buffers.emit(first, simd::kLanes, numPoints, sink);
          });
  }
#endif
  (void)scalarKernel;
  forEachPointInBlocks(
      numPoints, numFaces, threads, progress, [columns] { return GradientBuffers<Dim, DualOf<Dim>>(columns); },
      [&](GradientBuffers<Dim, DualOf<Dim>>& buffers, int p) {
        buffers.clear();
        DualOf<Dim> x[Dim];
        for (int a = 0; a < Dim; ++a) x[a] = DualOf<Dim>::variable(points(p, a), a);
        perPoint(buffers.row.data(), x);
        buffers.emit(p, 1, numPoints, sink);
      });
}

// Calls perFace(j, integrals) for every non-degenerate face of a 3D cage (PortableTriangleIntegralsOf) or every
// edge of non-zero length of a 2D one (EdgeIntegralsOf), with the point (or pack of points) as dual numbers.
template <int Dim, typename Scalar, typename PerFace>
void integrateDualFaces(const Cage& cage, const std::vector<TriangleFrame>& frames, const Scalar x[Dim],
                        PerFace perFace) {
  if constexpr (Dim == 3) {
    PortableTriangleIntegralsOf<Scalar> I;
    for (int j = 0; j < cage.numFaces(); ++j) {
      if (frames[j].degenerate) continue;
      integrateTriangle(frames[j], x, I);
      perFace(j, I);
    }
  } else {
    EdgeIntegralsOf<Scalar> I;
    for (int j = 0; j < cage.numFaces(); ++j) {
      if (isDegenerateFace(cage, j)) continue;
      const Eigen::Vector2d p0 = cage.vertices.row(cage.faces(j, 0)), p1 = cage.vertices.row(cage.faces(j, 1));
      integrateEdgeOf(p0, p1, x, I);
      perFace(j, I);
    }
  }
}

// Rows laid out as `layout` (vertexTermCount(Dim) terms per vertex, then its tailIntegrals): the vertex terms of
// somigliana_coordinates.h and, per face, writeFace(face block, integrals, n, tail integrals).
template <int Dim, typename WriteFace>
void vertexTermGradients(const Cage& cage, const Eigen::MatrixXd& points, int threads, const ProgressCallback& progress,
                         const CoordinateLayout& layout, WriteFace writeFace, const GradientRowSink& sink,
                         bool scalarKernel) {
  const RowMatrixXd normals = faceNormals(cage, cage.vertices);  // row-major: rows as pointers
  const int stride = layout.numVertices;
  const std::vector<TriangleFrame> frames = Dim == 3 ? cageFrames(cage) : std::vector<TriangleFrame>();
  forEachGradientRow<Dim>(
      points, cage.numFaces(), threads, progress, layout.integralColumns(), scalarKernel, sink,
      [&](auto* row, const auto* x) {
        // The accumulation of somigliana_coordinates.cpp (addVertexTerms), in dual numbers.
        integrateDualFaces<Dim>(cage, frames, x, [&](int j, const auto& I) {
          const double* n = normals.row(j).data();
          for (int k = 0; k < Dim; ++k) {
            auto* t = row + layout.vertexColumn(cage.faces(j, k), 0);
            t[0] += I.D[k];
            if constexpr (Dim == 3) {
              const auto& V = I.V[k];
              const auto& B = I.B[k];
              t[stride] += V[1] * n[2] - V[2] * n[1], t[2 * stride] += V[2] * n[0] - V[0] * n[2];
              t[3 * stride] += V[0] * n[1] - V[1] * n[0];
              t[4 * stride] += B[0][0], t[5 * stride] += B[1][1], t[6 * stride] += B[2][2];
              t[7 * stride] += B[0][1], t[8 * stride] += B[0][2], t[9 * stride] += B[1][2];
            } else {
              t[stride] += I.A[k];
              t[2 * stride] += I.B[k][0][0], t[3 * stride] += I.B[k][1][1], t[4 * stride] += I.B[k][0][1];
            }
          }
          writeFace(row + layout.faceColumn(j, 0), I, n, row + layout.mainColumns());
        });
      });
}

// Somigliana's face terms S_j and q_j = M_j n_j, and the affine terms (somigliana_coordinates.h), one point per group.
template <int Dim>
void somiglianaGradients(const Cage& cage, const Eigen::MatrixXd& points, int threads, const ProgressCallback& progress,
                         const GradientGroupSink& sink) {
  auto writeFace = [](auto* f, const auto& I, const double* n, auto* affine) {
    f[0] += I.S;
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) f[1 + a] += I.M[a][b] * n[b];
    addAffineTerms<Dim>(I.M, n, affine);
  };
  const CoordinateLayout layout = somiglianaLayout(Dim, cage.numVertices(), cage.numFaces());
  // One point at a time: the reference (the packs are somiglianaGradientPacks, the whole row in one dispatched call).
  vertexTermGradients<Dim>(
      cage, points, threads, progress, layout, writeFace,
      [&](int p, const double* const* rows) {
        GradientRowGroup group;
        group.first = p, group.count = 1, group.entryStride = 1;
        for (int a = 0; a < Dim; ++a) group.rows[a] = rows[a];
        sink(group);
      },
      /*scalarKernel=*/true);
}

// The boundary element's face terms S_j and the full moment M_j (bem_layer_integrals.h).
template <int Dim>
void bemLayerGradients(const Cage& cage, const Eigen::MatrixXd& points, int threads, const ProgressCallback& progress,
                       const GradientRowSink& sink, bool scalarKernel) {
  auto writeFace = [](auto* f, const auto& I, const double*, auto*) {
    f[0] = I.S;
    if constexpr (Dim == 3)
      f[1] = I.M[0][0], f[2] = I.M[1][1], f[3] = I.M[2][2], f[4] = I.M[0][1], f[5] = I.M[0][2], f[6] = I.M[1][2];
    else
      f[1] = I.M[0][0], f[2] = I.M[1][1], f[3] = I.M[0][1];
  };
  const CoordinateLayout layout = bemLayerLayout(Dim, cage.numVertices(), cage.numFaces());
  vertexTermGradients<Dim>(cage, points, threads, progress, layout, writeFace, sink, scalarKernel);
}

template <int Dim>
void greenGradients(const Cage& cage, const Eigen::MatrixXd& points, int threads, const ProgressCallback& progress,
                    const GradientRowSink& sink, bool scalarKernel) {
  const double scale = 1 / (Dim == 3 ? 4 * M_PI : 2 * M_PI);                    // green_coordinates.h
  const CoordinateLayout layout{cage.numVertices(), cage.numFaces(), 1, 1, 0};  // [phi | psi]
  const std::vector<TriangleFrame> frames = Dim == 3 ? cageFrames(cage) : std::vector<TriangleFrame>();
  forEachGradientRow<Dim>(points, cage.numFaces(), threads, progress, layout.mainColumns(), scalarKernel, sink,
                          [&](auto* row, const auto* x) {
                            integrateDualFaces<Dim>(cage, frames, x, [&](int j, const auto& I) {
                              for (int k = 0; k < Dim; ++k)
                                row[layout.vertexColumn(cage.faces(j, k), 0)] += scale * I.D[k];
                              row[layout.faceColumn(j, 0)] = scale * I.S;
                            });
                          });
}

#if SOMICAGE_SIMD_PACKS
// The three gradient rows of a group of points per call of the row kernel this CPU runs (somigliana_row_kernels.h),
// from the closed-form derivatives (somigliana_gradient_row.h), handed on interleaved as the kernel wrote them.
void somiglianaGradientPacks(const Cage& cage, const Eigen::MatrixXd& points, int threads,
                             const ProgressCallback& progress, const GradientGroupSink& sink) {
  const std::vector<PortableFace> faces = portableFaces(cage, cageFrames(cage));
  std::vector<PortableGradientFrame> tables(faces.size());  // the rotation tables, once per cage
  for (std::size_t j = 0; j < faces.size(); ++j) makeGradientFrame(faces[j].frame, tables[j]);
  const SomiglianaRowKernels& kernels = somiglianaRowKernels();
  const int numPoints = static_cast<int>(points.rows()), lanes = kernels.lanes;
  const std::size_t columns = somiglianaLayout(3, cage.numVertices(), cage.numFaces()).integralColumns();
  forEachPointGroup(
      points, lanes, cage.numFaces(), threads, progress, [&] { return makePackBuffer(3 * columns * lanes); },
      [&](PackBuffer& packed, int first, const double* x) {
        kernels.gradientRows(faces.data(), tables.data(), cage.numFaces(), cage.numVertices(), x, packed.get());
        GradientRowGroup group;
        group.first = first, group.count = std::min(lanes, numPoints - first);
        for (int a = 0; a < 3; ++a) group.rows[a] = packed.get() + a * lanes;
        group.laneStride = 1, group.entryStride = 3 * lanes;
        sink(group);
      });
}
#endif

}  // namespace

void integrateSomiglianaGradientGroups(const Cage& cage, const Eigen::MatrixXd& points, int threads,
                                       const ProgressCallback& progress, const GradientGroupSink& sink,
                                       bool scalarKernel) {
  assertCageAndPoints(cage, points);
#if SOMICAGE_SIMD_PACKS
  if (cage.dim() == 3 && !scalarKernel) return somiglianaGradientPacks(cage, points, threads, progress, sink);
#endif
  (void)scalarKernel;
  if (cage.dim() == 3)
    somiglianaGradients<3>(cage, points, threads, progress, sink);
  else
    somiglianaGradients<2>(cage, points, threads, progress, sink);
}

void integrateSomiglianaGradients(const Cage& cage, const Eigen::MatrixXd& points, int threads,
                                  const ProgressCallback& progress, const GradientRowSink& sink, bool scalarKernel) {
  const int dim = cage.dim();
  const std::size_t columns = somiglianaLayout(dim, cage.numVertices(), cage.numFaces()).integralColumns();
  integrateSomiglianaGradientGroups(
      cage, points, threads, progress,
      [&](const GradientRowGroup& group) {
        std::vector<double> split(dim * columns);
        for (int l = 0; l < group.count; ++l) {
          const double* rows[3];
          for (int a = 0; a < dim; ++a) {
            double* out = split.data() + a * columns;
            const double* in = group.rows[a] + l * group.laneStride;
            for (std::size_t k = 0; k < columns; ++k) out[k] = in[k * group.entryStride];
            rows[a] = out;
          }
          sink(group.first + l, rows);
        }
      },
      scalarKernel);
}

void integrateGreenGradients(const Cage& cage, const Eigen::MatrixXd& points, int threads,
                             const ProgressCallback& progress, const GradientRowSink& sink, bool scalarKernel) {
  assertCageAndPoints(cage, points);
  if (cage.dim() == 3)
    greenGradients<3>(cage, points, threads, progress, sink, scalarKernel);
  else
    greenGradients<2>(cage, points, threads, progress, sink, scalarKernel);
}

void integrateBemLayerGradients(const Cage& cage, const Eigen::MatrixXd& points, int threads,
                                const ProgressCallback& progress, const GradientRowSink& sink, bool scalarKernel) {
  assertCageAndPoints(cage, points);
  if (cage.dim() == 3)
    bemLayerGradients<3>(cage, points, threads, progress, sink, scalarKernel);
  else
    bemLayerGradients<2>(cage, points, threads, progress, sink, scalarKernel);
}

}  // namespace somicage
