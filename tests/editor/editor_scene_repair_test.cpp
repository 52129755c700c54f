// Loading files into the editor repairs the cage as the command line does (core/cage/cage_repair.h), keeps what was
// done as notices that the status bar shows, and refuses a cage that stays invalid.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "base/errors.h"
#include "cage/cage_validation.h"
#include "generation/cage_generation.h"
#include "io/obj_io.h"
#include "job_waiting.h"
#include "model/app_state.h"
#include "model/scene.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

// The cube [-1, 1]^3, outward, and a point set inside it, written to a fresh folder.
struct CubeFiles {
  std::filesystem::path dir;
  Cage cube;
  std::string mesh;

  explicit CubeFiles(const std::string& name) : dir(std::filesystem::path(::testing::TempDir()) / name) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    cube.vertices.resize(8, 3);
    for (int i = 0; i < 8; ++i) cube.vertices.row(i) << (i & 1 ? 1 : -1), (i & 2 ? 1 : -1), (i & 4 ? 1 : -1);
    cube.faces.resize(12, 3);
    cube.faces << 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1,
        7, 5;
    mesh = (dir / "points.obj").string();
    PolygonMesh soup;  // triangles through the points: a mesh with faces (a point set would get its own notice)
    for (int k = 0; k + 2 < 20; k += 3) soup.faces.push_back({k, k + 1, k + 2});
    saveObj(mesh, Eigen::MatrixXd::Random(20, 3) * 0.5, soup);
  }
  ~CubeFiles() { std::filesystem::remove_all(dir); }

  std::string cage(const std::string& name, const Cage& cage) const {
    const std::string path = (dir / name).string();
    saveObj(path, cage.vertices, cageTopology(cage));
    return path;
  }
};

}  // namespace

TEST(EditorSceneRepair, FlippedFacesAreRepairedWithANotice) {
  const CubeFiles files("somicage_scene_repair");
  Cage flipped = files.cube;
  for (int j : {2, 9}) flipped.faces.row(j) = flipped.faces.row(j).reverse().eval();
  const Scene scene = loadScene(files.mesh, files.cage("flipped.obj", flipped));
  EXPECT_EQ(scene.restCage.faces, files.cube.faces);
  EXPECT_EQ(scene.restCage.vertices, files.cube.vertices);
  EXPECT_EQ(scene.notices,
            std::vector<std::string>{"cage repaired: flipped 2 faces (2, 9) to match their neighbours' orientation"});
  EXPECT_TRUE(loadScene(files.mesh, files.cage("clean.obj", files.cube)).notices.empty());

  // The status bar says what was repaired.
  AppState state;
  PrecomputeOutcome outcome;
  outcome.scene = std::make_shared<const Scene>(scene);
  installOutcome(state, outcome);
  EXPECT_NE(state.status.message.find("; cage repaired: flipped 2 faces (2, 9)"), std::string::npos)
      << state.status.message;
  EXPECT_TRUE(state.status.errors.empty());
}

TEST(EditorSceneRepair, CageThatStaysInvalidIsRefused) {
  const CubeFiles files("somicage_scene_refuse");
  Cage open = files.cube;
  open.faces.conservativeResize(11, 3);
  const std::string path = files.cage("open.obj", open);
  try {
    loadScene(files.mesh, path);
    FAIL() << "an open cage was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), path);
    EXPECT_NE(e.problem().find("the cage cannot be used: the cage is not closed"), std::string::npos) << e.what();
  }
}

TEST(EditorSceneRepair, AMeshInOtherUnitsGetsANotice) {
  const CubeFiles files("somicage_scene_units");
  const std::string cage = files.cage("cube.obj", files.cube);
  const std::string millimetres = (files.dir / "millimetres.obj").string();
  const PolygonMesh mesh = loadMesh(files.mesh);
  saveObj(millimetres, mesh.vertices * 1000, mesh);
  const Scene scene = loadScene(millimetres, cage);
  ASSERT_EQ(scene.notices.size(), 1u);
  const std::string expected = "mesh warning: the mesh " + millimetres + " and the cage " + cage + " do not fit";
  EXPECT_EQ(scene.notices[0].rfind(expected, 0), 0u) << scene.notices[0];
}

namespace {

// A mesh opened alone gets a generated cage that encloses it (core/generation/cage_generation.h), and a notice saying
// so.
TEST(EditorSceneRepair, MeshWithoutACageGetsAGeneratedOne) {
  CubeFiles files("scene_generated_cage");
  const std::string mesh = files.cage("cube_mesh.obj", files.cube);  // the cube as a mesh this time
  const Scene scene = loadScene(mesh, "");
  EXPECT_TRUE(validateCage(scene.restCage).valid());
  EXPECT_LE(scene.restCage.numFaces(), CageGenerationOptions{}.maxFaces);
  // Strictly outside the cube [-1, 1]^3 by a margin: every cage vertex beyond it in some coordinate.
  for (int i = 0; i < scene.restCage.numVertices(); ++i)
    EXPECT_GT(scene.restCage.vertices.row(i).cwiseAbs().maxCoeff(), 1.0);
  ASSERT_FALSE(scene.notices.empty());
  EXPECT_NE(scene.notices.front().find("cage generated"), std::string::npos);
}

}  // namespace

// Issue 24, rows 3 and 4: a cage that does not enclose the mesh, and a mesh without faces (an OBJ cut short inside
// its `v` lines), loaded with only "loaded NAME" before. Both now say so in the status bar and on stderr (the log).
TEST(EditorSceneRepair, PointsOutsideTheCageAndAMeshWithoutFacesAreReported) {
  const CubeFiles files("somicage_scene_outside");
  Cage small = files.cube;
  small.vertices *= 0.25;  // the cube [-0.25, 0.25]^3 around points spread over [-0.5, 0.5]^3
  const std::string cage = files.cage("small.obj", small);
  const Eigen::MatrixXd points = loadMesh(files.mesh).vertices;
  const std::string pointSet = (files.dir / "point_set.obj").string();  // the points without the triangles
  saveObj(pointSet, points, PolygonMesh{});
  int outside = 0;  // counted here from the box, independently of the deformer's winding numbers
  for (Eigen::Index p = 0; p < points.rows(); ++p) outside += points.row(p).cwiseAbs().maxCoeff() > 0.25;
  ASSERT_GT(outside, 0);

  AppState state;
  requestSceneFiles(state, pointSet, cage);
  std::optional<PrecomputeOutcome> out = waitForOutcome(state.jobs.precompute);
  ASSERT_TRUE(out.has_value());
  ::testing::internal::CaptureStderr();
  installOutcome(state, std::move(*out));
  const std::string log = ::testing::internal::GetCapturedStderr();
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  const std::string counted = std::to_string(outside) + " of 20 points lie outside the cage";
  EXPECT_NE(state.status.message.find(counted), std::string::npos) << state.status.message;
  EXPECT_NE(log.find(counted), std::string::npos) << log;
  const std::string noFaces = "has 20 vertices but no faces";
  EXPECT_NE(state.status.message.find(noFaces), std::string::npos) << state.status.message;
  EXPECT_NE(log.find(noFaces), std::string::npos) << log;
}

TEST(EditorSceneRepair, AnObjCutShortInsideItsVertexLinesSaysSo) {
  const CubeFiles files("somicage_scene_truncated");
  const std::string whole = files.cage("whole.obj", files.cube);  // the cube as a mesh: 8 v lines, 12 f lines
  std::ifstream in(whole);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t cut = text.find("\nv ", text.find("\nv ") + 1);  // after the second vertex line
  const std::string truncated = (files.dir / "truncated.obj").string();
  std::ofstream(truncated) << text.substr(0, cut + 1);
  const Scene scene = loadScene(truncated, files.cage("cube.obj", files.cube));
  EXPECT_EQ(scene.meshTriangles.rows(), 0);
  ASSERT_FALSE(scene.notices.empty());
  EXPECT_NE(scene.notices.back().find(truncated + " has 2 vertices but no faces"), std::string::npos)
      << scene.notices.back();
  EXPECT_NE(scene.notices.back().find("cut short"), std::string::npos);
}
