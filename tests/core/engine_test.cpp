// The engine facade (core/engine/engine.h): the one load order (repair, validate, notices, refusal), the placement
// warning, the pose and parameter checks with the command line's messages, the memory refusal and cancel.
#include "engine/engine.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

#include "base/errors.h"
#include "methods/method_descriptors.h"
#include "test_shapes.h"

namespace somicage {
namespace {

struct Recorder {
  std::vector<Notice> notices;
  NoticeSink sink() {
    return [this](const Notice& n) { notices.push_back(n); };
  }
};

TEST(Engine, RepairsAnInsideOutCageAndSaysSo) {
  Cage flipped = test::makeCube();
  flipped.faces.col(1).swap(flipped.faces.col(2));
  Recorder r;
  const Cage cage = prepareCage(flipped, "cube.obj", r.sink());
  ASSERT_EQ(r.notices.size(), 1u);
  EXPECT_EQ(r.notices[0].kind, Notice::Kind::Repair);
  EXPECT_EQ(r.notices[0].source, "cube.obj");
  EXPECT_GT(signedMeasure(cage.vertices, cage.faces), 0.0) << "outward after the repair";
  EXPECT_LT(signedMeasure(flipped.vertices, flipped.faces), 0.0);
}

TEST(Engine, AnUnusableCageIsRefusedNamingItsSource) {
  Cage open = test::makeCube();
  open.faces.conservativeResize(open.faces.rows() - 1, 3);  // a hole: not closed, nothing to repair
  Recorder r;
  try {
    prepareCage(open, "open.obj", r.sink());
    FAIL() << "an open cage was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "open.obj");
  }
  EXPECT_TRUE(r.notices.empty());
}

TEST(Engine, AMeshBesideTheCageIsWarnedAboutWithBothNames) {
  const Cage cage = test::makeCube();
  Eigen::MatrixXd far = test::randomBoxPoints(20, 3, 0.2, 0.8, 1);
  far.col(0).array() += 100.0;
  Recorder r;
  const Eigen::MatrixXd points = meshPointsFor(cage, far, "mesh.obj", "cage.obj", r.sink());
  EXPECT_EQ(points, far);
  ASSERT_EQ(r.notices.size(), 1u);
  EXPECT_EQ(r.notices[0].kind, Notice::Kind::Warning);
  EXPECT_NE(r.notices[0].text.find("mesh.obj"), std::string::npos) << r.notices[0].text;
  EXPECT_NE(r.notices[0].text.find("cage.obj"), std::string::npos) << r.notices[0].text;
  r.notices.clear();
  // A 2D cage takes x, y of a mesh, and a mesh inside it says nothing.
  const Cage square = makePolygonCage(test::lLoop());
  Eigen::MatrixXd flat = Eigen::MatrixXd::Zero(5, 3);
  flat.leftCols(2) = test::randomBoxPoints(5, 2, 0.2, 0.8, 2);
  EXPECT_EQ(meshPointsFor(square, flat, "m", "c", r.sink()), flat.leftCols(2));
  EXPECT_TRUE(r.notices.empty());
}

TEST(Engine, PosesAndParametersAreCheckedWithTheirNames) {
  const Cage cage = test::makeCube();
  const Eigen::MatrixXd points = test::randomBoxPoints(10, 3, 0.3, 0.7, 4);
  const auto deformer = precompute(methods::somigliana(), cage, points, {}, "points");
  auto problemOf = [&](const Eigen::MatrixXd& posed, const DeformParams& params) -> std::string {
    try {
      deformPoints(*deformer, cage, posed, params, "pose", "points");
    } catch (const InputError& e) {
      return e.source() + ": " + e.problem();
    }
    return "";
  };
  EXPECT_EQ(problemOf(cage.vertices, {}), "");
  EXPECT_EQ(problemOf(cage.vertices.topRows(5), {}), "pose: the posed cage has 5 vertices, the rest cage has 8");
  EXPECT_EQ(problemOf(cage.vertices.leftCols(2), {}),
            "pose: the posed cage has 2 coordinates per vertex, the rest cage 3");
  Eigen::MatrixXd nan = cage.vertices;
  nan(3, 1) = std::nan("");
  EXPECT_EQ(problemOf(nan, {}), "pose: posed vertex 3 is not finite");
  DeformParams bad;
  bad.nu = 0.5;
  EXPECT_EQ(problemOf(cage.vertices, bad).rfind("nu: Poisson ratio", 0), 0u) << problemOf(cage.vertices, bad);
  // At rest every method reproduces its points (inside the cage).
  for (Method m : allMethods()) {
    const Eigen::MatrixXd out =
        deformPoints(*precompute(m, cage, points, {}, "points"), cage, cage.vertices, {}, "pose", "points");
    EXPECT_LT((out - points).cwiseAbs().maxCoeff(), 1e-9) << methodName(m);
  }
}

TEST(Engine, APrecomputeThatWouldNotFitIsRefusedBeforeItStarts) {
  ASSERT_EQ(setenv(kMemoryLimitVariable, "1000", 1), 0);
  const Cage cage = test::makeCube();
  bool started = false;
  try {
    precompute(methods::somigliana(), cage, test::randomBoxPoints(100, 3, 0.3, 0.7, 5), {}, "points.obj",
               [&](double) { return started = true; });
    ADD_FAILURE() << "no refusal";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "points.obj");
    EXPECT_NE(e.problem().find("but only 1 kB are free"), std::string::npos) << e.problem();
  }
  unsetenv(kMemoryLimitVariable);
  EXPECT_FALSE(started);
}

TEST(Engine, APrecomputeIsCancelledThroughItsProgress) {
  const Cage cage = test::makeCube();
  for (Method m : allMethods())
    EXPECT_THROW(
        precompute(m, cage, test::randomBoxPoints(5000, 3, 0.3, 0.7, 6), {}, "points", [](double) { return false; }),
        Cancelled)
        << methodName(m);
}

}  // namespace
}  // namespace somicage
