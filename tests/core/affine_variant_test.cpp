// The affine variant (VariantKind::Affine): the best-fit affine map A = R S and tractions R sigma(S) n_j. With
// exact coordinates, sum_i T_i = I and the Somigliana identity, any affine pose x -> A x + b is reproduced exactly,
// for every nu (the identity holds for the linear field S x with stress sigma(S)); the similarity variant misses it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <limits>
#include <random>

#include "deform/boundary_conditions.h"
#include "deform/deformer.h"
#include "deform/jacobian.h"
#include "io/obj_io.h"
#include "methods/method_descriptors.h"
#include "test_models.h"
#include "test_shapes.h"

namespace somicage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

DeformParams affineParams(double nu, double gamma = 0) {
  DeformParams p{0.0, nu, gamma, true};
  p.kind = VariantKind::Affine;
  return p;
}

// A random affine map with det A > 0: a rotation times a symmetric stretch with singular values in [0.6, 1.6], and
// a shear on top.
AffineMap randomAffine(int d, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(d, d);
  for (int a = 0; a < d; ++a)
    for (int b = 0; b < d; ++b) M(a, b) += 0.35 * uniform(rng);
  if (M.determinant() < 0) M.col(0) *= -1;
  AffineMap map;
  map.linear = M;
  map.translation = Eigen::VectorXd(d);
  for (int a = 0; a < d; ++a) map.translation(a) = uniform(rng);
  return map;
}

Eigen::MatrixXd apply(const AffineMap& map, const Eigen::MatrixXd& points) {
  return (points * map.linear.transpose()).rowwise() + map.translation.transpose();
}

TEST(AffineVariant, FitAffineRecoversAnAffineMap) {
  for (int d : {2, 3}) {
    const Eigen::MatrixXd V = test::makeBumpySphere(0).vertices.leftCols(d);
    const AffineMap map = randomAffine(d, 3);
    const AffineMap fit = fitAffine(V, apply(map, V));
    EXPECT_LT((fit.linear - map.linear).norm(), 1e-13);
    EXPECT_LT((fit.translation - map.translation).norm(), 1e-13);
  }
}

TEST(AffineVariant, ReproducesAffinePosesForEveryNu) {
  // 1e-9 diameters (round-off of the closed-form integrals, partition of unity ~1e-14); the global variant misses
  // the same poses by more than 1e-3 diameters.
  for (int d : {2, 3}) {
    const Cage cage = d == 3 ? test::makeBumpySphere(1) : test::makeStarPolygon(6);
    const Eigen::MatrixXd points = d == 3 ? test::randomBallPoints(60, 0.6, 9) : test::randomDiscPoints(60, 0.4, 9);
    const auto deformer = makeDeformer(methods::somigliana(), cage, points, {}, noProgress);
    for (unsigned seed : {1u, 2u}) {
      const AffineMap map = randomAffine(d, seed);
      const Eigen::MatrixXd posed = apply(map, cage.vertices), expected = apply(map, points);
      const double diameter = cageDiameter(posed);
      for (double nu : {-0.9, -0.5, 0.0, 0.3, 0.45, 0.49, kInf, -kInf}) {
        for (bool fix : {true, false}) {
          DeformParams p = affineParams(nu);
          p.tractionCorrection = fix;
          const Eigen::MatrixXd out = deformer->deform(posed, p);
          EXPECT_LT((out - expected).rowwise().norm().maxCoeff(), 1e-9 * diameter) << d << "D nu " << nu;
        }
        const Eigen::MatrixXd global = deformer->deform(posed, {0.0, nu, 0.0, true});
        EXPECT_GT((global - expected).rowwise().norm().maxCoeff(), 1e-3 * diameter) << d << "D nu " << nu;
      }
    }
  }
}

TEST(AffineVariant, TheExactGradientOfAnAffinePoseIsA) {
  // J from the dual-number gradients of C (jacobian.h), the affine terms' included: A everywhere, to 1e-9.
  const Cage cage = test::makeBumpySphere(1);
  const Eigen::MatrixXd points = test::randomBallPoints(20, 0.6, 4);
  const auto deformer = makeDeformer(methods::somigliana(), cage, points, {}, noProgress);
  const DeformationGradients gradients(*deformer, points);
  const AffineMap map = randomAffine(3, 7);
  Eigen::MatrixXd positions, jacobians;
  gradients.evaluate(apply(map, cage.vertices), affineParams(0.45), positions, jacobians);
  for (int p = 0; p < points.rows(); ++p)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) EXPECT_NEAR(jacobians(p, a * 3 + b), map.linear(a, b), 1e-9) << p;
}

TEST(AffineVariant, PointsOutsideTheCageFollowTheAffineMap) {
  // The exterior rule (exterior_points.h) moves a point far outside by the frame's map: A x + b here.
  const Cage cage = test::makeBumpySphere(1);
  Eigen::MatrixXd points(2, 3);
  points << 0.1, 0.2, 0.0, 4.0, 1.0, -2.0;
  const auto deformer = makeDeformer(methods::somigliana(), cage, points, {}, noProgress);
  const AffineMap map = randomAffine(3, 5);
  const Eigen::MatrixXd out = deformer->deform(apply(map, cage.vertices), affineParams(0.3));
  EXPECT_LT((out - apply(map, points)).rowwise().norm().maxCoeff(), 1e-9 * cageDiameter(cage.vertices));
}

TEST(AffineVariant, IsTheGlobalVariantOnSimilarityPoses) {
  // A = s R: S = s I, sigma n_j = s (2 + d lambda) n_j, the global variant's traction (Eq. 14 with eta = lambda = s).
  for (int d : {2, 3}) {
    const Cage cage = d == 3 ? test::makeBumpySphere(1) : test::makeStarPolygon(6);
    const Eigen::MatrixXd points = d == 3 ? test::randomBallPoints(30, 0.6, 2) : test::randomDiscPoints(30, 0.4, 2);
    const auto deformer = makeDeformer(methods::somigliana(), cage, points, {}, noProgress);
    const test::TestSimilarity s = test::randomSimilarity(d, 6);
    const Eigen::MatrixXd posed = s.apply(cage.vertices);
    for (double nu : {0.0, 0.3, 0.45}) {
      const Eigen::MatrixXd affine = deformer->deform(posed, affineParams(nu));
      const Eigen::MatrixXd global = deformer->deform(posed, {0.0, nu, 0.0, true});
      EXPECT_LT((affine - global).rowwise().norm().maxCoeff(), 1e-9 * cageDiameter(posed)) << d << "D nu " << nu;
    }
  }
}

// BOTIJO (shared models): a random affine pose of its cage moves its mesh by the same map, to 1e-9 diameters, for
// every nu; the global variant misses it by ~1e-1 (issue 26 measured 7.6e-2 for one such pose).
TEST(AffineVariant, ReproducesAnAffinePoseOfBotijo) {
  test::ModelCase botijo;
  for (const test::ModelCase& c : test::modelCases())
    if (c.folder == "botijo") botijo = c;
  Cage cage;
  Eigen::MatrixXd points;
#ifdef SOMICAGE_SANITIZE
  const int stride = 0;
#else
  const int stride = 20;  // ~1,000 of its vertices
#endif
  if (!test::loadModel(botijo, cage, points, stride)) return;
  const auto deformer = makeDeformer(methods::somigliana(), cage, points, {}, noProgress);
  const AffineMap map = randomAffine(3, 11);
  const Eigen::MatrixXd posed = apply(map, cage.vertices), expected = apply(map, points);
  const double diameter = cageDiameter(posed);
  double worst = 0, globalMiss = 0;
  for (double nu : {0.0, 0.3, 0.45, 0.49, kInf}) {
    worst = std::max(worst, (deformer->deform(posed, affineParams(nu)) - expected).rowwise().norm().maxCoeff());
    globalMiss = std::max(globalMiss,
                          (deformer->deform(posed, {0.0, nu, 0.0, true}) - expected).rowwise().norm().maxCoeff());
  }
  EXPECT_LT(worst, 1e-9 * diameter);
  EXPECT_GT(globalMiss, 1e-2 * diameter);
  std::printf("  BOTIJO affine pose: affine variant %.1e, global %.1e diameters\n", worst / diameter,
              globalMiss / diameter);
}

}  // namespace
}  // namespace somicage
