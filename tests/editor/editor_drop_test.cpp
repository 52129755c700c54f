// Files dropped on the window (drop.h): which dropped .obj is the mesh, the cage and the posed cage (names first,
// then the order), single posed cages, sessions, and the messages that say what to drop; plus openDroppedFiles on
// an AppState.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <memory>

#include "interaction/drop.h"
#include "io/obj_io.h"
#include "job_waiting.h"
#include "model/app_state.h"
#include "model/scene.h"

using namespace somicage;
using namespace somicage::editor;

namespace {
void expectScene(const DropPlan& plan, const std::string& mesh, const std::string& cage, const std::string& posed) {
  ASSERT_EQ(plan.kind, DropPlan::Kind::Scene) << plan.message;
  EXPECT_EQ(plan.mesh, mesh);
  EXPECT_EQ(plan.cage, cage);
  EXPECT_EQ(plan.posed, posed);
}
}  // namespace

TEST(EditorDrop, TwoFilesUseTheCageNameInAnyOrder) {
  expectScene(planDrop({"/m/bunny.obj", "/m/bunny_cage.obj"}, -1, -1), "/m/bunny.obj", "/m/bunny_cage.obj", "");
  expectScene(planDrop({"/m/bunny_cage.obj", "/m/bunny.obj"}, -1, -1), "/m/bunny.obj", "/m/bunny_cage.obj", "");
  expectScene(planDrop({"/m/Cage.OBJ", "/m/x.obj"}, -1, -1), "/m/x.obj", "/m/Cage.OBJ", "");  // case-insensitive
}

TEST(EditorDrop, FoldersNeverDecide) {
  // Both files live in a "cages" folder: only the file names count, so the name "cage" still picks the cage.
  expectScene(planDrop({"/cages/armadillo_cage.obj", "/cages/armadillo.obj"}, -1, -1), "/cages/armadillo.obj",
              "/cages/armadillo_cage.obj", "");
  // And with no marker in either name, the order decides.
  expectScene(planDrop({"/posed/a.obj", "/posed/b.obj"}, -1, -1), "/posed/a.obj", "/posed/b.obj", "");
}

TEST(EditorDrop, TwoFilesWithoutNamesFollowTheOrder) {
  expectScene(planDrop({"a.obj", "b.obj"}, -1, -1), "a.obj", "b.obj", "");
  expectScene(planDrop({"cage1.obj", "cage2.obj"}, -1, -1), "cage1.obj", "cage2.obj", "");  // ambiguous: order
  // Two files: a posed name still counts as the cage.
  expectScene(planDrop({"rest_pose.obj", "mesh.obj"}, -1, -1), "mesh.obj", "rest_pose.obj", "");
}

TEST(EditorDrop, ThreeFilesUseNamesInEveryOrder) {
  const std::vector<std::string> files{"bunny.obj", "bunny_cage.obj", "bunny_cage_deformed.obj"};
  std::vector<int> order{0, 1, 2};
  do {
    const std::vector<std::string> dropped{files[order[0]], files[order[1]], files[order[2]]};
    SCOPED_TRACE(dropped[0] + " " + dropped[1] + " " + dropped[2]);
    expectScene(planDrop(dropped, -1, -1), "bunny.obj", "bunny_cage.obj", "bunny_cage_deformed.obj");
  } while (std::next_permutation(order.begin(), order.end()));
  expectScene(planDrop({"pose.obj", "cage.obj", "mesh.obj"}, -1, -1), "mesh.obj", "cage.obj", "pose.obj");
  expectScene(planDrop({"x_posed.obj", "x.obj", "x_cage.obj"}, -1, -1), "x.obj", "x_cage.obj", "x_posed.obj");
}

TEST(EditorDrop, ThreeFilesSettleWhatTheNamesCanAndOrderTheRest) {
  // Only the posed cage is named: the other two follow the order (mesh, cage).
  expectScene(planDrop({"b.obj", "pose.obj", "a.obj"}, -1, -1), "b.obj", "a.obj", "pose.obj");
  // Two cages, one mesh: the mesh is found, the cages follow the order (rest cage, posed cage).
  expectScene(planDrop({"cage_2.obj", "cage_1.obj", "m.obj"}, -1, -1), "m.obj", "cage_2.obj", "cage_1.obj");
  // Only the cage is named: mesh then posed in the order given.
  expectScene(planDrop({"p.obj", "c_cage.obj", "m.obj"}, -1, -1), "p.obj", "c_cage.obj", "m.obj");
  // No names at all: the order.
  expectScene(planDrop({"1.obj", "2.obj", "3.obj"}, -1, -1), "1.obj", "2.obj", "3.obj");
}

TEST(EditorDrop, OneObjIsAPoseOnlyWithTheCurrentCageVertexCount) {
  const DropPlan pose = planDrop({"/x/anything.obj"}, 20, 20);
  ASSERT_EQ(pose.kind, DropPlan::Kind::Pose);
  EXPECT_EQ(pose.posed, "/x/anything.obj");

  for (const DropPlan& p : {planDrop({"bunny.obj"}, 20, 21), planDrop({"c.obj"}, 20, 8), planDrop({"c.obj"}, -1, -1),
                            planDrop({"c.obj"}, 20, -1)}) {
    EXPECT_EQ(p.kind, DropPlan::Kind::Error);
    EXPECT_NE(p.message.find("2 .obj files"), std::string::npos) << p.message;  // says what to drop
  }
  EXPECT_NE(planDrop({"c.obj"}, 20, 8).message.find("8 vertices"), std::string::npos);
}

TEST(EditorDrop, SessionsAndMistakes) {
  const DropPlan s = planDrop({"/s/Session.JSON"}, -1, -1);
  ASSERT_EQ(s.kind, DropPlan::Kind::Session);
  EXPECT_EQ(s.session, "/s/Session.JSON");
  EXPECT_EQ(planDrop({"s.json", "m.obj"}, -1, -1).kind, DropPlan::Kind::Error);
  EXPECT_EQ(planDrop({"a.obj", "b.obj", "c.obj", "d.obj"}, -1, -1).kind, DropPlan::Kind::Error);
  EXPECT_EQ(planDrop({}, -1, -1).kind, DropPlan::Kind::Error);
  const DropPlan png = planDrop({"a.obj", "shot.png"}, -1, -1);
  EXPECT_EQ(png.kind, DropPlan::Kind::Error);
  EXPECT_NE(png.message.find("shot.png"), std::string::npos);
  EXPECT_EQ(planDrop({"/a.dir/noext"}, -1, -1).kind, DropPlan::Kind::Error);
  EXPECT_EQ(lowerExtension("/a.dir/noext"), "");
  EXPECT_EQ(lowerExtension("/a/B.Obj"), ".obj");
}

TEST(EditorDrop, CountsObjVerticesAndStopsEarly) {
  const std::string path = ::testing::TempDir() + "somicage_drop_count.obj";
  {
    std::ofstream out(path);
    out << "# comment\nv 0 0 0\nvt 0 0\nvn 0 0 1\n  v 1 0 0\nv\t0 1 0\nf 1 2 3\nv 1 1 1\n";
  }
  EXPECT_EQ(countObjVertices(path, 100), 4);
  EXPECT_EQ(countObjVertices(path, 2), 3);  // limit + 1: more than the limit
  EXPECT_EQ(countObjVertices(path + ".missing", 100), -1);
  std::remove(path.c_str());
}

TEST(EditorDrop, OpenDroppedFilesPosesTheSceneOrExplains) {
  AppState state;
  auto scene = std::make_shared<Scene>(makeDemoScene(3));
  state.model.scene = scene;
  state.document.pose = scene->restCage.vertices;
  state.input.selection.resize(scene->restCage.numVertices());
  state.document.history.reset(currentDocument(state), "Open demo", true);

  // A posed cage with the cage's vertex count poses the current scene (an undoable edit).
  const std::string posedPath = ::testing::TempDir() + "somicage_drop_posed.obj";
  Eigen::MatrixXd posed = scene->restCage.vertices;
  posed.col(1).array() += 0.25;
  saveObj(posedPath, posed, cageTopology(scene->restCage));
  openDroppedFiles(state, {posedPath});
  waitUntilDone(state.jobs.posedCage);  // counted and read on its job, applied by the poll
  pollPosedCage(state);
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  EXPECT_LT((state.document.pose - posed).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_TRUE(state.document.history.canUndo());

  // A single mesh: an error that says what to drop; the scene and pose stay.
  const std::string meshPath = ::testing::TempDir() + "somicage_drop_mesh.obj";
  PolygonMesh tri;
  tri.faces = {{0, 1, 2}};
  saveObj(meshPath, Eigen::MatrixXd::Identity(3, 3), tri);
  openDroppedFiles(state, {meshPath});
  waitUntilDone(state.jobs.posedCage);
  EXPECT_FALSE(pollPosedCage(state));
  ASSERT_EQ(state.status.errors.size(), 1u);
  EXPECT_NE(state.status.errors.front().find("3 vertices"), std::string::npos) << state.status.errors.front();
  EXPECT_EQ(state.model.scene, scene);
  EXPECT_LT((state.document.pose - posed).cwiseAbs().maxCoeff(), 1e-9);
  std::remove(posedPath.c_str());
  std::remove(meshPath.c_str());
}
