// Relations between the methods (paper section 5, "Comparisons"): in 2D, Somigliana coordinates with
// nu = +-infinity and gamma = 0 are exactly Green coordinates; in 3D they are not.
#include <gtest/gtest.h>

#include <limits>

#include "deform/deformer.h"
#include "methods/method_descriptors.h"
#include "test_shapes.h"

namespace somicage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(MethodComparison, Somigliana2DAtInfiniteNuEqualsGreen) {
  // The traction scale s_j = eta - lambda vanishes and T_i reduces to the Cauchy-Green kernel, which commutes
  // with rotations (paper section 5); so the results agree to round-off, asserted at 1e-9 of the cage diameter.
  const Cage cage = test::makeStarPolygon(6);
  const Eigen::MatrixXd points = test::randomDiscPoints(200, 0.45, 17);
  const auto somigliana = makeDeformer(methods::somigliana(), cage, points);
  const auto green = makeDeformer(methods::green(), cage, points);
  for (unsigned seed : {1u, 2u, 3u}) {
    const Eigen::MatrixXd posed = test::bendPose(cage.vertices, 0.4, seed);
    const Eigen::MatrixXd expected = green->deform(posed, {});
    for (double nu : {kInf, -kInf})
      for (double blend : {0.0, 0.5, 1.0})
        for (bool fix : {true, false}) {
          const Eigen::MatrixXd actual = somigliana->deform(posed, {blend, nu, 0.0, fix});
          EXPECT_LT((actual - expected).rowwise().norm().maxCoeff(), 1e-9 * cageDiameter(posed))
              << "seed " << seed << " nu " << nu << " blend " << blend << " fix " << fix;
        }
  }
}

TEST(MethodComparison, Somigliana3DAtInfiniteNuDiffersFromGreenOnlyBeyondSimilarities) {
  // In 3D the limit keeps an antisymmetric part in T_i and a traction scale eta - 2 lambda != 0 (section 5), so the
  // two are different deformers; both reproduce a similarity pose exactly (each moves every interior point by the
  // similarity, an independent closed form), so they agree there to round-off (1e-8 diameters) and differ by more
  // than 1e-3 diameters on a bend.
  const Cage cage = test::makeBumpySphere(1);
  const Eigen::MatrixXd points = test::randomBallPoints(200, 0.6, 3);
  const auto somigliana = makeDeformer(methods::somigliana(), cage, points);
  const auto green = makeDeformer(methods::green(), cage, points);
  const test::TestSimilarity similarity = test::randomSimilarity(3, 4);
  const Eigen::MatrixXd moved = similarity.apply(cage.vertices), expected = similarity.apply(points);
  const double movedDiameter = cageDiameter(moved);
  EXPECT_LT((somigliana->deform(moved, {0, kInf, 0, true}) - expected).rowwise().norm().maxCoeff(),
            1e-8 * movedDiameter);
  EXPECT_LT((green->deform(moved, {}) - expected).rowwise().norm().maxCoeff(), 1e-8 * movedDiameter);
  const Eigen::MatrixXd posed = test::bendPose(cage.vertices, 0.4, 2);
  EXPECT_GT((somigliana->deform(posed, {0, kInf, 0, true}) - green->deform(posed, {})).rowwise().norm().maxCoeff(),
            1e-3 * cageDiameter(posed));
}

}  // namespace
}  // namespace somicage
