// The units warning: a mesh that fits its cage gets none; one scaled by a unit factor, or moved beside the cage, gets
// one sentence naming both files and the factor.
#include "geometry/mesh_placement.h"

#include <gtest/gtest.h>

#include <cmath>

#include "test_shapes.h"

namespace somicage {
namespace {

Cage unitSquare() { return test::makeUnitSquare(); }

TEST(MeshPlacement, AMeshInsideItsCageFits) {
  Eigen::MatrixXd points(3, 2);
  points << 0.2, 0.2, 0.8, 0.3, 0.5, 0.9;
  const MeshPlacement placement = measureMeshPlacement(unitSquare(), points);
  EXPECT_NEAR(placement.sizeRatio, std::hypot(0.6, 0.7) / std::sqrt(2.0), 1e-15);
  EXPECT_FALSE(placement.disjoint);
  EXPECT_FALSE(describeMeshPlacement(placement, "m.obj", "c.obj"));
  // A single point, or a mesh a little larger than the cage (a few points outside), is no units problem either.
  EXPECT_FALSE(describeMeshPlacement(measureMeshPlacement(unitSquare(), points.topRows(1)), "m.obj", "c.obj"));
  EXPECT_FALSE(describeMeshPlacement(measureMeshPlacement(unitSquare(), 3 * points), "m.obj", "c.obj"));
}

TEST(MeshPlacement, UnitFactorsAndOffsetsAreNamed) {
  Eigen::MatrixXd points(2, 2);
  points << 0, 0, 1, 1;  // the cage's own diagonal
  const auto larger = describeMeshPlacement(measureMeshPlacement(unitSquare(), 1000 * points), "m.obj", "c.obj");
  ASSERT_TRUE(larger);
  EXPECT_EQ(larger->rfind("the mesh m.obj and the cage c.obj do not fit: the mesh is 1000 times the size of the cage: "
                          "are the two files in different units",
                          0),
            0u)
      << *larger;
  const auto inches = describeMeshPlacement(measureMeshPlacement(unitSquare(), points / 25.4), "m.obj", "c.obj");
  EXPECT_FALSE(inches) << "25.4 times smaller is a small part, not a units error";
  const auto smaller = describeMeshPlacement(measureMeshPlacement(unitSquare(), points / 1e4), "m.obj", "c.obj");
  ASSERT_TRUE(smaller);
  EXPECT_NE(smaller->find("the mesh is 10000 times smaller than the cage"), std::string::npos) << *smaller;
  const auto beside =
      describeMeshPlacement(measureMeshPlacement(unitSquare(), points.rowwise() + Eigen::RowVector2d(5, 0)), "m", "c");
  ASSERT_TRUE(beside);
  EXPECT_NE(beside->find("do not overlap: the mesh lies beside the cage"), std::string::npos) << *beside;
}

}  // namespace
}  // namespace somicage
