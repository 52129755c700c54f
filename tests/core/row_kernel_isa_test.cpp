// Each instruction set's copy of the Somigliana row kernels (core/coordinates/somigliana_row_kernels.h) that this
// CPU runs, called directly rather than through the run-time choice: every copy's rows agree with the scalar closed
// form (IntegrationOptions::scalarKernel, the reference) to 1e-13 of each term's size (at least 1), and with each
// other: the rows to 1e-13, the gradient rows to 1e-13 between the fused-multiply-add copies and to 1e-12 / 1e-11
// (0.1 / 1e-3 inside the faces) against the baseline copy's rounded products. That the baseline copy also runs on
// a CPU without AVX2 is
// tests/python/test_portable_build.py (qemu); that no copy shares a symbol with another is core.isa_symbols.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <string>
#include <vector>

#include "base/point_blocks.h"
#include "coordinates/coordinate_gradients.h"
#include "coordinates/somigliana_coordinates.h"
#include "coordinates/somigliana_row_kernels.h"
#include "geometry/triangle_integrals.h"
#include "recorded_number.h"
#include "test_shapes.h"

namespace somicage {
namespace {

using test::scientific;

// A copy's rows (integral columns) and gradient rows of every point, one point per row.
struct CopyRows {
  Eigen::MatrixXd values, winding, gradients[3];
};

CopyRows runCopy(const SomiglianaRowKernels& kernels, const Cage& cage, const Eigen::MatrixXd& points) {
  std::vector<TriangleFrame> frames;
  for (int j = 0; j < cage.numFaces(); ++j)
    frames.push_back(makeTriangleFrame(cage.vertices.row(cage.faces(j, 0)), cage.vertices.row(cage.faces(j, 1)),
                                       cage.vertices.row(cage.faces(j, 2))));
  const std::vector<PortableFace> faces = portableFaces(cage, frames);
  std::vector<PortableGradientFrame> tables(faces.size());
  for (std::size_t j = 0; j < faces.size(); ++j) makeGradientFrame(faces[j].frame, tables[j]);
  const int lanes = kernels.lanes, n = static_cast<int>(points.rows());
  const int columns = somiglianaLayout(3, cage.numVertices(), cage.numFaces()).integralColumns();
  CopyRows out{Eigen::MatrixXd(n, columns), Eigen::MatrixXd(n, 1), {}};
  for (Eigen::MatrixXd& g : out.gradients) g.resize(n, columns);
  const PackBuffer rows = makePackBuffer(static_cast<std::size_t>(columns) * lanes),
                   gradients = makePackBuffer(3 * static_cast<std::size_t>(columns) * lanes);
  for (int first = 0; first < n; first += lanes) {
    double x[3 * kMaxGroupLanes], winding[kMaxGroupLanes];
    for (int l = 0; l < lanes; ++l)
      for (int a = 0; a < 3; ++a) x[a * lanes + l] = points(std::min(first + l, n - 1), a);
    kernels.rows(faces.data(), cage.numFaces(), cage.numVertices(), x, rows.get(), winding);
    kernels.gradientRows(faces.data(), tables.data(), cage.numFaces(), cage.numVertices(), x, gradients.get());
    for (int l = 0; l < lanes && first + l < n; ++l) {
      out.winding(first + l, 0) = winding[l];
      for (int k = 0; k < columns; ++k) {
        out.values(first + l, k) = rows[k * lanes + l];
        for (int a = 0; a < 3; ++a) out.gradients[a](first + l, k) = gradients[(3 * k + a) * lanes + l];
      }
    }
  }
  return out;
}

// max |a - b| / max(1, |b|) over every entry.
double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return ((a - b).array().abs() / b.array().abs().max(1.0)).maxCoeff();
}

std::vector<KernelIsa> copiesThisCpuRuns() {
  std::vector<KernelIsa> copies;
  for (KernelIsa isa : {KernelIsa::baseline, KernelIsa::x86_64_v3, KernelIsa::x86_64_v4})
    if (somiglianaRowKernelsFor(isa)) copies.push_back(isa);
  return copies;
}

TEST(RowKernelIsa, EveryCopyAgreesWithTheScalarClosedFormAndWithTheOthers) {
#if !SOMICAGE_SIMD_PACKS
  GTEST_SKIP() << "no SIMD packs in this build: the scalar kernels run, there are no copies";
#endif
  const std::vector<KernelIsa> copies = copiesThisCpuRuns();
  ASSERT_FALSE(copies.empty());
  ASSERT_EQ(copies.front(), KernelIsa::baseline);  // every CPU of the architecture runs it
  for (const Cage& cage : {test::makeIcosphere(2), test::makeExtrudedL()}) {
    // 0.1 and 1e-3 of the cage's size inside its faces, 201 points: the last group of 4 or 8 is partly padding.
    // (Closer to the faces the integrals' conditioning amplifies the copies' different roundings: SimdPrecompute.)
    const int near = 101, nearer = 100;
    Eigen::MatrixXd points(near + nearer, 3);
    points << test::pointsNearFaces(cage, near, 1e-1, 4), test::pointsNearFaces(cage, nearer, 1e-3, 5);
    const int columns = somiglianaLayout(3, cage.numVertices(), cage.numFaces()).integralColumns();
    IntegrationOptions scalar;
    scalar.scalarKernel = true;
    Eigen::MatrixXd reference(points.rows(), columns), referenceWinding(points.rows(), 1);
    integrateSomiglianaCoordinates(cage, points, scalar, noProgress, [&](int p, const double* row, double w) {
      reference.row(p) = Eigen::Map<const Eigen::RowVectorXd>(row, columns);
      referenceWinding(p, 0) = w;
    });
    std::vector<CopyRows> rows;
    for (KernelIsa isa : copies) rows.push_back(runCopy(*somiglianaRowKernelsFor(isa), cage, points));
    const CopyRows& baseline = rows.front();
    for (std::size_t c = 0; c < copies.size(); ++c) {
      const CopyRows& copy = rows[c];
      const std::string name = std::string(kernelIsaName(copies[c])) + "_" + std::to_string(cage.numFaces()) + "_faces";
      const double againstScalar = std::max(relativeDifference(copy.values, reference),
                                            relativeDifference(copy.winding, referenceWinding));
      EXPECT_LE(againstScalar, 1e-13) << name;
      RecordProperty("against_scalar_" + name, scientific(againstScalar));
      // Against the baseline copy: they differ by fused against rounded products. The gradients' entries are sums
      // of larger per-face terms, more so nearer the faces (docs/performance.md, "The gradients in closed form").
      const double values = std::max(relativeDifference(copy.values, baseline.values),
                                     relativeDifference(copy.winding, baseline.winding));
      double gradientsNear = 0, gradientsNearer = 0;
      for (int a = 0; a < 3; ++a) {
        gradientsNear = std::max(gradientsNear, relativeDifference(copy.gradients[a].topRows(near),
                                                                   baseline.gradients[a].topRows(near)));
        gradientsNearer = std::max(gradientsNearer, relativeDifference(copy.gradients[a].bottomRows(nearer),
                                                                       baseline.gradients[a].bottomRows(nearer)));
      }
      EXPECT_LE(values, 1e-13) << name;
      EXPECT_LE(gradientsNear, 1e-12) << name;
      EXPECT_LE(gradientsNearer, 1e-11) << name;
      RecordProperty("against_baseline_" + name, scientific(values));
      RecordProperty("gradients_against_baseline_0.1_" + name, scientific(gradientsNear));
      RecordProperty("gradients_against_baseline_1e-3_" + name, scientific(gradientsNearer));
      // The copies with fused multiply-adds (x86-64-v3, v4) do the same operations per lane, in 4 or 8 lanes.
      if (c >= 2) {
        double fused = std::max(relativeDifference(copy.values, rows[1].values),
                                relativeDifference(copy.winding, rows[1].winding));
        for (int a = 0; a < 3; ++a)
          fused = std::max(fused, relativeDifference(copy.gradients[a], rows[1].gradients[a]));
        EXPECT_LE(fused, 1e-13) << name << " against " << kernelIsaName(copies[1]);
        RecordProperty("against_" + std::string(kernelIsaName(copies[1])) + "_" + name, scientific(fused));
      }
    }
  }
}

// streamFloatRows (the gradient matrices' writer) and sumEntries against their definitions, out[l * columns + c] = in[c * stride + l]
// (c < packed) or tail[l * (columns - packed) + c - packed], in floats: every copy, for rows narrower and wider than
// a cache line, starts at every float offset within a line, and the floats just before and after the span untouched.
TEST(RowKernelIsa, EveryCopyStreamsItsRowsExactlyWhereTheyBelong) {
#if !SOMICAGE_SIMD_PACKS
  GTEST_SKIP() << "no SIMD packs in this build: no copies";
#endif
  for (KernelIsa isa : copiesThisCpuRuns()) {
    const SomiglianaRowKernels& kernels = *somiglianaRowKernelsFor(isa);
    const int lanes = kernels.lanes;
    const long stride = 3L * lanes;  // the gradient rows' interleaving
    for (const auto& [packed, columns] : {std::pair{3, 5}, {15, 17}, {16, 16}, {40, 72}, {866, 898}}) {
      const PackBuffer in = makePackBuffer(static_cast<std::size_t>(stride) * packed);
      for (long k = 0; k < stride * packed; ++k) in[k] = 1 + 0.5 * static_cast<double>(k);  // exact in float
      double sums[kMaxGroupLanes];  // sumEntries: the lanes' sums, here of exact halves, so exact
      kernels.sumEntries(in.get(), stride, packed, sums);
      for (int l = 0; l < lanes; ++l) {
        double want = 0;
        for (int c = 0; c < packed; ++c) want += in[c * stride + l];
        EXPECT_EQ(sums[l], want) << kernelIsaName(isa) << " lane " << l;
      }
      std::vector<double> tail(static_cast<std::size_t>(lanes * (columns - packed)));
      for (std::size_t k = 0; k < tail.size(); ++k) tail[k] = -1.0 - static_cast<double>(k);
      const float guard = 12345.f;
      for (int offset = 0; offset < 16; ++offset) {
        std::vector<float> storage(static_cast<std::size_t>(lanes * columns + 48), guard);
        float* const lineStart = storage.data() + (16 - reinterpret_cast<std::uintptr_t>(storage.data()) % 64 / 4);
        float* const out = lineStart + offset;
        kernels.streamFloatRows(in.get(), stride, packed, tail.data(), columns, out);
        int wrong = 0;
        for (int l = 0; l < lanes; ++l)
          for (int c = 0; c < columns; ++c) {
            const double want =
                c < packed ? in[c * stride + l] : tail[static_cast<std::size_t>(l * (columns - packed) + c - packed)];
            wrong += out[l * columns + c] != static_cast<float>(want);
          }
        EXPECT_EQ(wrong, 0) << kernelIsaName(isa) << " " << packed << "/" << columns << " offset " << offset;
        EXPECT_EQ(out[-1], guard) << kernelIsaName(isa) << " offset " << offset;
        EXPECT_EQ(out[lanes * columns], guard) << kernelIsaName(isa) << " offset " << offset;
      }
    }
  }
}

}  // namespace
}  // namespace somicage
