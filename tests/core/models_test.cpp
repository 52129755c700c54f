// The models of ../shared/models (published meshes, cages and poses): every triangle cage loads, the partition of
// unity holds on its mesh to 1e-9 (the requirement; the closed form reaches ~1e-14), and every posed
// cage deforms the mesh without NaN. Skips visibly when the folder is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "coordinates/somigliana_coordinates.h"
#include "deform/deformer.h"
#include "methods/method_descriptors.h"
#include "test_models.h"

namespace somicage {
namespace {

using test::ModelCase;

class ModelsTest : public ::testing::TestWithParam<ModelCase> {};

TEST_P(ModelsTest, CageLoadsAndPartitionOfUnityHolds) {
  const ModelCase& c = GetParam();
#ifdef SOMICAGE_SANITIZE
  const int stride = 0;  // instrumented code is ~20x slower: at most kMaxModelPoints points, spread over the mesh
#else
  const int stride = 1;
#endif
  Cage cage;
  Eigen::MatrixXd points;
  if (!test::loadModel(c, cage, points, stride)) return;
  // The inside share is exact on the whole mesh (within 0.02 of models/README.md); a subsample only estimates it,
  // within three binomial standard deviations.
  const double shareTolerance = stride == 1 ? 0.02 : 0.02 + 1.5 / std::sqrt(static_cast<double>(points.rows()));

  const SomiglianaCoordinates coords = computeSomiglianaCoordinates(cage, points);
  const Eigen::VectorXd residual = partitionOfUnityResidual(coords);
  double worst = 0;
  int inside = 0;
  for (int p = 0; p < coords.numPoints(); ++p)
    if (coords.winding(p) > 0.5) worst = std::max(worst, residual(p)), ++inside;
  EXPECT_LE(worst, 1e-9) << c.cage;
  EXPECT_NEAR(static_cast<double>(inside) / coords.numPoints(), c.insideFraction, shareTolerance) << c.cage;
  RecordProperty("pou_max", std::to_string(worst));

  if (c.pose.empty()) return;
  const Eigen::MatrixXd posed = loadPosedVertices(test::modelPath(c, c.pose), cage);
  const auto deformer = makeDeformer(methods::somigliana(), cage, points, {}, noProgress);
  for (double blend : {0.0, 1.0}) {
    const Eigen::MatrixXd out = deformer->deform(posed, {blend, 0.3, 1.0, true});
    EXPECT_TRUE(out.allFinite()) << c.pose << " blend " << blend;
  }
}

INSTANTIATE_TEST_SUITE_P(SharedModels, ModelsTest, ::testing::ValuesIn(test::modelCases()), test::modelCaseName);

}  // namespace
}  // namespace somicage
