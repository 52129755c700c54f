// core/generation/cage_generation.h on every mesh of ../shared/models (skipped visibly when absent), at the face count
// of the model's hand-made cage, checked by generated_cage_checks.h. How tight the cages are is measured, not asserted
// here (docs/cli.md's table compares them with the hand-made ones). Labelled "slow" (about two minutes in all on two
// busy cores): run_all.sh runs it, the sanitizer build does not.
#include <gtest/gtest.h>

#include "core/generated_cage_checks.h"
#include "core/test_models.h"
#include "generation/cage_enclosure.h"
#include "generation/cage_generation.h"
#include "io/mesh_formats.h"

namespace somicage {
namespace {

class GeneratedCageOnModel : public ::testing::TestWithParam<test::ModelCase> {};

TEST_P(GeneratedCageOnModel, EnclosesTheMeshAtTheHandMadeFaceCount) {
  const test::ModelCase& c = GetParam();
  if (test::skipIfModelAbsent(c)) return;
  const Cage handMade = loadCage(test::modelPath(c, c.cage));
  const PolygonMesh mesh = loadMesh(test::modelPath(c, c.mesh));
  const Eigen::MatrixXi triangles = triangulatePolygons(mesh.vertices, mesh.faces);
  CageGenerationOptions options;
  options.maxFaces = handMade.numFaces();
  const GeneratedCage generated = generateCage(mesh.vertices, triangles, options, c.mesh);
  test::expectGeneratedCageValid(generated.cage, mesh.vertices, triangles, options.maxFaces, 300);
  EXPECT_GE(generated.minAngleDegrees, 1.0);
  RecordProperty("generated_hausdorff",
                 std::to_string(measureTightness(generated.cage, mesh.vertices, triangles).hausdorff));
}

// One case per mesh: the first listed hand-made cage of each (the others are variants of the same mesh).
std::vector<test::ModelCase> oneCasePerMesh() {
  std::vector<test::ModelCase> cases;
  for (const test::ModelCase& c : test::modelCases()) {
    bool seen = false;
    for (const test::ModelCase& k : cases) seen = seen || (k.folder == c.folder && k.mesh == c.mesh);
    if (!seen && c.insideFraction == 1.0) cases.push_back(c);
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(SharedModels, GeneratedCageOnModel, ::testing::ValuesIn(oneCasePerMesh()),
                         test::modelCaseName);

}  // namespace
}  // namespace somicage
