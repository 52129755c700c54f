// somicage check, run as a process: --json prints one object that parses and has the documented keys; the exit
// status says whether the cage is valid; points outside the cage are counted, not averaged.
#include "cli_test_support.h"
#include "io/mesh_formats.h"

namespace somicage {
namespace {

using namespace somicage::test;

Json checkJson(const std::vector<std::string>& args, int expectedExit) {
  std::vector<std::string> all = {"check"};
  all.insert(all.end(), args.begin(), args.end());
  all.push_back("--json");
  const RunResult r = runSomicage(all);
  EXPECT_EQ(r.exitCode, expectedExit) << r;
  EXPECT_TRUE(r.err.empty()) << r;
  try {
    return JsonParser::parse(r.out);
  } catch (const std::exception& e) {
    ADD_FAILURE() << e.what() << "\n" << r.out;
    return Json();
  }
}

TEST(CliCheck, JsonHasTheKeysAndTheNumbers) {
  const Json json = checkJson({"--cage", dataFile("cube_cage.obj"), "--mesh", dataFile("pyramid_mesh.obj")}, 0);
  ASSERT_EQ(json.type, Json::Type::Object);
  const std::pair<const char*, Json::Type> keys[] = {{"cage_vertices", Json::Type::Number},
                                                     {"cage_faces", Json::Type::Number},
                                                     {"closed", Json::Type::Bool},
                                                     {"manifold", Json::Type::Bool},
                                                     {"outward", Json::Type::Bool},
                                                     {"mesh_vertices", Json::Type::Number},
                                                     {"outside_points", Json::Type::Number},
                                                     {"pou_max", Json::Type::Number},
                                                     {"pou_median", Json::Type::Number},
                                                     {"dim", Json::Type::Number},
                                                     {"valid", Json::Type::Bool},
                                                     {"problems", Json::Type::Array},
                                                     {"precompute_s", Json::Type::Number},
                                                     {"inside_points", Json::Type::Number},
                                                     {"repairs", Json::Type::Array},
                                                     {"usable", Json::Type::Bool},
                                                     {"warnings", Json::Type::Array},
                                                     {"intersecting_face_pairs", Json::Type::Number}};
  for (const auto& [key, type] : keys) {
    ASSERT_TRUE(json.has(key)) << key;
    EXPECT_EQ(json[key].type, type) << key;
  }
  EXPECT_EQ(json["dim"].number, 3);
  EXPECT_EQ(json["cage_vertices"].number, 8);
  EXPECT_EQ(json["cage_faces"].number, 12);
  EXPECT_TRUE(json["closed"].boolean && json["manifold"].boolean && json["outward"].boolean);
  EXPECT_TRUE(json["valid"].boolean);
  EXPECT_TRUE(json["problems"].array.empty());
  EXPECT_EQ(json["mesh_vertices"].number, 5);
  EXPECT_EQ(json["outside_points"].number, 0);
  EXPECT_EQ(json["inside_points"].number, 5);
  EXPECT_LE(json["pou_max"].number, 1e-9);
  EXPECT_LE(json["pou_median"].number, json["pou_max"].number);
  EXPECT_GE(json["pou_median"].number, 0.0);
  // Each method's identity error at rest, in cage diameters: exact integrals and MVC reproduce it to round-off.
  ASSERT_TRUE(json.has("reproduction_error"));
  for (const char* method : {"somigliana", "green", "mvc"}) {
    ASSERT_TRUE(json["reproduction_error"].has(method)) << method;
    EXPECT_LE(json["reproduction_error"][method].number, 1e-12) << method;
  }
}

TEST(CliCheck, PolygonCage) {
  ScratchDir dir;
  Eigen::MatrixXd P(5, 2);
  P << 0.5, 0.5, 1.5, 0.5, 0.5, 1.5, 1.5, 1.5, 3, 3;  // the last two lie in the notch of the L and beyond it
  saveObj(dir.file("points.obj"), P, PolygonMesh{});
  const Json json = checkJson({"--cage", dataFile("l_shape_loop.obj"), "--mesh", dir.file("points.obj")}, 0);
  ASSERT_TRUE(json.has("dim"));
  EXPECT_EQ(json["dim"].number, 2);
  EXPECT_EQ(json["cage_faces"].number, 6);
  EXPECT_TRUE(json["simple"].boolean);
  EXPECT_EQ(json["signed_area"].number, 3);
  EXPECT_EQ(json["mesh_vertices"].number, 5);
  EXPECT_EQ(json["inside_points"].number, 3);
  EXPECT_EQ(json["outside_points"].number, 2);
  EXPECT_LE(json["pou_max"].number, 1e-9);
}

TEST(CliCheck, CageWithProblemsExitsOne) {
  ScratchDir dir;
  Cage cube = loadCage(dataFile("cube_cage.obj"));
  cube.faces = cube.faces.rowwise().reverse().eval();
  const std::string insideOut = dir.file("inside_out.obj");
  saveObj(insideOut, cube.vertices, cageTopology(cube));

  const Json json = checkJson({"--cage", insideOut, "--mesh", dataFile("pyramid_mesh.obj")}, 1);
  ASSERT_TRUE(json.has("valid"));
  EXPECT_FALSE(json["valid"].boolean);
  EXPECT_FALSE(json["outward"].boolean);
  EXPECT_TRUE(json["closed"].boolean);
  ASSERT_EQ(json["problems"].array.size(), 1u);
  EXPECT_NE(json["problems"].array[0].string.find("the faces point inward"), std::string::npos);

  const RunResult r = runSomicage({"check", "--cage", insideOut});
  EXPECT_EQ(r.exitCode, 1) << r;
  EXPECT_NE(r.out.find("outward NO"), std::string::npos) << r;
  EXPECT_NE(r.out.find("result: the cage has 1 problem"), std::string::npos) << r;
}

// check reports the file as given (exit 1), then what deform would repair; the coordinates are the repaired cage's.
TEST(CliCheck, RepairableCageListsTheRepair) {
  const std::string flipped = dataFile("cube_cage_flipped_faces.obj");
  const Json json = checkJson({"--cage", flipped, "--mesh", dataFile("pyramid_mesh.obj")}, 1);
  ASSERT_TRUE(json.has("repairs"));
  EXPECT_FALSE(json["valid"].boolean);
  EXPECT_FALSE(json["consistently_oriented"].boolean);
  EXPECT_TRUE(json["usable"].boolean);
  ASSERT_EQ(json["repairs"].array.size(), 1u);
  EXPECT_EQ(json["repairs"].array[0].string, "flipped 3 faces (1, 4, 7) to match their neighbours' orientation");
  EXPECT_EQ(json["inside_points"].number, 5);
  EXPECT_LE(json["pou_max"].number, 1e-9);

  const RunResult r = runSomicage({"check", "--cage", flipped});
  EXPECT_EQ(r.exitCode, 1) << r;
  EXPECT_NE(r.out.find("consistently oriented NO"), std::string::npos) << r;
  EXPECT_NE(r.out.find("repairs that deform, bench and the editor apply (the file is not changed):\n"
                       "  - flipped 3 faces (1, 4, 7)"),
            std::string::npos)
      << r;
  EXPECT_NE(r.out.find("result: the cage has 1 problem; repaired as above, it is usable"), std::string::npos) << r;
}

TEST(CliCheck, SelfIntersectingCageIsValidWithAWarning) {
  const std::string pierced = dataFile("cube_pierced_by_spike.obj");
  const Json json = checkJson({"--cage", pierced}, 0);
  ASSERT_TRUE(json.has("warnings"));
  EXPECT_TRUE(json["valid"].boolean);
  EXPECT_TRUE(json["repairs"].array.empty());
  EXPECT_EQ(json["intersecting_face_pairs"].number, 3);
  ASSERT_EQ(json["warnings"].array.size(), 1u);
  EXPECT_NE(json["warnings"].array[0].string.find("faces 0 and 13, faces 0 and 14, faces 0 and 15"), std::string::npos);

  const RunResult r = runSomicage({"check", "--cage", pierced});
  EXPECT_EQ(r.exitCode, 0) << r;
  EXPECT_NE(r.out.find("warnings:\n  - the cage intersects itself"), std::string::npos) << r;
  EXPECT_NE(r.out.find("result: the cage is valid"), std::string::npos) << r;
}

TEST(CliCheck, ReadableReport) {
  const RunResult r =
      runSomicage({"check", "--cage", dataFile("cube_quads.obj"), "--mesh", dataFile("pyramid_mesh.obj")});
  EXPECT_EQ(r.exitCode, 0) << r;
  EXPECT_NE(r.out.find("8 vertices, 12 triangles"), std::string::npos) << r;
  EXPECT_NE(r.out.find("5 inside the cage, 0 outside"), std::string::npos) << r;
  EXPECT_NE(r.out.find("result: the cage is valid"), std::string::npos) << r;
}

TEST(CliCheck, PartialCageCountsOutsidePoints) {
  if (!fs::is_directory(kModelsDir)) GTEST_SKIP() << "models folder " << kModelsDir << " is absent";
  const std::string cage = (kModelsDir / "bar" / "bar_cage_partial.OBJ").string();
  const std::string mesh = (kModelsDir / "bar" / "bar.OBJ").string();
  const Json json = checkJson({"--cage", cage, "--mesh", mesh}, 0);
  ASSERT_TRUE(json.has("outside_points"));
  EXPECT_EQ(json["mesh_vertices"].number, 386);
  const double inside = json["inside_points"].number / 386.0;
  EXPECT_NEAR(inside, 0.46, 0.02) << "models/README.md: 46 % of the bar is inside the partial cage";
  EXPECT_EQ(json["inside_points"].number + json["outside_points"].number + json["singular_points"].number, 386);
  EXPECT_LE(json["pou_max"].number, 1e-9);
}

TEST(CliCheck, WithoutMesh) {
  const Json json = checkJson({"--cage", dataFile("cube_cage.obj")}, 0);
  ASSERT_TRUE(json.has("pou_max"));
  EXPECT_EQ(json["pou_max"].type, Json::Type::Null);
  EXPECT_EQ(json["mesh_vertices"].number, 0);
  EXPECT_EQ(json["mesh"].type, Json::Type::Null);
}

// The fit of a cage around a mesh, for a case with a closed form: the cube [-1, 1]^3 around [-0.5, 0.5]^3 has 8 times
// its volume, and its corners are sqrt(3) / 2 from the inner cube, half the inner cube's diagonal.
TEST(CliCheck, ReportsTheFitOfTheCageAroundTheMesh) {
  ScratchDir dir;
  Cage inner = loadCage(dataFile("cube_cage.obj"));
  inner.vertices *= 0.5;
  const std::string mesh = dir.file("half_cube.obj");
  saveObj(mesh, inner.vertices, cageTopology(inner));
  const Json json = checkJson({"--cage", dataFile("cube_cage.obj"), "--mesh", mesh}, 0);
  EXPECT_NEAR(json["volume_ratio"].number, 8.0, 1e-9);
  EXPECT_NEAR(json["hausdorff_diagonals"].number, 0.5, 1e-9);
  EXPECT_TRUE(json["mesh_closed"].boolean);

  Cage open = inner;
  open.faces.conservativeResize(10, 3);  // an open box: no volume to compare with
  saveObj(mesh, open.vertices, cageTopology(open));
  const Json openJson = checkJson({"--cage", dataFile("cube_cage.obj"), "--mesh", mesh}, 0);
  EXPECT_EQ(openJson["volume_ratio"].type, Json::Type::Null);
  EXPECT_FALSE(openJson["mesh_closed"].boolean);
  EXPECT_NEAR(openJson["hausdorff_diagonals"].number, 0.5, 1e-9);
  const RunResult readable = runSomicage({"check", "--cage", dataFile("cube_cage.obj"), "--mesh", mesh});
  EXPECT_NE(readable.out.find("Hausdorff cage -> mesh 0.5 diagonals, volume cage / mesh - (open mesh)"),
            std::string::npos)
      << readable;
}

}  // namespace
}  // namespace somicage
