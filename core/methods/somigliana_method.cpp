// The corotational Somigliana deformer (paper Eqs. 10-15) over precomputed Somigliana coordinates, and its method
// descriptor (method.h).
#include <cmath>
#include <memory>
#include <mutex>
#include <vector>

#include "base/errors.h"
#include "base/point_blocks.h"
#include "base/prefault.h"
#include "base/simd_pack.h"
#include "coordinates/coordinate_gradients.h"
#include "coordinates/somigliana_coordinates.h"
#include "coordinates/somigliana_row_kernels.h"
#include "deform/boundary_conditions.h"
#include "deform/deformer.h"
#include "deform/exterior_points.h"
#include "deform/fold_check.h"
#include "deform/jacobian.h"
#include "methods/method_descriptors.h"

namespace somicage {

namespace {

// The d by d matrices E_k with T_i = sum_k t_k E_k(nu), t_k the stored terms of vertex i (somigliana_coordinates.h).
std::vector<Eigen::MatrixXd> vertexTermBasis(int d, double nu) {
  const NuCoefficients c = nuCoefficients(d, nu);
  std::vector<Eigen::MatrixXd> basis;
  auto unit = [d](int r, int s) {
    Eigen::MatrixXd E = Eigen::MatrixXd::Zero(d, d);
    E(r, s) = 1;
    return E;
  };
  basis.push_back(c.alpha * Eigen::MatrixXd::Identity(d, d));  // D
  if (d == 3) {
    basis.push_back(c.alpha * (unit(2, 1) - unit(1, 2)));  // omega_x: w -> e_x x w
    basis.push_back(c.alpha * (unit(0, 2) - unit(2, 0)));  // omega_y
    basis.push_back(c.alpha * (unit(1, 0) - unit(0, 1)));  // omega_z
    for (int a = 0; a < 3; ++a) basis.push_back(c.beta * unit(a, a));
    const int offDiagonal[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    for (const auto& rs : offDiagonal) basis.push_back(c.beta * (unit(rs[0], rs[1]) + unit(rs[1], rs[0])));
  } else {
    basis.push_back(c.alpha * (unit(0, 1) - unit(1, 0)));  // A01
    basis.push_back(c.beta * unit(0, 0));
    basis.push_back(c.beta * unit(1, 1));
    basis.push_back(c.beta * (unit(0, 1) + unit(1, 0)));
  }
  return basis;
}

// The T outputs (frame_evaluation.h: symmetric and antisymmetric parts) of a d by d matrix M into row `row` of W.
void setTColumns(const Eigen::MatrixXd& M, Eigen::MatrixXd& W, int row) {
  const Eigen::VectorXd y = tOutputsFromMatrix(M);
  W.row(row).head(y.size()) = y.transpose();
}

// The per-vertex sums of a row's vertex terms (vertexTermCount numbers into sums, zeroed by the caller). In vertex
// order: an Eigen reduction's order would depend on the buffer's alignment, and so on the thread.
void sumVertexTerms(const CoordinateLayout& layout, const double* integrals, double* sums) {
  for (int k = 0; k < layout.vertexTerms; ++k)
    for (int i = 0; i < layout.numVertices; ++i) sums[k] += integrals[layout.vertexColumn(i, k)];
}

// A point's tail of its row of C, in the storage type: [per-vertex sums | affine terms | x | 1] with [x | 1] zero;
// tail integral k at tailIntegrals[k * stride], the tail written from `tail` (the row's tailColumn(0)).
template <typename Scalar>
void writeTailColumns(const CoordinateLayout& layout, const double* sums, const double* tailIntegrals,
                      std::ptrdiff_t stride, Scalar* tail) {
  for (int k = 0; k < layout.vertexTerms; ++k) tail[k] = static_cast<Scalar>(sums[k]);
  for (int k = 0; k < layout.tailIntegrals; ++k)
    tail[layout.vertexTerms + k] = static_cast<Scalar>(tailIntegrals[k * stride]);
  for (int k = layout.vertexTerms + layout.tailIntegrals; k < layout.tailColumns; ++k) tail[k] = Scalar(0);
}

// A point's integrals (layout.integralColumns() numbers: the main block in the layout of C, then the affine terms)
// into its row of C, in the storage type: the main block, then the tail.
template <typename Scalar>
void writeIntegralColumns(const CoordinateLayout& layout, const double* integrals, const double* sums, Scalar* row) {
  for (int k = 0; k < layout.mainColumns(); ++k) row[k] = static_cast<Scalar>(integrals[k]);
  writeTailColumns(layout, sums, integrals + layout.mainColumns(), 1, row + layout.mainColumns());
}

// The main block of a group's gradient row (writeGradientGroup) into the lanes' rows, with their per-vertex sums
// (in vertex order, as sumVertexTerms); returns where the tail integrals start. Lanes > 0: exactly that many lanes,
// contiguous, so that the compiler keeps the lanes' sums in registers (twice as fast as a count it does not know).
template <int Lanes, typename Scalar>
const double* writeMainColumns(const CoordinateLayout& layout, const GradientRowGroup& group, const double* in,
                               Scalar* const* out, double (*sums)[vertexTermCount(3)]) {
  const int count = Lanes > 0 ? Lanes : group.count;
  const std::ptrdiff_t laneStride = Lanes > 0 ? 1 : group.laneStride, entryStride = group.entryStride;
  int k = 0;
  for (int t = 0; t < layout.vertexTerms; ++t) {
    double sum[kMaxGroupLanes] = {};
    for (int i = 0; i < layout.numVertices; ++i, ++k, in += entryStride)  // k = layout.vertexColumn(i, t)
      for (int l = 0; l < count; ++l) {
        const double value = in[l * laneStride];
        out[l][k] = static_cast<Scalar>(value);
        sum[l] += value;
      }
    for (int l = 0; l < count; ++l) sums[l][t] = sum[l];
  }
  for (; k < layout.mainColumns(); ++k, in += entryStride)
    for (int l = 0; l < count; ++l) out[l][k] = static_cast<Scalar>(in[l * laneStride]);
  return in;
}

#if SOMICAGE_SIMD_PACKS
// sumVertexTerms for each lane of a pack's rows (entry k of lane l at in[k * stride + l]), added by the kernel copy.
void sumVertexTermsOfPack(const SomiglianaRowKernels& kernels, const CoordinateLayout& layout, const double* in,
                          std::ptrdiff_t stride, double (*sums)[vertexTermCount(3)]) {
  for (int t = 0; t < layout.vertexTerms; ++t) {  // in vertex order, as sumVertexTerms
    double termSums[kMaxGroupLanes];
    kernels.sumEntries(in + layout.vertexColumn(0, t) * stride, stride, layout.numVertices, termSums);
    for (int l = 0; l < kernels.lanes; ++l) sums[l][t] = termSums[l];
  }
}

// A whole pack's rows in the layout of C (entry k of lane l at in[k * stride + l], the lanes' per-vertex sums in
// `sums`) as the pack's consecutive float rows from `out`: the tails made here in double, every row then streamed out
// by the kernels' writer (somigliana_row_kernels.h: whole cache lines without reading them first).
void streamPackRows(const SomiglianaRowKernels& kernels, const CoordinateLayout& layout, const double* in,
                    std::ptrdiff_t stride, const double (*sums)[vertexTermCount(3)], float* out) {
  double tails[kMaxGroupLanes * tailColumnCount(3)];  // the packs' rows are 3D ones
  for (int l = 0; l < kernels.lanes; ++l)
    writeTailColumns(layout, sums[l], in + layout.mainColumns() * stride + l, stride, tails + l * layout.tailColumns);
  kernels.streamFloatRows(in, stride, layout.mainColumns(), tails, layout.columns(), out);
}

// A whole pack's gradient rows into float matrices, which are three times the size of C and written once
// (streamPackRows).
void streamGradientGroup(const CoordinateLayout& layout, const GradientRowGroup& group,
                         const std::vector<PointRegion>& regions, std::vector<CoordinateMatrix<float>>& gradients) {
  const SomiglianaRowKernels& kernels = somiglianaRowKernels();
  for (std::size_t a = 0; a < gradients.size(); ++a) {
    double sums[kMaxGroupLanes][vertexTermCount(3)];
    sumVertexTermsOfPack(kernels, layout, group.rows[a], group.entryStride, sums);
    streamPackRows(kernels, layout, group.rows[a], group.entryStride, sums, gradients[a].row(group.first).data());
    for (int l = 0; l < group.count; ++l)
      if (regions[static_cast<std::size_t>(group.first + l)] != PointRegion::Inside)
        gradients[a].row(group.first + l).setZero();
  }
}
#endif

// A group's gradient rows d(row of C)/dx_a (coordinate_gradients.h) into the gradient matrices, as
// writeIntegralColumns writes C's rows, with the lanes innermost: the packs' interleaved rows are read once, in
// order, straight into the matrices (a copy per point first took as long as the float rows' writing). Rows of
// points that are not Inside are zero. A whole pack into float matrices is streamed (above).
template <typename Scalar>
void writeGradientGroup(const CoordinateLayout& layout, const GradientRowGroup& group,
                        const std::vector<PointRegion>& regions, std::vector<CoordinateMatrix<Scalar>>& gradients) {
  const bool contiguous = group.laneStride == 1;
#if SOMICAGE_SIMD_PACKS  // else no kernel copies: groups of one point
  if constexpr (std::is_same_v<Scalar, float>) {
    if (contiguous && group.count == somiglianaRowKernels().lanes && layout.tailColumns <= tailColumnCount(3))
      return streamGradientGroup(layout, group, regions, gradients);
  }
#endif
  for (std::size_t a = 0; a < gradients.size(); ++a) {
    Scalar* out[kMaxGroupLanes] = {};
    for (int l = 0; l < group.count; ++l) out[l] = gradients[a].row(group.first + l).data();
    double sums[kMaxGroupLanes][vertexTermCount(3)] = {};
    const double* tail;
    if (contiguous && group.count == 8)
      tail = writeMainColumns<8>(layout, group, group.rows[a], out, sums);
    else if (contiguous && group.count == 4)
      tail = writeMainColumns<4>(layout, group, group.rows[a], out, sums);
    else
      tail = writeMainColumns<0>(layout, group, group.rows[a], out, sums);
    for (int l = 0; l < group.count; ++l) {
      if (regions[static_cast<std::size_t>(group.first + l)] != PointRegion::Inside)
        gradients[a].row(group.first + l).setZero();
      else
        writeTailColumns(layout, sums[l], tail + l * group.laneStride, group.entryStride,
                         out[l] + layout.mainColumns());
    }
  }
}

// The d gradient matrices of C's point rows (CageDeformer::coordinateGradients): the closed-form integrals of
// coordinate_gradients.h (in the layout of C) and their sums; zero rows for points that are not Inside.
template <typename Scalar>
void fillCoordinateGradients(const Cage& cage, const Eigen::MatrixXd& points, const std::vector<PointRegion>& regions,
                             int threads, const ProgressCallback& progress, const CoordinateLayout& layout,
                             std::vector<CoordinateMatrix<Scalar>>& gradients) {
  gradients.resize(static_cast<std::size_t>(cage.dim()));  // one at a time: no temporary fourth copy
  // Not zeroed here: the sink writes every row once, on the worker threads (a serial setZero of 3 x 140 MB for
  // FIREHYDRANT would touch every page twice, once on one thread); only their pages are allocated up front.
  for (auto& g : gradients) {
    g.resize(points.rows(), layout.columns());
    prefaultForWriting(g.data(), static_cast<std::size_t>(g.size()) * sizeof(Scalar), threads);
  }
  integrateSomiglianaGradientGroups(cage, points, threads, progress, [&](const GradientRowGroup& group) {
    writeGradientGroup(layout, group, regions, gradients);
  });
}

// A point's region from the per-vertex sums of its integrals (their partition-of-unity residual into `residual`) and
// whether they are all finite; reliable integrals of a point inside are used, the rest follow the exterior rule.
PointRegion classifyRow(const double* sums, double winding, bool finite, bool exactIntegrals, int dim,
                        double& residual) {
  residual = unityResidualOfSums(sums, dim);
  // The Gauss baseline misses Eq. 9 by up to 1e-1 near the cage (docs/engine.md): only exact integrals are held
  // to kUnreliableResidual.
  const bool reliable = finite && (!exactIntegrals || residual <= kUnreliableResidual);
  return classifyPoint(winding, reliable);
}

// Writes a point's row of C in the storage type: its integrals (already in the layout of C) and their per-vertex
// sums where they are reliable, else the similarity row [0 | x | 1] (exterior_points.h). Returns the point's region
// and its partition-of-unity residual. Rows are independent, so this runs on the integration's worker threads.
// The one writer of C's rows, whichever integrator (CPU or device) produced them, but for whole packs of float rows
// (writeFrameGroup).
template <typename Scalar>
PointRegion writeFrameRow(const double* integrals, double winding, const Eigen::MatrixXd& points, int p,
                          const CoordinateLayout& layout, bool exactIntegrals, Scalar* row, double& residual) {
  const int dim = static_cast<int>(points.cols()), main = layout.integralColumns(), columns = layout.columns();
  double sums[vertexTermCount(3)] = {0};
  sumVertexTerms(layout, integrals, sums);
  // NaN and infinity survive a sum: one vectorised reduction checks the whole row (7x cheaper than allFinite).
  const bool finite = std::isfinite(Eigen::Map<const Eigen::ArrayXd>(integrals, main).sum());
  const PointRegion region = classifyRow(sums, winding, finite, exactIntegrals, dim, residual);
  if (region != PointRegion::Inside) {
    writeSimilarityRow(points, p, row, columns);
    return region;
  }
  writeIntegralColumns(layout, integrals, sums, row);
  return region;
}

#if SOMICAGE_SIMD_PACKS
// writeFrameGroup for a whole pack into float storage: the lanes classified from their sums (added in packs), then
// their rows streamed (streamPackRows): C is written once and is larger than the caches.
void streamFrameGroup(const CoordinateRowGroup& group, const Eigen::MatrixXd& points, const CoordinateLayout& layout,
                      bool exactIntegrals, const SomiglianaRowKernels& kernels, CoordinateMatrix<float>& C,
                      PrecomputeDiagnostics& diagnostics) {
  const int lanes = group.lanes;
  double sums[kMaxGroupLanes][vertexTermCount(3)], all[kMaxGroupLanes];
  sumVertexTermsOfPack(kernels, layout, group.rows, lanes, sums);
  kernels.sumEntries(group.rows, lanes, layout.integralColumns(), all);  // NaN and infinity survive a sum
  PointRegion regions[kMaxGroupLanes];
  for (int l = 0; l < lanes; ++l) {
    const int p = group.first + l;
    diagnostics.winding(p) = group.winding[l];
    regions[l] = classifyRow(sums[l], group.winding[l], std::isfinite(all[l]), exactIntegrals, 3,
                             diagnostics.unityResidual(p));
    diagnostics.regions[static_cast<std::size_t>(p)] = regions[l];
  }
  streamPackRows(kernels, layout, group.rows, lanes, sums, C.row(group.first).data());
  for (int l = 0; l < lanes; ++l)
    if (regions[l] != PointRegion::Inside)
      writeSimilarityRow(points, group.first + l, C.row(group.first + l).data(), layout.columns());
}
#endif

// A group of points' rows (integrateSomiglianaCoordinateGroups) into C and the diagnostics, as writeFrameRow does
// point by point: a whole pack into float storage streamed (above), else the rows one by one through writeRow.
template <typename Scalar>
void writeFrameGroup(const CoordinateRowGroup& group, const Eigen::MatrixXd& points, const CoordinateLayout& layout,
                     bool exactIntegrals, CoordinateMatrix<Scalar>& C, PrecomputeDiagnostics& diagnostics,
                     const CoordinateRowSink& writeRow) {
#if SOMICAGE_SIMD_PACKS
  const SomiglianaRowKernels& kernels = somiglianaRowKernels();
  if constexpr (std::is_same_v<Scalar, float>) {
    if (group.count == group.lanes && group.lanes == kernels.lanes && layout.tailColumns <= tailColumnCount(3))
      return streamFrameGroup(group, points, layout, exactIntegrals, kernels, C, diagnostics);
  }
#endif
  forEachRowOfGroup(group, layout.integralColumns(), writeRow);
}

// Fills C (#P + 2 #E rows) in its storage type: the points' rows, then for every exterior point its proxy's row
// (the proxy's own integrals) and its anchor [0 | x_in | 1] (frame_evaluation.h). Rows go straight into C: no
// second, double-precision copy of the coordinates; adding the exterior rows reallocates in place.
// The CPU's rows come in groups (writeFrameGroup); a device's (`device`, when given) one point at a time.
template <typename Scalar>
void fillFrameCoordinates(const Cage& cage, const Eigen::MatrixXd& points, const IntegrationOptions& integration,
                          const RowIntegrator& device, const ProgressCallback& progress,
                          const CoordinateLayout& layout, CoordinateMatrix<Scalar>& C,
                          std::vector<ExteriorBlend>& blends, PrecomputeDiagnostics& diagnostics) {
  const int numPoints = static_cast<int>(points.rows()), columns = layout.columns();
  const bool exact = integration.rule == IntegrationOptions::Rule::ClosedForm;
  const RowIntegrator integrate = device ? device : integrateSomiglianaCoordinates;
  C.resize(numPoints, columns);
  prefaultForWriting(C.data(), static_cast<std::size_t>(C.size()) * sizeof(Scalar), integration.threads);
  const CoordinateRowSink writeRow = [&](int p, const double* row, double w) {
    diagnostics.winding(p) = w;
    diagnostics.regions[static_cast<std::size_t>(p)] =
        writeFrameRow(row, w, points, p, layout, exact, C.row(p).data(), diagnostics.unityResidual(p));
  };
  const auto writeGroup = [&](const CoordinateRowGroup& group) {
    writeFrameGroup(group, points, layout, exact, C, diagnostics, writeRow);
  };
  if (device || !integrateSomiglianaCoordinateGroups(cage, points, integration, progress, writeGroup))
    integrate(cage, points, integration, progress, writeRow);
  ExteriorPlan plan = planExteriorPoints(cage, points, diagnostics.regions, integration.threads);
  if (plan.blends.empty()) return;
  C.conservativeResize(numPoints + 2 * static_cast<Eigen::Index>(plan.blends.size()), columns);
  integrateProxies(cage, plan, [&](const Eigen::MatrixXd& proxies, const std::vector<int>& which) {
    std::vector<char> reliable(which.size());  // one per proxy, written from the worker threads
    integrate(cage, proxies, integration, noProgress, [&](int k, const double* row, double w) {
      double residual;
      Scalar* proxyRow = C.row(numPoints + 2 * which[static_cast<std::size_t>(k)]).data();
      reliable[static_cast<std::size_t>(k)] =
          writeFrameRow(row, w, proxies, k, layout, exact, proxyRow, residual) == PointRegion::Inside;
    });
    return std::vector<bool>(reliable.begin(), reliable.end());
  });
  // A proxy that failed everywhere holds [0 | x_in | 1] like its anchor: its point follows S alone.
  for (int e = 0; e < static_cast<int>(plan.blends.size()); ++e)
    writeSimilarityRow(plan.proxies, e, C.row(numPoints + 2 * e + 1).data(), columns);
  blends = std::move(plan.blends);
}

class SomiglianaDeformer final : public CageDeformer {
 public:
  SomiglianaDeformer(Cage rest, FrameCoordinates coordinates, PrecomputeDiagnostics diagnostics, int threads,
                     IntegrationOptions integration)
      : CageDeformer(std::move(coordinates), threads),
        integration_(integration),
        rest_(std::move(rest)),
        restNormals_(faceNormals(rest_, rest_.vertices)),
        layout_(somiglianaLayout(rest_.dim(), rest_.numVertices(), rest_.numFaces())) {
    diagnostics_ = std::move(diagnostics);
  }

  Method method() const override { return methods::somigliana(); }
  int dim() const override { return rest_.dim(); }

  std::vector<FrameCoordinates> coordinateGradients(const Eigen::MatrixXd& points,
                                                    const ProgressCallback& progress) const override {
    std::vector<FrameCoordinates> frames(static_cast<std::size_t>(dim()));
    const bool isFloat = coordinates_.isFloat();
    std::vector<CoordinateMatrix<float>> floats;
    std::vector<CoordinateMatrix<double>> doubles;
    if (isFloat)
      fillCoordinateGradients(rest_, points, diagnostics_.regions, threads_, progress, layout_, floats);
    else
      fillCoordinateGradients(rest_, points, diagnostics_.regions, threads_, progress, layout_, doubles);
    for (std::size_t a = 0; a < frames.size(); ++a) {
      frames[a].mainColumns = coordinates_.mainColumns;
      if (isFloat)
        frames[a].floats = std::move(floats[a]);
      else
        frames[a].doubles = std::move(doubles[a]);
    }
    return frames;
  }

  // Eq. 11: x~ = T(x)^-1 [sum_i R_i T_i R_i^T v~_i + sum_j R_j K_j R_j^T tau~_j], T(x) = sum_i R_i T_i R_i^T,
  // evaluated as o + T(x)^-1 [... (v~_i - o) ...] about the posed centroid o (frame_evaluation.h).
  // Both sums are linear in the stored nu-independent terms t_k (T_i = sum_k t_k E_k), so their weights are
  // R_i E_k R_i^T (for T) and R_i E_k R_i^T v~_i (for the right-hand side); the face terms give
  // R_j K_j R_j^T tau~_j = s_j R_j K_j n_j = s_j R_j (k1 S_j n_j + k2 q_j) (Eq. 14, docs/method.md).
  // The affine variant adds R K_j sigma n_j = R (k1 S_j sigma n_j + k2 M_j sigma n_j) for one global sigma: the
  // first through S_j's column, the second from the per-point affine terms in the tail (somigliana_coordinates.h).
  FrameWeights frameWeights(const Eigen::MatrixXd& posed, const DeformParams& params) const override {
    validateDeformParams(params);
    SOMICAGE_ASSERT(posed.rows() == rest_.numVertices() && posed.cols() == dim(), "posed cage matches the rest cage");
    if (params.kind != VariantKind::Stable || params.nu == 0)
      return weightsFor(computeBoundaryConditions(rest_, posed, params), posed, params);
    // The stable variant: the local variant's weights W0 (s = 0) blended toward the fully damped W1 (s = 1) by the
    // least s that passes the fold check (fold_check.h). The tractions, and so W and J, are affine in s.
    DeformParams localParams = params;
    localParams.kind = VariantKind::Blend;
    localParams.blend = 1;
    const BoundaryConditions localBc = computeBoundaryConditions(rest_, posed, localParams);
    const FrameWeights W0 = weightsFor(localBc, posed, localParams);
    const FoldProbe& probe = foldProbe();
    const double minDet = kFoldCheckMargin * std::pow(localBc.global.scale, dim());
    Eigen::MatrixXd positions, J0, J1;
    probe.gradients->evaluate(W0, positions, J0);
    if (foldFree(J0, minDet)) return W0;  // the local variant passes: no damping
    FrameWeights W = weightsFor(computeBoundaryConditions(rest_, posed, params), posed, params);
    probe.gradients->evaluate(W, positions, J1);
    const double s = leastFoldFreeBlend(J0, J1, minDet);
    W.main = W0.main + s * (W.main - W0.main);  // the tails agree: they hold no tractions
    return W;
  }

 private:
  // The fold check's samples inside the rest cage, with their coordinates and coordinate gradients: made at the
  // first stable frame with nu != 0 (a few hundred points; other variants never pay for them).
  struct FoldProbe {
    std::unique_ptr<CageDeformer> deformer;
    std::shared_ptr<const DeformationGradients> gradients;  // kept by the probe's deformer too
  };
  const FoldProbe& foldProbe() const {
    std::call_once(foldProbeMade_, [this] {
      const Eigen::MatrixXd samples = foldCheckSamples(rest_);
      PrecomputeOptions options;
      options.integration = integration_;
      options.threads = threads_;
      foldProbe_.deformer = methods::somigliana().precompute(rest_, samples, options, noProgress);
      foldProbe_.gradients = foldProbe_.deformer->gradients(samples);
    });
    return foldProbe_;
  }

  FrameWeights weightsFor(const BoundaryConditions& bc, const Eigen::MatrixXd& posed,
                          const DeformParams& params) const {
    const int d = dim(), terms = vertexTermCount(d);
    const std::vector<Eigen::MatrixXd> basis = vertexTermBasis(d, params.nu);
    const bool affine = params.kind == VariantKind::Affine;
    // Every R_i = R: T(x) comes from the per-point sums in the tail.
    const bool global = affine || (params.kind == VariantKind::Blend && params.blend == 0);
    const Eigen::MatrixXd& rotation = affine ? bc.faceRotations.front() : bc.global.rotation;

    FrameWeights W;
    W.finish = methods::somigliana().finish;
    W.outputs = frameOutputs(W.finish, d);
    // The global variant reads T(x) = R (sum_i T_i) R^T from the per-point sums in the tail; the local one takes
    // the D part of T (alpha D I, unchanged by rotations) from the sums too, and the rest from the vertex terms.
    W.mainOffset = global ? d * d : 0;
    const int rhs = W.outputs - W.mainOffset - d;  // where the right-hand side starts in W.main
    // b relative to the posed centroid o: every term's T weight times (v~_i - o) gives b - T(x) o.
    W.origin = posed.colwise().mean().transpose();
    W.main = Eigen::MatrixXd::Zero(layout_.mainColumns(), W.outputs - W.mainOffset);
    W.tail = Eigen::MatrixXd::Zero(layout_.tailColumns, W.outputs);
    for (int i = 0; i < rest_.numVertices(); ++i) {
      const Eigen::MatrixXd& R = global ? rotation : bc.vertexRotations[i];
      const Eigen::VectorXd v = posed.row(i).transpose() - W.origin;
      for (int k = 0; k < terms; ++k) {
        const Eigen::MatrixXd rotated = R * basis[k] * R.transpose();
        const int row = layout_.vertexColumn(i, k);
        if (!global && k > 0) setTColumns(rotated, W.main, row);
        W.main.row(row).segment(rhs, d) = (rotated * v).transpose();
      }
    }
    const NuCoefficients c = nuCoefficients(d, params.nu);
    for (int j = 0; j < rest_.numFaces(); ++j) {
      const Eigen::MatrixXd& R = bc.faceRotations[j];
      const double s = bc.tractionScales(j);
      const int row = layout_.faceColumn(j, 0);
      const auto n = restNormals_.row(j).transpose();
      if (affine)
        W.main.row(row).segment(rhs, d) = (c.k1 * R * (s * n + bc.stress * n)).transpose();
      else
        W.main.row(row).segment(rhs, d) = (s * c.k1 * R * n).transpose();
      for (int a = 0; a < d; ++a) W.main.row(row + 1 + a).segment(rhs, d) = (s * c.k2 * R.col(a)).transpose();
      if (bc.globalScales.size() > 0) {  // stable: + u_j R n_j in the global frame
        const double u = bc.globalScales(j);
        W.main.row(row).segment(rhs, d) += (u * c.k1 * rotation * n).transpose();
        for (int a = 0; a < d; ++a) W.main.row(row + 1 + a).segment(rhs, d) += (u * c.k2 * rotation.col(a)).transpose();
      }
    }
    if (global) {
      for (int k = 0; k < terms; ++k) setTColumns(rotation * basis[k] * rotation.transpose(), W.tail, k);
    } else {
      setTColumns(basis[0], W.tail, 0);  // sum_i R_i (alpha D_i I) R_i^T = alpha (sum_i D_i) I
    }
    if (affine) {  // tail row (a, pair bc) holds sum_j (M_j sigma n_j)_a's coefficient of sigma_bc
      const int pairs = d * (d + 1) / 2;
      const int first[6] = {0, 1, 2, 0, 0, 1}, second[6] = {0, 1, 2, 1, 2, 2}, second2[3] = {0, 1, 1};
      for (int a = 0; a < d; ++a)
        for (int k = 0; k < pairs; ++k) {
          const int b = d == 3 ? first[k] : (k == 2 ? 0 : k), e = d == 3 ? second[k] : second2[k];
          W.tail.row(terms + a * pairs + k).tail(d) = (c.k2 * bc.stress(b, e) * rotation.col(a)).transpose();
        }
    }
    // Rows [0 | x | 1] (exterior points, exterior_points.h), the tail's last d + 1: T = I and b = s R x + t, or
    // A x + b in the affine variant.
    const int xRow = layout_.tailColumns - d - 1;
    const Eigen::MatrixXd map = affine ? bc.affine.linear : Eigen::MatrixXd(bc.global.scale * bc.global.rotation);
    const Eigen::VectorXd shift = affine ? bc.affine.translation : bc.global.translation;
    for (int a = 0; a < d; ++a) W.tail.row(xRow + a).tail(d) = map.col(a).transpose();
    setTColumns(Eigen::MatrixXd::Identity(d, d), W.tail, xRow + d);
    W.tail.row(xRow + d).tail(d) = (shift - W.origin).transpose();
    return W;
  }

  IntegrationOptions integration_;
  mutable std::once_flag foldProbeMade_;
  mutable FoldProbe foldProbe_;
  Cage rest_;
  Eigen::MatrixXd restNormals_;
  CoordinateLayout layout_;
};

std::unique_ptr<CageDeformer> precomputeSomigliana(const Cage& restCage, const Eigen::MatrixXd& points,
                                                   const PrecomputeOptions& options, const ProgressCallback& progress) {
  IntegrationOptions integration = options.integration;
  if (integration.threads == 0) integration.threads = options.threads;
  const int numPoints = static_cast<int>(points.rows());
  const CoordinateLayout layout = somiglianaLayout(restCage.dim(), restCage.numVertices(), restCage.numFaces());
  PrecomputeDiagnostics diagnostics{Eigen::VectorXd(numPoints), Eigen::VectorXd(numPoints),
                                    std::vector<PointRegion>(static_cast<std::size_t>(numPoints))};
  FrameCoordinates frame;
  frame.mainColumns = layout.mainColumns();
  if (options.floatStorage)
    fillFrameCoordinates(restCage, points, integration, options.rowIntegrator, progress, layout, frame.floats,
                         frame.exteriorBlends, diagnostics);
  else
    fillFrameCoordinates(restCage, points, integration, options.rowIntegrator, progress, layout, frame.doubles,
                         frame.exteriorBlends, diagnostics);
  return std::make_unique<SomiglianaDeformer>(restCage, std::move(frame), std::move(diagnostics), options.threads,
                                              integration);
}

// Rows go straight into C; the diagnostics keep a winding number, a residual and a region per point; each thread
// has a group's rows (a pack buffer: kMaxGroupLanes rows of the integrals) and, where it writes them one by one, a row.
std::size_t somiglianaWorkingBytes(const CoordinateLayout& layout, int, std::size_t points, bool, int threads) {
  return static_cast<std::size_t>(threads) * (kMaxGroupLanes + 1) * static_cast<std::size_t>(layout.integralColumns()) *
             sizeof(double) +
         points * (2 * sizeof(double) + sizeof(PointRegion));
}

}  // namespace

namespace methods {

const MethodDescriptor& somigliana() {
  static const MethodDescriptor descriptor{
      "somigliana",
      "Somigliana",
      "Somigliana coordinates (Chen et al. 2023): elastic, with Poisson ratio nu and bulging gamma",
      0,
      kParamBlend | kParamNu | kParamGamma | kParamTractionFix | kParamBulging | kParamNormals,
      false,
      false,
      {},
      validateDeformParams,
      somiglianaLayout,
      somiglianaWorkingBytes,
      precomputeSomigliana,
      FrameFinish::SolveT,
      kFieldVertex | kFieldFace};
  return descriptor;
}

}  // namespace methods

}  // namespace somicage
