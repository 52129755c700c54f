// CGAL's tetrahedra of a cage (core/cage_tetrahedralization.cpp): the cage's vertices first and exactly, a mesh
// of the cage that checkVolumeMesh accepts as it is, finer with each level.
#include "cage_tetrahedralization.h"

#include <gtest/gtest.h>

#include "core/test_models.h"
#include "core/test_shapes.h"
#include "core/volume_mesh_checks.h"
#include "errors.h"

namespace somicage {
namespace {

void expectMeshOf(const Cage& cage, VolumeMesh mesh, double volume) {
  ASSERT_GE(mesh.numVertices(), cage.numVertices());
  EXPECT_EQ(mesh.vertices.topRows(cage.numVertices()), cage.vertices) << "the cage's vertices, exactly, in order";
  for (int s = 0; s < mesh.numSimplices(); ++s) EXPECT_GT(signedSimplexMeasure(mesh, s), 0);
  EXPECT_NEAR(test::totalMeasure(mesh), volume, 1e-12 * volume);
  EXPECT_EQ(checkVolumeMesh(mesh, cage, {"generated", {}, {}}), 0);
}

TEST(CageTetrahedralization, MeshesTheCubeAndTheExtrudedLFinerWithEachLevel) {
  struct Case {
    Cage cage;
    double volume;
  };
  for (const Case& c : {Case{test::makeCube(), 8.0}, Case{test::makeExtrudedL(), 3.0}}) {
    // Finer than level 0 at every level above it. Neighbouring levels may tie within a few vertices: Mesh_3's
    // refinement is not monotone in its size bound (the extruded L gave 314 then 313 at levels 1 and 2).
    int coarsest = 0;
    for (int level = 0; level <= 2; ++level) {
      SCOPED_TRACE("level " + std::to_string(level));
      const VolumeMesh mesh = tetrahedralizeCage(c.cage, level);
      expectMeshOf(c.cage, mesh, c.volume);
      if (level == 0)
        coarsest = mesh.numVertices();
      else
        EXPECT_GT(mesh.numVertices(), coarsest);
    }
  }
}

TEST(CageTetrahedralization, MeshesTheFireHydrantsCage) {
#ifdef SOMICAGE_SANITIZE
  GTEST_SKIP() << "3 s of CGAL meshing here, a minute instrumented: the small cages above cover the code";
#endif
  const test::ModelCase c = test::modelCases().front();
  if (test::skipIfModelAbsent(c)) return;
  const Cage cage = loadCage(test::modelPath(c, c.cage));
  expectMeshOf(cage, tetrahedralizeCage(cage, kDefaultTetLevel), signedMeasure(cage.vertices, cage.faces));
}

TEST(CageTetrahedralization, RefusesAnUnknownLevel) {
  try {
    tetrahedralizeCageWithOptions(test::makeCube(), {{"tet-level", "9"}});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "--tet-level");
  }
}

}  // namespace
}  // namespace somicage
