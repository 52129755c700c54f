// The Kelvin layer integrals of the boundary element method: the interior limit on a point's own face (closed form
// with h = -0) against the ordinary closed form approached from inside, and the jump it carries (sum_i T_i = I on
// the cage, Eq. 9), in 2D and 3D.
#include "coordinates/bem_layer_integrals.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "geometry/edge_integrals.h"
#include "geometry/triangle_integrals.h"
#include "test_shapes.h"

namespace somicage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(BemLayerIntegrals, TriangleInteriorLimitIsTheLimitFromInside) {
  // Approaching the point from inside (x = c - delta n) the ordinary closed form converges to the limit linearly in
  // delta: at delta = 1e-7 every output is within 1e-5 of its size (the O(delta) terms), at 1e-9 within 1e-7.
  const Eigen::Vector3d p0(0.1, -0.2, 0.3), p1(1.3, 0.1, 0.2), p2(0.4, 0.9, -0.1);
  const TriangleFrame frame = makeTriangleFrame(p0, p1, p2);
  const Eigen::Vector3d c = (0.2 * p0 + 0.5 * p1 + 0.3 * p2);
  TriangleIntegrals limit, near;
  integrateTriangleInteriorLimit(frame, c, limit);
  EXPECT_NEAR(limit.solidAngle, -2 * M_PI, 1e-15);
  const double phi[3] = {0.2, 0.5, 0.3};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(limit.D[k], 2 * M_PI * phi[k], 1e-12);  // the double layer's jump, exactly
    EXPECT_LT((limit.B[k] - (2 * M_PI / 3) * phi[k] * Eigen::Matrix3d::Identity()).norm(), 1e-12);
  }
  for (double delta : {1e-7, 1e-9}) {
    integrateTriangle(frame, c - delta * frame.n, near);
    const double tolerance = 100 * delta;
    EXPECT_NEAR(near.S, limit.S, tolerance * std::abs(limit.S));
    EXPECT_LT((near.M - limit.M).norm(), tolerance * limit.M.norm());
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(near.D[k], limit.D[k], tolerance * std::abs(limit.D[k]));
      EXPECT_LT((near.V[k] - limit.V[k]).norm(), tolerance * limit.V[k].norm());
      EXPECT_LT((near.B[k] - limit.B[k]).norm(), tolerance * limit.B[k].norm());
    }
  }
}

TEST(BemLayerIntegrals, EdgeInteriorLimitIsTheLimitFromInside) {
  const Eigen::Vector2d p0(0.2, -0.1), p1(1.1, 0.7);
  const Eigen::Vector2d onEdge = 0.35 * p0 + 0.65 * p1, n = Eigen::Vector2d((p1 - p0).y(), -(p1 - p0).x()).normalized();
  EdgeIntegrals limit, near;
  integrateEdgeInteriorLimit(p0, p1, onEdge, limit);
  EXPECT_NEAR(limit.angle, -M_PI, 1e-15);
  const double phi[2] = {0.35, 0.65};
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(limit.D[k], M_PI * phi[k], 1e-12);
    EXPECT_LT((limit.B[k] - (M_PI / 2) * phi[k] * Eigen::Matrix2d::Identity()).norm(), 1e-12);
  }
  for (double delta : {1e-7, 1e-9}) {
    integrateEdge(p0, p1, onEdge - delta * n, near);
    const double tolerance = 100 * delta;
    EXPECT_NEAR(near.S, limit.S, tolerance * std::max(1.0, std::abs(limit.S)));
    EXPECT_LT((near.M - limit.M).norm(), tolerance * limit.M.norm());
    for (int k = 0; k < 2; ++k) {
      EXPECT_NEAR(near.D[k], limit.D[k], tolerance * std::abs(limit.D[k]));
      EXPECT_NEAR(near.A[k], limit.A[k], tolerance * std::max(1.0, std::abs(limit.A[k])));
      EXPECT_LT((near.B[k] - limit.B[k]).norm(), tolerance * limit.B[k].norm());
    }
  }
}

// Every face centroid of the cage, taken in the limit on its own face.
void expectPartitionOfUnityOnTheCage(const Cage& cage) {
  const int d = cage.dim();
  Eigen::MatrixXd centroids = Eigen::MatrixXd::Zero(cage.numFaces(), d);
  std::vector<int> own(static_cast<std::size_t>(cage.numFaces()));
  for (int j = 0; j < cage.numFaces(); ++j) {
    for (int k = 0; k < d; ++k) centroids.row(j) += cage.vertices.row(cage.faces(j, k)) / d;
    own[static_cast<std::size_t>(j)] = j;
  }
  const BemLayerIntegrals I = integrateBemLayers(cage, centroids, own);
  for (double nu : {-0.5, 0.0, 0.3, 0.49, kInf}) {
    double worst = 0;
    for (int c = 0; c < cage.numFaces(); ++c) {
      Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(d, d);
      for (int i = 0; i < cage.numVertices(); ++i) sum += I.vertexCoordinate(c, i, nu);
      worst = std::max(worst, (sum - Eigen::MatrixXd::Identity(d, d)).cwiseAbs().maxCoeff());
      EXPECT_NEAR(I.winding(c), 1.0, 1e-12);
    }
    // Eq. 9 on the boundary: the half from the other faces (a principal value) and the jump of the own face.
    EXPECT_LT(worst, 1e-12) << "nu " << nu;
  }
}

TEST(BemLayerIntegrals, PartitionOfUnityHoldsOnTheCageIn3D) {
  expectPartitionOfUnityOnTheCage(test::makeBumpySphere(1));
  expectPartitionOfUnityOnTheCage(test::makeExtrudedL());
}

TEST(BemLayerIntegrals, PartitionOfUnityHoldsOnTheCageIn2D) {
  expectPartitionOfUnityOnTheCage(test::makeStarPolygon(6));
  expectPartitionOfUnityOnTheCage(makePolygonCage(test::lLoop()));
}

TEST(BemLayerIntegrals, KelvinletOfAFaceMatchesTheSomiglianaCoordinates) {
  // K_j n_j from the full moment equals the Somigliana coordinates' K_j n_j (their q_j = M_j n_j): another route.
  const Cage cage = test::makeBumpySphere(0);
  const Eigen::MatrixXd points = test::randomBallPoints(5, 0.5, 3);
  const BemLayerIntegrals I = integrateBemLayers(cage, points, {});
  const SomiglianaCoordinates S = computeSomiglianaCoordinates(cage, points);
  for (int p = 0; p < 5; ++p)
    for (int j = 0; j < cage.numFaces(); ++j) {
      const Eigen::VectorXd n = S.restNormals.row(j).transpose();
      EXPECT_LT((I.faceKelvinlet(p, j, 0.3) * n - S.faceCoordinateTimesNormal(p, j, 0.3)).norm(), 1e-14);
      EXPECT_LT(
          (I.vertexCoordinate(p, j % cage.numVertices(), 0.3) - S.vertexCoordinate(p, j % cage.numVertices(), 0.3))
              .norm(),
          1e-14);
    }
}

}  // namespace
}  // namespace somicage
