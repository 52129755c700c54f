// The deformation gradient (core/deform/jacobian.h) against independent references: central differences of the exact
// map (CageDeformer::deform at displaced points), the identity at rest, s I for a uniform scale, and rotations.
#include "deform/jacobian.h"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <memory>

#include "method_cases.h"
#include "methods/method_descriptors.h"
#include "test_shapes.h"

namespace somicage {
namespace {

using test::MethodCase;

struct JacobianSetup {
  Cage cage;
  Eigen::MatrixXd points, posed;
};

// A non-convex cage, points at least 0.1 diameters inside, and a bent pose.
JacobianSetup setupFor(int dim) {
  JacobianSetup s;
  s.cage = dim == 3 ? test::makeBumpySphere(1) : test::makeStarPolygon(7);
  s.points = dim == 3 ? test::randomBallPoints(12, 0.55, 3) : test::randomDiscPoints(12, 0.35, 3);
  s.posed = test::bendPose(s.cage.vertices, 0.3, 5);
  return s;
}

Eigen::MatrixXd jacobianOfRow(const Eigen::MatrixXd& J, int p, int d) {
  Eigen::MatrixXd M(d, d);
  for (int a = 0; a < d; ++a)
    for (int b = 0; b < d; ++b) M(a, b) = J(p, a * d + b);
  return M;
}

// Parameter sets that exercise every part of the Somigliana frame (global T from sums, local T from vertex terms,
// bulging, no traction fix) and of the BEM frame (nu, corotation); the other methods ignore them.
std::vector<DeformParams> parameterSets(Method method) {
  if (method == methods::bem()) return {{0.0, 0.3, 0.0, true, false}, {0.0, -0.5, 0.0, true, true}};
  if (method != methods::somigliana()) return {DeformParams{}};
  return {{0.0, 0.3, 0.0, true}, {1.0, 0.45, 0.7, true}, {0.5, -0.5, 0.2, false}};
}

class JacobianTest : public ::testing::TestWithParam<MethodCase> {};

// J against central differences of the map itself, f(x + h e_b) - f(x - h e_b) over 2h, with the deformer made for
// the displaced points (an independent precompute). Richardson's extrapolation of h and h/2 (h = 1e-3 diameters)
// leaves a truncation error ~h^4 and rounding ~eps/h: about 1e-12, so even the nearly singular J of a fold-over
// (det J ~ 1e-3) is checked to 1e-6 of its determinant.
TEST_P(JacobianTest, DeterminantMatchesCentralDifferencesOfTheMap) {
  const MethodCase& c = GetParam();
  const JacobianSetup s = setupFor(c.dim);
  const int d = c.dim, P = static_cast<int>(s.points.rows());
  const double h = 1e-3 * cageDiameter(s.cage.vertices);
  const double steps[4] = {h, -h, h / 2, -h / 2};
  Eigen::MatrixXd displaced(4 * d * P, d);
  for (int p = 0; p < P; ++p)
    for (int b = 0; b < d; ++b)
      for (int k = 0; k < 4; ++k) {
        displaced.row((p * d + b) * 4 + k) = s.points.row(p);
        displaced((p * d + b) * 4 + k, b) += steps[k];
      }
  const auto deformer = makeDeformer(c.method, s.cage, s.points);
  const auto reference = makeDeformer(c.method, s.cage, displaced);
  const DeformationGradients gradients(*deformer, s.points);
  EXPECT_EQ(gradients.undefinedCount(), 0);
  for (const DeformParams& params : parameterSets(c.method)) {
    Eigen::MatrixXd positions, J;
    gradients.evaluate(s.posed, params, positions, J);
    EXPECT_LE((positions - deformer->deform(s.posed, params)).cwiseAbs().maxCoeff(), 1e-12);
    const Eigen::MatrixXd moved = reference->deform(s.posed, params);
    for (int p = 0; p < P; ++p) {
      Eigen::MatrixXd F(d, d);
      for (int b = 0; b < d; ++b) {
        const int r = (p * d + b) * 4;
        const Eigen::VectorXd coarse = (moved.row(r) - moved.row(r + 1)).transpose() / (2 * h);
        const Eigen::VectorXd fine = (moved.row(r + 2) - moved.row(r + 3)).transpose() / h;
        F.col(b) = (4 * fine - coarse) / 3;
      }
      const Eigen::MatrixXd Jp = jacobianOfRow(J, p, d);
      EXPECT_NEAR(Jp.determinant(), F.determinant(), 1e-6 * std::abs(F.determinant()))
          << "point " << p << " blend " << params.blend << " nu " << params.nu;
      EXPECT_LE((Jp - F).norm(), 1e-6 * F.norm()) << "point " << p;
    }
  }
}

// At rest every method reproduces the identity map (for Somigliana at any nu, gamma, variant), so J = I.
TEST_P(JacobianTest, IsTheIdentityAtRest) {
  const MethodCase& c = GetParam();
  const JacobianSetup s = setupFor(c.dim);
  const auto deformer = makeDeformer(c.method, s.cage, s.points);
  const DeformationGradients gradients(*deformer, s.points);
  for (const DeformParams& params : parameterSets(c.method)) {
    Eigen::MatrixXd positions, J;
    gradients.evaluate(s.cage.vertices, params, positions, J);
    for (int p = 0; p < s.points.rows(); ++p) {
      const Eigen::MatrixXd Jp = jacobianOfRow(J, p, c.dim);
      EXPECT_LE((Jp - Eigen::MatrixXd::Identity(c.dim, c.dim)).cwiseAbs().maxCoeff(), 1e-9) << "point " << p;
    }
  }
}

// A similarity of the cage (rotation R, scale s) is reproduced by every method: J = s R, det J = s^d. Linear
// elasticity (BEM) reproduces a rotation only when it is removed first (corotational).
TEST_P(JacobianTest, IsTheSimilarityForASimilarityPose) {
  const MethodCase& c = GetParam();
  const JacobianSetup s = setupFor(c.dim);
  const test::TestSimilarity similarity = test::randomSimilarity(c.dim, 11);
  const auto deformer = makeDeformer(c.method, s.cage, s.points);
  const DeformationGradients gradients(*deformer, s.points);
  for (const DeformParams& params : parameterSets(c.method)) {
    if (c.method == methods::bem() && !params.corotational) continue;
    Eigen::MatrixXd positions, J;
    gradients.evaluate(similarity.apply(s.cage.vertices), params, positions, J);
    const Eigen::MatrixXd expected = similarity.scale * similarity.rotation;
    for (int p = 0; p < s.points.rows(); ++p) {
      const Eigen::MatrixXd Jp = jacobianOfRow(J, p, c.dim);
      EXPECT_LE((Jp - expected).cwiseAbs().maxCoeff(), 1e-9 * similarity.scale) << "point " << p;
      EXPECT_NEAR(Jp.determinant(), std::pow(similarity.scale, c.dim), 1e-9 * std::pow(similarity.scale, c.dim));
    }
  }
}

// Points outside the cage follow the exterior rule: their J is marked undefined (NaN), their positions are the
// deformer's.
TEST(Jacobian, MarksPointsThatFollowTheExteriorRule) {
  const Cage cage = test::makeIcosphere(1);
  Eigen::MatrixXd points(3, 3);
  points << 0.1, 0.2, 0.0, 1.5, 0.0, 0.0, 0.0, 0.0, 3.0;
  const auto deformer = makeDeformer(methods::somigliana(), cage, points);
  const DeformationGradients gradients(*deformer, points);
  EXPECT_TRUE(gradients.defined(0));
  EXPECT_FALSE(gradients.defined(1));
  EXPECT_FALSE(gradients.defined(2));
  const Eigen::MatrixXd posed = test::bendPose(cage.vertices, 0.2, 2);
  Eigen::MatrixXd positions, J;
  gradients.evaluate(posed, DeformParams{}, positions, J);
  EXPECT_TRUE(J.row(0).allFinite());
  EXPECT_TRUE(J.row(1).array().isNaN().all());
  EXPECT_LE((positions - deformer->deform(posed, DeformParams{})).cwiseAbs().maxCoeff(), 1e-12);
}

// Float storage (the editor's and the CLI's): the gradient matrices are written in whole packs of points by the
// kernels' streaming writer (somigliana_row_kernels.h), a part pack by the plain one. J agrees with the double
// matrices' to float rounding of the gradients' entries, and a point outside the cage in the middle of a pack still
// has an undefined J: 21 points, so at least two whole packs and a part pack.
TEST(Jacobian, FloatStoredGradientsAgreeWithDoubleOnesToFloatRounding) {
  const JacobianSetup s = setupFor(3);
  Eigen::MatrixXd points = test::randomBallPoints(21, 0.55, 7);
  points.row(5) << 2.0, 0.0, 0.0;  // outside
  PrecomputeOptions floats;
  floats.floatStorage = true;
  const auto doubleDeformer = makeDeformer(methods::somigliana(), s.cage, points);
  const auto floatDeformer = makeDeformer(methods::somigliana(), s.cage, points, floats);
  const DeformationGradients doubles(*doubleDeformer, points), singles(*floatDeformer, points);
  for (const DeformParams& params : parameterSets(methods::somigliana())) {
    Eigen::MatrixXd positions, J, floatPositions, floatJ;
    doubles.evaluate(s.posed, params, positions, J);
    singles.evaluate(s.posed, params, floatPositions, floatJ);
    for (int p = 0; p < points.rows(); ++p) {
      ASSERT_EQ(doubles.defined(p), p != 5);
      ASSERT_EQ(singles.defined(p), p != 5);
      if (p == 5) {
        EXPECT_TRUE(floatJ.row(p).array().isNaN().all());
        continue;
      }
      // float's 6e-8 of entries of about 1 (the coordinates' gradients in a cage of diameter 2), summed over the row
      EXPECT_LE((floatJ.row(p) - J.row(p)).cwiseAbs().maxCoeff(), 1e-5 * std::max(1.0, J.row(p).cwiseAbs().maxCoeff()))
          << "point " << p;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Methods, JacobianTest,
    ::testing::Values(MethodCase{"Somigliana3d", 3, methods::somigliana()}, MethodCase{"Green3d", 3, methods::green()},
                      MethodCase{"MeanValue3d", 3, methods::mvc()}, MethodCase{"Bem3d", 3, methods::bem()},
                      MethodCase{"Somigliana2d", 2, methods::somigliana()}, MethodCase{"Green2d", 2, methods::green()},
                      MethodCase{"MeanValue2d", 2, methods::mvc()}, MethodCase{"Bem2d", 2, methods::bem()}),
    test::methodCaseName);

}  // namespace
}  // namespace somicage
