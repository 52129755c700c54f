// The portable (host + device) port of the closed-form integrals, core/triangle_integrals_kernel.h and
// somigliana_row_portable.h, compiled here by the host compiler and compared with the engine's own
// integrateTriangle and integrateSomiglianaCoordinates. This is how the CUDA precompute's math is verified on
// machines without a GPU: the kernel runs exactly these functions.
//
// Tolerance: 1e-12 relative to the largest entry of each compared quantity wherever both sides get the same local
// coordinates of the query point (then they evaluate the same formulas in the same order, and any larger
// difference means the port has drifted from core/triangle_integrals.cpp); 1e-10 for arbitrary orientations, below.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "cuda/somigliana_row_portable.h"
#include "somigliana_coordinates.h"
#include "test_shapes.h"
#include "triangle_integrals.h"

namespace somicage {
namespace {

constexpr double kRelativeTolerance = 1e-12;

// Largest |a - b| relative to the largest |a| of one quantity (n numbers each).
struct Comparison {
  double worst = 0;
  const char* quantity = "";
  void add(const char* name, const double* a, const double* b, int n) {
    double scale = 0, error = 0;
    for (int i = 0; i < n; ++i) scale = std::max(scale, std::abs(a[i])), error = std::max(error, std::abs(a[i] - b[i]));
    const double relative = scale > 0 ? error / scale : error;
    if (relative > worst) worst = relative, quantity = name;
  }
};

TEST(CudaPortableIntegrals, DegenerateFaceGivesZeros) {
  const Eigen::Vector3d p(0, 0, 0), q(1, 1, 1);
  const TriangleFrame frame = makeTriangleFrame(p, q, 2 * q);  // collinear corners
  ASSERT_TRUE(frame.degenerate);
  PortableTriangleIntegrals out;
  const double x[3] = {0.3, -0.2, 0.5};
  integrateTrianglePortable(frame.kernel, x, out);
  EXPECT_EQ(out.S, 0.0);
  EXPECT_EQ(out.solidAngle, 0.0);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(out.D[k], 0.0);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(out.V[k][i], 0.0);
      for (int j = 0; j < 3; ++j) EXPECT_EQ(out.B[k][i][j], 0.0);
    }
  }
}

// The whole per-point row the CUDA kernel writes (strided, as on the device) against the CPU precompute.
TEST(CudaPortableIntegrals, RowsMatchIntegrateSomiglianaCoordinates) {
  const Cage cage = test::makeBumpySphere(1);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  Eigen::MatrixXd points(60, 3);
  for (int p = 0; p < points.rows(); ++p) points.row(p) = 0.7 * Eigen::RowVector3d(unit(rng), unit(rng), unit(rng));
  points.row(0) << 0, 0, 0;
  points.row(1) << 3, 0, 0;  // outside: winding 0
  const SomiglianaCoordinates expected = computeSomiglianaCoordinates(cage, points);

  std::vector<PortableFace> faces(cage.numFaces());
  for (int j = 0; j < cage.numFaces(); ++j) {
    faces[j].frame = makeTriangleFrame(cage.vertices.row(cage.faces(j, 0)), cage.vertices.row(cage.faces(j, 1)),
                                       cage.vertices.row(cage.faces(j, 2)))
                         .kernel;
    for (int k = 0; k < 3; ++k) faces[j].corners[k] = cage.faces(j, k);
  }
  const int numPoints = static_cast<int>(points.rows()), columns = static_cast<int>(expected.values.cols());
  std::vector<double> rows(static_cast<size_t>(columns) * numPoints, 12345.0);  // overwritten, column-major
  Comparison comparison;
  double worstWinding = 0;
  for (int p = 0; p < numPoints; ++p) {
    const double x[3] = {points(p, 0), points(p, 1), points(p, 2)};
    const double winding = integrateSomiglianaRowPortable(faces.data(), cage.numFaces(), cage.numVertices(), x,
                                                          rows.data() + p, numPoints);
    std::vector<double> row(columns);
    for (int k = 0; k < columns; ++k) row[k] = rows[static_cast<size_t>(k) * numPoints + p];
    comparison.add("row", expected.values.row(p).data(), row.data(), columns);
    worstWinding = std::max(worstWinding, std::abs(winding - expected.winding(p)));
  }
  EXPECT_LE(comparison.worst, kRelativeTolerance) << "largest relative difference of a row";
  EXPECT_LE(worstWinding, 1e-12);
  EXPECT_NEAR(expected.winding(0), 1.0, 1e-12);
  EXPECT_NEAR(expected.winding(1), 0.0, 1e-12);
}

}  // namespace
}  // namespace somicage
