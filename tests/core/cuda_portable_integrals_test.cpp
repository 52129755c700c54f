// The portable (host + device) port of the closed-form integrals, core/cuda/triangle_integrals_portable.h and
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

#include "test_shapes.h"
#include "cuda/portable_frame.h"
#include "cuda/somigliana_row_portable.h"
#include "somigliana_coordinates.h"
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

void compareOnePair(const Eigen::Vector3d corners[3], const Eigen::Vector3d& x, Comparison& comparison) {
  const TriangleFrame frame = makeTriangleFrame(corners[0], corners[1], corners[2]);
  TriangleIntegrals expected;
  integrateTriangle(frame, x, expected);
  PortableTriangleIntegrals actual;
  const double xp[3] = {x.x(), x.y(), x.z()};
  integrateTrianglePortable(portableFrame(frame), xp, actual);

  comparison.add("S", &expected.S, &actual.S, 1);
  comparison.add("solidAngle", &expected.solidAngle, &actual.solidAngle, 1);
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> M = expected.M;
  comparison.add("M", M.data(), &actual.M[0][0], 9);
  comparison.add("D", expected.D, actual.D, 3);
  for (int k = 0; k < 3; ++k) {
    comparison.add("V", expected.V[k].data(), actual.V[k], 3);
    const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> B = expected.B[k];
    comparison.add("B", B.data(), &actual.B[k][0][0], 9);
  }
}

// Query points around a triangle: just off the face, near an edge, near a corner, in its plane outside it, nearby
// and far away. delta runs from 1e-8 to 1 triangle size.
std::vector<Eigen::Vector3d> queryPoints(const Eigen::Vector3d corners[3], double scale, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1, 1), zeroOne(0, 1);
  const Eigen::Vector3d n = (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalized();
  std::vector<Eigen::Vector3d> points;
  for (int q = 0; q < 12; ++q) {
    const Eigen::Vector3d direction(unit(rng), unit(rng), unit(rng));
    const double a = zeroOne(rng), b = zeroOne(rng) * (1 - a), delta = scale * std::pow(10.0, -8 * zeroOne(rng));
    const Eigen::Vector3d inFace = corners[0] + a * (corners[1] - corners[0]) + b * (corners[2] - corners[0]);
    const Eigen::Vector3d onEdge = corners[q % 3] + zeroOne(rng) * (corners[(q + 1) % 3] - corners[q % 3]);
    switch (q % 6) {
      case 0: points.push_back(inFace + (q % 2 ? delta : -delta) * n); break;
      case 1: points.push_back(onEdge + delta * direction); break;
      case 2: points.push_back(corners[q % 3] + delta * direction); break;
      case 3: points.push_back(corners[0] + 1.5 * (corners[1] - corners[0]) + 0.5 * (corners[2] - corners[0])); break;
      case 4: points.push_back(inFace + 2 * scale * direction); break;
      default: points.push_back(inFace + 1e3 * scale * direction); break;
    }
  }
  return points;
}

// Triangles in a coordinate plane with their first edge along a coordinate axis (any axes, any signs): the frame
// [u v n] is a signed permutation, so both sides compute the local coordinates of x exactly and every difference
// would come from the ported formulas themselves, wherever x is, however ill-conditioned the integrals.
TEST(CudaPortableIntegrals, MatchIntegrateTriangleOnAxisAlignedTriangles) {
  std::mt19937 rng(20230801);
  std::uniform_real_distribution<double> unit(-1, 1), zeroOne(0, 1);
  Comparison comparison;
  int pairs = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const double scale = std::pow(10.0, 4 * unit(rng));  // triangles from 1e-4 to 1e4 in size
    const int axisU = trial % 3, axisV = (axisU + 1 + (trial / 3) % 2) % 3;
    Eigen::Vector3d eu = Eigen::Vector3d::Zero(), ev = Eigen::Vector3d::Zero();
    eu(axisU) = unit(rng) < 0 ? -1 : 1;
    ev(axisV) = unit(rng) < 0 ? -1 : 1;
    const Eigen::Vector3d p0 = 10 * scale * Eigen::Vector3d(unit(rng), unit(rng), unit(rng));
    const Eigen::Vector3d corners[3] = {p0, p0 + scale * (0.2 + zeroOne(rng)) * eu,
                                        p0 + scale * unit(rng) * eu + scale * (0.2 + zeroOne(rng)) * ev};
    for (const Eigen::Vector3d& x : queryPoints(corners, scale, rng)) compareOnePair(corners, x, comparison), ++pairs;
  }
  EXPECT_LE(comparison.worst, kRelativeTolerance)
      << "largest relative difference in " << comparison.quantity << " over " << pairs << " pairs";
}

// Arbitrary orientations: the two sides round the local coordinates of x differently (Eigen's dot products sum in
// another order), and that rounding is amplified by the conditioning of the integrals: up to about
// eps (distance / size)^3 for a far triangle (core/triangle_integrals.h). With points at least a tenth of the
// triangle's size from its plane and at most ~15 sizes away, 1e-10 relative bounds it (measured: 6e-11, in B).
TEST(CudaPortableIntegrals, MatchIntegrateTriangleOnRandomTriangles) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> unit(-1, 1);
  auto randomVector = [&] { return Eigen::Vector3d(unit(rng), unit(rng), unit(rng)); };
  Comparison comparison;
  int pairs = 0;
  while (pairs < 4000) {
    const double scale = std::pow(10.0, 4 * unit(rng));
    const Eigen::Vector3d offset = 10 * scale * randomVector();
    const Eigen::Vector3d corners[3] = {offset + scale * randomVector(), offset + scale * randomVector(),
                                        offset + scale * randomVector()};
    const Eigen::Vector3d x = offset + 3 * scale * randomVector();
    const Eigen::Vector3d n = (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalized();
    if (std::abs(n.dot(x - corners[0])) < 0.1 * scale) continue;  // the plane's distance bounds the face's
    compareOnePair(corners, x, comparison);
    ++pairs;
  }
  EXPECT_LE(comparison.worst, 1e-10)
      << "largest relative difference in " << comparison.quantity << " over " << pairs << " pairs";
}

TEST(CudaPortableIntegrals, DegenerateFaceGivesZeros) {
  const Eigen::Vector3d p(0, 0, 0), q(1, 1, 1);
  const TriangleFrame frame = makeTriangleFrame(p, q, 2 * q);  // collinear corners
  ASSERT_TRUE(frame.degenerate);
  PortableTriangleIntegrals out;
  const double x[3] = {0.3, -0.2, 0.5};
  integrateTrianglePortable(portableFrame(frame), x, out);
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
    faces[j].frame = portableFrame(makeTriangleFrame(cage.vertices.row(cage.faces(j, 0)),
                                                     cage.vertices.row(cage.faces(j, 1)),
                                                     cage.vertices.row(cage.faces(j, 2))));
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
