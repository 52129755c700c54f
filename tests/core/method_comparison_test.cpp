// Relations between the methods (paper section 5, "Comparisons"): in 2D, Somigliana coordinates with
// nu = +-infinity and gamma = 0 are exactly Green coordinates; in 3D they are not.
#include <gtest/gtest.h>

#include <limits>

#include "deformer.h"
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

TEST(MethodComparison, Somigliana3DAtInfiniteNuDiffersFromGreen) {
  // In 3D the limit keeps an antisymmetric part in T_i and a traction scale eta - 2 lambda != 0 (section 5):
  // on a real pose the two deformers differ by more than 1e-3 diameters somewhere.
  const Cage cage = test::makeBumpySphere(1);
  const Eigen::MatrixXd points = test::randomBallPoints(200, 0.6, 3);
  const Eigen::MatrixXd posed = test::bendPose(cage.vertices, 0.4, 2);
  const Eigen::MatrixXd somigliana =
      makeDeformer(methods::somigliana(), cage, points)->deform(posed, {0, kInf, 0, true});
  const Eigen::MatrixXd green = makeDeformer(methods::green(), cage, points)->deform(posed, {});
  EXPECT_GT((somigliana - green).rowwise().norm().maxCoeff(), 1e-3 * cageDiameter(posed));
}

}  // namespace
}  // namespace somicage
