// somicage analyze, run as a process, against independent measurements: the volume change equals the signed
// volume of the OBJ that `somicage deform` writes for the same pose (computed here), the fold-over count equals the
// CSV rows with det J <= 0, each nu sweep entry equals `analyze --nu` at that nu, and bad sweeps are refused.
#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <regex>

#include "cli_test_support.h"
#include "io/obj_io.h"

namespace somicage {
namespace {

using namespace somicage::test;

// The number after "key": in JSON output (NaN when absent or null).
double jsonNumber(const std::string& json, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(json, m, std::regex("\"" + key + "\": (-?[0-9.eE+-]+)"))) return std::nan("");
  return std::stod(m[1]);
}

// Signed volume of a closed polygon mesh by the divergence theorem (fan triangles, origin at 0).
double signedVolume(const PolygonMesh& mesh) {
  double six = 0;
  for (const auto& f : mesh.faces)
    for (std::size_t k = 1; k + 1 < f.size(); ++k) {
      const Eigen::Vector3d a = mesh.vertices.row(f[0]), b = mesh.vertices.row(f[k]), c = mesh.vertices.row(f[k + 1]);
      six += a.dot(b.cross(c));
    }
  return six / 6;
}

// The cube cage with its top pushed down and twisted: a pose that squashes the pyramid (and can fold it).
std::string writeSquashedCube(const ScratchDir& dir, double drop) {
  const PolygonMesh cube = loadMesh(dataFile("cube_cage.obj"));
  Eigen::MatrixXd V = cube.vertices;
  for (int i = 0; i < V.rows(); ++i)
    if (V(i, 2) > 0) {
      V(i, 2) -= drop;
      const double x = V(i, 0), y = V(i, 1);
      V(i, 0) = std::cos(0.6) * x - std::sin(0.6) * y, V(i, 1) = std::sin(0.6) * x + std::cos(0.6) * y;
    }
  const std::string path = dir.file("posed.obj");
  saveObj(path, V, cube);
  return path;
}

std::vector<std::string> analyzeArgs(const std::string& posed, const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"analyze", "--cage", dataFile("cube_cage.obj"),    "--posed",
                                   posed,     "--mesh", dataFile("pyramid_mesh.obj"), "--json"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

TEST(CliAnalyze, VolumeChangeEqualsTheVolumeOfTheDeformedObj) {
  ScratchDir dir;
  const std::string posed = writeSquashedCube(dir, 0.8);
  for (const std::vector<std::string>& method :
       std::vector<std::vector<std::string>>{{"--variant", "local", "--nu", "0.3", "--gamma", "0.5"},
                                             {"--method", "green"},
                                             {"--method", "mvc"},
                                             {"--method", "bem", "--nu", "0.3", "--corotational"}}) {
    const RunResult analyzed = runSomicage(analyzeArgs(posed, method));
    ASSERT_EQ(analyzed.exitCode, 0) << analyzed;
    std::vector<std::string> deformArgs = {"deform",
                                           "--cage",
                                           dataFile("cube_cage.obj"),
                                           "--posed",
                                           posed,
                                           "--mesh",
                                           dataFile("pyramid_mesh.obj"),
                                           "--out",
                                           dir.file("out.obj")};
    deformArgs.insert(deformArgs.end(), method.begin(), method.end());
    const RunResult deformed = runSomicage(deformArgs);
    ASSERT_EQ(deformed.exitCode, 0) << deformed;
    const double rest = signedVolume(loadMesh(dataFile("pyramid_mesh.obj")));
    EXPECT_NEAR(rest, 1.1 / 3, 1e-12);  // base 1 x 1, height 1.1
    const double after = signedVolume(loadMesh(dir.file("out.obj")));
    EXPECT_EQ(analyzed.out.find("\"closed\": true") != std::string::npos, true) << analyzed.out;
    EXPECT_NEAR(jsonNumber(analyzed.out, "volume_rest"), rest, 1e-12);
    EXPECT_NEAR(jsonNumber(analyzed.out, "volume_deformed"), after, 1e-9);
    EXPECT_NEAR(jsonNumber(analyzed.out, "volume_change"), after / rest - 1, 1e-9) << method[0];
    EXPECT_EQ(jsonNumber(analyzed.out, "outside_points"), 0);
  }
}

TEST(CliAnalyze, FoldoverCountIsTheNumberOfCsvRowsWithNonPositiveDetJ) {
  ScratchDir dir;
  const std::string posed = writeSquashedCube(dir, 2.6);  // the top pushed through the bottom
  const RunResult r = runSomicage(analyzeArgs(posed, {"--variant", "local", "--fields", dir.file("j.csv")}));
  ASSERT_EQ(r.exitCode, 0) << r;
  std::ifstream csv(dir.file("j.csv"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "vertex,det_j,conformal_distortion,j00,j01,j02,j10,j11,j12,j20,j21,j22");
  int rows = 0, folded = 0;
  while (std::getline(csv, line)) {
    std::vector<double> v;
    std::stringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) v.push_back(std::stod(cell));
    ASSERT_EQ(v.size(), 12u) << line;
    EXPECT_EQ(v[0], rows);
    // det_j is the determinant of the row's J (to rounding).
    Eigen::Matrix3d J;
    J << v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11];
    EXPECT_NEAR(v[1], J.determinant(), 1e-12 * std::max(1.0, J.norm() * J.norm() * J.norm()));
    folded += v[1] <= 0;
    ++rows;
  }
  EXPECT_EQ(rows, 5);
  EXPECT_GT(folded, 0);  // the pose does fold the pyramid: the count is compared with something
  EXPECT_EQ(jsonNumber(r.out, "foldover_vertices"), folded);
}

TEST(CliAnalyze, SweepEntriesEqualAnalyzeAtThatNu) {
  ScratchDir dir;
  const std::string posed = writeSquashedCube(dir, 0.8);
  const RunResult sweep = runSomicage(analyzeArgs(posed, {"--variant", "local", "--nu-sweep", "-0.5:0.4:4"}));
  ASSERT_EQ(sweep.exitCode, 0) << sweep;
  const std::regex entry(
      "\\{\"nu\": (-?[0-9.eE+-]+), \"volume_change\": (-?[0-9.eE+-]+), "
      "\"foldover_vertices\": ([0-9]+)\\}");
  int entries = 0;
  for (std::sregex_iterator it(sweep.out.begin(), sweep.out.end(), entry), end; it != end; ++it, ++entries) {
    const RunResult single = runSomicage(analyzeArgs(posed, {"--variant", "local", "--nu", (*it)[1].str()}));
    ASSERT_EQ(single.exitCode, 0) << single;
    EXPECT_NEAR(std::stod((*it)[2]), jsonNumber(single.out, "volume_change"), 1e-12);
    EXPECT_EQ(std::stod((*it)[3]), jsonNumber(single.out, "foldover_vertices"));
  }
  EXPECT_EQ(entries, 4) << sweep.out;
}

TEST(CliAnalyze, RefusesABadSweepNamingTheOption) {
  for (const std::string bad : {"0.1:0.2", "-1:0.3:5", "0:0.6:5", "0:0.3:1", "a:b:c"}) {
    const RunResult r = runSomicage(analyzeArgs(dataFile("cube_cage.obj"), {"--nu-sweep", bad}));
    EXPECT_EQ(r.exitCode, 2) << bad << "\n" << r;
    EXPECT_NE(r.err.find("--nu-sweep"), std::string::npos) << r;
  }
}

// The chosen variant and choices (issue 26) are named in the JSON; a bad choice is refused naming the option.
TEST(CliAnalyze, JsonNamesTheChosenOptions) {
  const RunResult r = runSomicage(
      analyzeArgs(dataFile("cube_cage.obj"), {"--variant", "affine", "--bulging", "reference", "--normals", "angle"}));
  ASSERT_EQ(r.exitCode, 0) << r;
  for (const char* field : {"\"variant\": \"affine\"", "\"bulging\": \"reference\"", "\"normals\": \"angle\""})
    EXPECT_NE(r.out.find(field), std::string::npos) << field << "\n" << r.out;
  const RunResult bad = runSomicage(analyzeArgs(dataFile("cube_cage.obj"), {"--bulging", "solid_angle"}));
  EXPECT_EQ(bad.exitCode, 2) << bad;
  EXPECT_NE(bad.err.find("--bulging: 'solid_angle' is not a choice (use solid-angle, reference, swept-volume or polygon"),
            std::string::npos)
      << bad;
}

// seam_jump: Phong's J jumps across the cube's tetrahedra (its star) where the pyramid's edges cross them, and is
// measured without asking; Somigliana's is one function (0), measured with --seams only; at rest nothing jumps.
TEST(CliAnalyze, SeamJumpIsPhongsAndZeroForASmoothMethod) {
  ScratchDir dir;
  const std::string posed = writeSquashedCube(dir, 0.5);
  const RunResult phong = runSomicage(analyzeArgs(posed, {"--method", "phong", "--nu", "0.3"}));
  ASSERT_EQ(phong.exitCode, 0) << phong;
  const std::string seams = phong.out.substr(phong.out.find("\"seam_jump\""));
  EXPECT_GT(jsonNumber(seams, "max"), 1e-2) << phong.out;
  EXPECT_GE(jsonNumber(seams, "max"), jsonNumber(seams, "p50")) << phong.out;
  const RunResult still = runSomicage(analyzeArgs(dataFile("cube_cage.obj"), {"--method", "phong"}));
  ASSERT_EQ(still.exitCode, 0) << still;
  EXPECT_LE(jsonNumber(still.out.substr(still.out.find("\"seam_jump\"")), "max"), 1e-12) << still.out;

  const RunResult plain = runSomicage(analyzeArgs(posed, {"--nu", "0.3"}));
  ASSERT_EQ(plain.exitCode, 0) << plain;
  EXPECT_EQ(plain.out.find("seam_jump"), std::string::npos) << "asked for with a smooth method";
  const RunResult smooth = runSomicage(analyzeArgs(posed, {"--nu", "0.3", "--seams", "--tet-level", "0"}));
  ASSERT_EQ(smooth.exitCode, 0) << smooth;
  EXPECT_EQ(smooth.err.find("ignores"), std::string::npos) << "--seams reads --tet-level\n" << smooth.err;
  ASSERT_NE(smooth.out.find("\"seam_jump\""), std::string::npos) << smooth.out;
  EXPECT_LE(jsonNumber(smooth.out.substr(smooth.out.find("\"seam_jump\"")), "max"), 1e-12) << smooth.out;
}

TEST(CliAnalyze, TwoDimensionalAreasAndCsvHeader) {
  ScratchDir dir;
  const std::string csv = dir.file("j.csv");
  const RunResult r =
      runSomicage({"analyze", "--cage", dataFile("square_polygon.obj"), "--posed", dataFile("square_polygon.obj"),
                   "--mesh", dataFile("square_points.obj"), "--json", "--fields", csv});
  ASSERT_EQ(r.exitCode, 0) << r;
  EXPECT_NEAR(jsonNumber(r.out, "p50"), 1, 1e-9) << r.out;  // det J = 1 at rest
  EXPECT_EQ(readFile(csv).substr(0, readFile(csv).find('\n')), "vertex,det_j,conformal_distortion,j00,j01,j10,j11");
}

}  // namespace
}  // namespace somicage
