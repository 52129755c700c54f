// somicage cage, run as a process: it writes a cage that 'somicage check' finds valid with every mesh vertex inside,
// keeps the face budget, reports what the README documents, and refuses bad options with exit 2 and no file.
#include "cli_test_support.h"
#include "io/mesh_formats.h"

namespace somicage {
namespace {

using namespace somicage::test;

TEST(CliCage, WritesACageThatCheckFindsValidWithNoPointOutside) {
  ScratchDir dir;
  const std::string out = dir.file("cage.obj");
  const RunResult made =
      runSomicage({"cage", "--mesh", dataFile("pyramid_mesh.obj"), "--out", out, "--faces", "40", "--json"});
  ASSERT_EQ(made.exitCode, 0) << made;
  const Json report = JsonParser::parse(made.out);
  EXPECT_LE(report["faces"].number, 40);
  EXPECT_TRUE(report["valid"].boolean);
  EXPECT_GT(report["min_angle_deg"].number, 1.0);
  EXPECT_GT(report["hausdorff_diagonals"].number, 0.0);
  EXPECT_TRUE(report["mesh_closed"].boolean);
  EXPECT_GT(report["volume_ratio"].number, 1.0);  // the cage holds the closed mesh
  EXPECT_EQ(loadCage(out).numFaces(), int(report["faces"].number));

  const RunResult checked = runSomicage({"check", "--cage", out, "--mesh", dataFile("pyramid_mesh.obj"), "--json"});
  ASSERT_EQ(checked.exitCode, 0) << checked;
  const Json check = JsonParser::parse(checked.out);
  EXPECT_TRUE(check["valid"].boolean);
  EXPECT_EQ(check["outside_points"].number, 0);
  EXPECT_GT(check["inside_points"].number, 0);
}

TEST(CliCage, BadOptionsExitTwoAndWriteNothing) {
  ScratchDir dir;
  const std::string out = dir.file("cage.obj");
  for (const std::vector<std::string>& extra :
       {std::vector<std::string>{"--faces", "4"}, {"--margin", "-1"}, {"--margin", "2"}, {"--faces", "many"}}) {
    std::vector<std::string> args = {"cage", "--mesh", dataFile("pyramid_mesh.obj"), "--out", out};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = runSomicage(args);
    EXPECT_EQ(r.exitCode, 2) << r;
    EXPECT_NE(r.err.find("somicage cage: --"), std::string::npos) << r;
    EXPECT_FALSE(fs::exists(out));
  }
  const RunResult missing = runSomicage({"cage", "--mesh", dir.file("absent.obj"), "--out", out});
  EXPECT_EQ(missing.exitCode, 2) << missing;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace somicage
