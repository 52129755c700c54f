// The precompute's SIMD packs (core/base/simd_pack.h, simd_math.h) against the scalar closed form, which stays the
// reference (IntegrationOptions::scalarKernel): every coordinate term and winding number agrees to 1e-13 of the
// term's size (at least 1), on small cages with points from 1e-7 to 0.1 inside their faces and on a subsample of every
// shared model, and the packs' partition of unity holds to 1e-12 inside the shared models' cages.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "base/simd_pack.h"
#include "coordinates/somigliana_coordinates.h"
#include "recorded_number.h"
#include "test_models.h"
#include "test_shapes.h"

namespace somicage {
namespace {

using test::scientific;

// The largest |packs - scalar| / max(1, |scalar|) over every term and winding number.
double worstDifference(const Cage& cage, const Eigen::MatrixXd& points) {
  IntegrationOptions scalar;
  scalar.scalarKernel = true;
  const SomiglianaCoordinates reference = computeSomiglianaCoordinates(cage, points, scalar);
  const SomiglianaCoordinates packs = computeSomiglianaCoordinates(cage, points);
  const Eigen::ArrayXXd scale = reference.values.array().abs().max(1.0);
  return std::max(((packs.values - reference.values).array().abs() / scale).maxCoeff(),
                  (packs.winding - reference.winding).cwiseAbs().maxCoeff());
}

TEST(SimdPrecompute, AgreesWithTheScalarClosedFormNearAndFarFromFaces) {
  for (const Cage& cage : {test::makeCube(), test::makeIcosphere(2), test::makeExtrudedL()}) {
    // 4k + 3 points, so that the last pack is partly padding; offsets down to 1e-7 of the cage's size.
    Eigen::MatrixXd points(4 * 60 + 3, 3);
    points << test::pointsNearFaces(cage, 80, 1e-1, 1), test::pointsNearFaces(cage, 80, 1e-3, 2),
        test::pointsNearFaces(cage, 83, 1e-7, 3);
    const double worst = worstDifference(cage, points);
    EXPECT_LE(worst, 1e-13) << cage.numFaces() << " faces";
    RecordProperty("worst_difference_" + std::to_string(cage.numFaces()) + "_faces", scientific(worst));
  }
}

class SimdPrecomputeModels : public ::testing::TestWithParam<test::ModelCase> {};

TEST_P(SimdPrecomputeModels, AgreesWithTheScalarClosedFormAndPartitionOfUnityHolds) {
  Cage cage;
  Eigen::MatrixXd sample;
  if (!test::loadModel(GetParam(), cage, sample)) return;
  Eigen::MatrixXd points(std::min<Eigen::Index>(sample.rows(), 201), 3);  // a quick subsample, 4k + 1 points
  for (Eigen::Index p = 0; p < points.rows(); ++p) points.row(p) = sample.row(p * (sample.rows() / points.rows()));
  const double worst = worstDifference(cage, points);
  EXPECT_LE(worst, 1e-13);
  RecordProperty("worst_difference", scientific(worst));
  const SomiglianaCoordinates packs = computeSomiglianaCoordinates(cage, points);
  const Eigen::VectorXd residual = partitionOfUnityResidual(packs);
  for (Eigen::Index p = 0; p < points.rows(); ++p)
    if (packs.winding(p) > 0.5) {
      EXPECT_LE(residual(p), 1e-12) << "point " << p;
    }
}

INSTANTIATE_TEST_SUITE_P(SharedModels, SimdPrecomputeModels, ::testing::ValuesIn(test::modelCases()),
                         test::modelCaseName);

}  // namespace
}  // namespace somicage
