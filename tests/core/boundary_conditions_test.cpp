// Rotations, stretches and traction scales of the corotational deformer (section 4.4, Eqs. 12-15, docs/method.md).
#include "deform/boundary_conditions.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "test_shapes.h"

namespace somicage {
namespace {

TEST(BoundaryConditions, FitSimilarityRecoversAKnownSimilarity) {
  const Cage cage = test::makeBumpySphere(0);
  for (int d : {2, 3}) {
    const Eigen::MatrixXd V = cage.vertices.leftCols(d);
    const test::TestSimilarity s = test::randomSimilarity(d, 3);
    const Similarity fit = fitSimilarity(V, s.apply(V));
    EXPECT_LT((fit.rotation - s.rotation).norm(), 1e-12);
    EXPECT_NEAR(fit.scale, s.scale, 1e-12);
    EXPECT_LT((fit.translation - s.translation.transpose()).norm(), 1e-12);
  }
}

TEST(BoundaryConditions, FitSimilarityNeverReflects) {
  // A mirrored cage is best matched by a reflection; the fit must still return a rotation (det = +1).
  const Cage cage = test::makeBumpySphere(0);
  Eigen::MatrixXd mirrored = cage.vertices;
  mirrored.col(0) *= -1;
  const Similarity fit = fitSimilarity(cage.vertices, mirrored);
  EXPECT_NEAR(fit.rotation.determinant(), 1.0, 1e-12);
  EXPECT_LT((fit.rotation.transpose() * fit.rotation - Eigen::Matrix3d::Identity()).norm(), 1e-12);
}

TEST(BoundaryConditions, ClosestRotationIsThePolarFactor) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Eigen::Matrix3d S;
  S << 2, 0.3, 0.1, 0.3, 1.5, -0.2, 0.1, -0.2, 0.8;  // symmetric positive definite
  EXPECT_LT((closestRotation(R * S) - R).norm(), 1e-12);
}

TEST(BoundaryConditions, NormalSpreadIsSignedAndZeroForEqualNormals) {
  const Cage sphere = test::makeIcosphere(1);
  const Eigen::VectorXd spread = normalSpread(sphere, vertexNormals(sphere, sphere.vertices));
  EXPECT_GT(spread.minCoeff(), 0.0) << "convex everywhere";
  // The solid angles of the vertex-normal triangles of a sphere tile the Gauss sphere: they add up to 4 pi.
  EXPECT_NEAR(spread.sum(), 4 * M_PI, 1e-9);
  Eigen::MatrixXd flat = Eigen::MatrixXd::Zero(sphere.numVertices(), 3);
  flat.col(2).setOnes();
  EXPECT_LT(normalSpread(sphere, flat).cwiseAbs().maxCoeff(), 1e-15);
  // 2D: the angles add up to the turning number 2 pi; the floor of a notch (its vertex normals converge) is < 0.
  Eigen::MatrixXd loop(8, 2);
  loop << 0, 0, 3, 0, 3, 3, 2, 3, 2, 1, 1, 1, 1, 3, 0, 3;
  const Cage notched = makePolygonCage(loop);
  const Eigen::VectorXd angles = normalSpread(notched, vertexNormals(notched, notched.vertices));
  EXPECT_NEAR(angles.sum(), 2 * M_PI, 1e-12);
  EXPECT_LT(angles(4), -0.5) << "edge (2,1) -> (1,1), the floor of the notch";
  EXPECT_GT(angles(0), 0.5) << "edge (0,0) -> (3,0), convex";
}

TEST(BoundaryConditions, SimilarityPoseGivesUniformConditions) {
  // docs/method.md: for a similarity pose every R_j = R, lambda_j = eta_j = scale, s_j = c * scale, and the
  // traction correction changes nothing (sum_j A_j n_j = 0 on a closed cage).
  for (int d : {2, 3}) {
    const Cage cage = d == 3 ? test::makeBumpySphere(1) : test::makeStarPolygon(5);
    const test::TestSimilarity s = test::randomSimilarity(d, 4);
    for (double blend : {0.0, 0.5, 1.0}) {
      const DeformParams params{blend, 0.3, 2.0, true};
      const BoundaryConditions bc = computeBoundaryConditions(cage, s.apply(cage.vertices), params);
      const double c = 2 * (1 + d * 0.3 / (1 - 2 * 0.3));
      for (int j = 0; j < cage.numFaces(); ++j) {
        EXPECT_LT((bc.faceRotations[j] - s.rotation).norm(), 1e-10);
        EXPECT_NEAR(bc.tangentialStretch(j), s.scale, 1e-10);
        EXPECT_NEAR(bc.normalStretch(j), s.scale, 1e-10);
        EXPECT_NEAR(bc.tractionScales(j), c * s.scale, 1e-9);
      }
      for (const auto& R : bc.vertexRotations) EXPECT_LT((R - s.rotation).norm(), 1e-10);
    }
  }
}

TEST(BoundaryConditions, LocalStretchIsTheMeanSingularValue) {
  const Cage cage = test::makeIcosphere(0);
  const Eigen::MatrixXd posed = test::bendPose(cage.vertices, 0.4, 2);
  const BoundaryConditions bc = computeBoundaryConditions(cage, posed, {1.0, 0.0, 0.0, false});
  for (int j = 0; j < cage.numFaces(); ++j) {
    Eigen::Matrix<double, 3, 2> E, F;
    for (int k = 1; k < 3; ++k) {
      E.col(k - 1) = cage.vertices.row(cage.faces(j, k)) - cage.vertices.row(cage.faces(j, 0));
      F.col(k - 1) = posed.row(cage.faces(j, k)) - posed.row(cage.faces(j, 0));
    }
    // The in-plane map F E^+ restricted to the face plane has the face map's two non-zero singular values.
    const Eigen::Matrix3d map = F * (E.transpose() * E).inverse() * E.transpose();
    const Eigen::Vector3d sigma = Eigen::JacobiSVD<Eigen::Matrix3d>(map).singularValues();
    EXPECT_NEAR(bc.tangentialStretch(j), 0.5 * (sigma(0) + sigma(1)), 1e-12);
    // The local rotation maps the rest normal to the posed normal.
    const Eigen::Vector3d n = E.col(0).cross(E.col(1)).normalized(), nPosed = F.col(0).cross(F.col(1)).normalized();
    EXPECT_LT((bc.faceRotations[j] * n - nPosed).norm(), 1e-12);
  }
}

TEST(BoundaryConditions, BlendIsTheGeodesicMidpoint) {
  const Cage cage = test::makeIcosphere(0);
  const Eigen::MatrixXd posed = test::bendPose(cage.vertices, 0.4, 2);
  const BoundaryConditions global = computeBoundaryConditions(cage, posed, {0.0, 0.0, 0.0, true});
  const BoundaryConditions local = computeBoundaryConditions(cage, posed, {1.0, 0.0, 0.0, true});
  const BoundaryConditions half = computeBoundaryConditions(cage, posed, {0.5, 0.0, 0.0, true});
  for (int j = 0; j < cage.numFaces(); ++j) {
    const Eigen::AngleAxisd full(Eigen::Matrix3d(global.faceRotations[j].transpose() * local.faceRotations[j]));
    const Eigen::AngleAxisd part(Eigen::Matrix3d(global.faceRotations[j].transpose() * half.faceRotations[j]));
    EXPECT_NEAR(part.angle(), 0.5 * full.angle(), 1e-10);
    EXPECT_NEAR(half.tangentialStretch(j), 0.5 * (global.tangentialStretch(j) + local.tangentialStretch(j)), 1e-12);
  }
}

TEST(BoundaryConditions, TractionCorrectionBalancesTheTractions) {
  // Eq. 15: after the correction sum_j A_j s'_j R_j n_j = 0, and s' is the smallest area-weighted change.
  for (int d : {2, 3}) {
    const Cage cage = d == 3 ? test::makeBumpySphere(1) : test::makeStarPolygon(5);
    const Eigen::MatrixXd posed = test::bendPose(cage.vertices, 0.5, 3);
    const DeformParams params{1.0, 0.3, 3.0, true};
    DeformParams uncorrected = params;
    uncorrected.tractionCorrection = false;
    const BoundaryConditions bc = computeBoundaryConditions(cage, posed, params);
    const BoundaryConditions raw = computeBoundaryConditions(cage, posed, uncorrected);
    const Eigen::VectorXd A = faceAreas(cage, cage.vertices);
    const Eigen::MatrixXd N = faceNormals(cage, cage.vertices);
    Eigen::VectorXd balance = Eigen::VectorXd::Zero(d), before = Eigen::VectorXd::Zero(d);
    for (int j = 0; j < cage.numFaces(); ++j) {
      balance += A(j) * bc.tractionScales(j) * bc.faceRotations[j] * N.row(j).transpose();
      before += A(j) * raw.tractionScales(j) * raw.faceRotations[j] * N.row(j).transpose();
    }
    EXPECT_GT(before.norm(), 1e-3) << "the test pose is unbalanced before the correction";
    EXPECT_LT(balance.norm(), 1e-12 * A.sum());
  }
}

}  // namespace
}  // namespace somicage
