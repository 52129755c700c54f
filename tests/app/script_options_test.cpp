// --strict and --quiet, the options of scripted runs (issue 22), run as processes. Each kind of warning (points
// outside the cage, a mesh in other units, a repaired cage, a self-intersecting cage, a widened --margin) leaves the
// exit code 0 without --strict and makes it 3 with it, once the output is written, in every command that can give
// it; a clean run stays 0 under --strict and bad input stays 2. --quiet leaves stderr without the progress,
// estimate and summary lines, but keeps the warnings. Ctrl-C exits 130 and leaves no output.
#include <csignal>
#include <cstdlib>

#include "cli/progress_reporter.h"
#include "cli_test_support.h"
#include "io/obj_io.h"

namespace somicage {
namespace {

using namespace somicage::test;

// The pyramid moved by (dx, 0, 0) and scaled, written to path.
std::string movedPyramid(const std::string& path, double dx, double scale = 1.0) {
  const PolygonMesh pyramid = loadMesh(dataFile("pyramid_mesh.obj"));
  saveObj(path, (pyramid.vertices * scale).rowwise() + Eigen::RowVector3d(dx, 0, 0), pyramid);
  return path;
}

// The command line with --strict added, or as given.
std::vector<std::string> withStrict(std::vector<std::string> args, bool strict) {
  if (strict) args.push_back("--strict");
  return args;
}

// Runs args without and with --strict: exit 0, then 3, and both times the warning on stderr and the output written
// (outputFile, when not empty, is removed before each run; stdout, when expected, is one JSON object).
void expectWarningExitsThreeUnderStrict(const std::vector<std::string>& args, const std::string& warning,
                                        const std::string& outputFile = "", bool jsonOnStdout = false) {
  for (const bool strict : {false, true}) {
    SCOPED_TRACE(strict ? "--strict" : "without --strict");
    if (!outputFile.empty()) fs::remove(outputFile);
    const RunResult r = runSomicage(withStrict(args, strict));
    EXPECT_EQ(r.exitCode, strict ? 3 : 0) << r;
    EXPECT_NE(r.err.find(warning), std::string::npos) << r;
    if (!outputFile.empty()) {
      EXPECT_TRUE(fs::exists(outputFile)) << "the output is written before exit 3";
    }
    if (jsonOnStdout) {
      EXPECT_NO_THROW(JsonParser::parse(r.out)) << r;
    }
  }
}

TEST(StrictOption, PointsOutsideTheCage) {
  ScratchDir dir;
  // x + 0.8: the pyramid's base corners at x = 1.3 lie outside the cube [-1, 1]^3, its other vertices inside.
  const std::string mesh = movedPyramid(dir.file("outside.obj"), 0.8);
  const std::string cage = dataFile("cube_cage.obj"), out = dir.file("out.obj");
  const std::string outside = "2 of 5 points lie outside the cage";
  expectWarningExitsThreeUnderStrict({"deform", "--cage", cage, "--posed", cage, "--mesh", mesh, "--out", out}, outside,
                                     out);
  expectWarningExitsThreeUnderStrict({"analyze", "--cage", cage, "--posed", cage, "--mesh", mesh, "--json"}, outside,
                                     "", true);
  // check lists them in its report (stdout), not again on stderr.
  for (const bool strict : {false, true}) {
    const RunResult r = runSomicage(withStrict({"check", "--cage", cage, "--mesh", mesh, "--json"}, strict));
    EXPECT_EQ(r.exitCode, strict ? 3 : 0) << r;
    EXPECT_EQ(JsonParser::parse(r.out)["outside_points"].number, 2) << r;
  }

  const std::string session = dir.file("s.json");
  std::ofstream(session) << R"({"format": "somicage-session", "version": 2, "mesh": ")" << mesh << R"(", "cage": ")"
                         << cage << R"(", "method": "somigliana",
      "params": {"blend": 0, "nu": 0, "gamma": 0, "tractionCorrection": true},
      "poses": [{"name": "rest", "vertices": [[-1, -1, -1], [-1, -1, 1], [-1, 1, -1], [-1, 1, 1], [1, -1, -1],
                                              [1, -1, 1], [1, 1, -1], [1, 1, 1]]}],
      "timeline": {"fps": 24, "first": 0, "last": 2, "loop": false, "interpolation": "linear",
                   "keys": [{"frame": 0, "pose": "rest"}]}})";
  expectWarningExitsThreeUnderStrict({"animate", "--session", session, "--out", dir.file("anim.glb")}, outside,
                                     dir.file("anim.glb"));
}

TEST(StrictOption, MeshInOtherUnitsRepairedAndSelfIntersectingCages) {
  ScratchDir dir;
  const std::string cage = dataFile("cube_cage.obj"), mesh = dataFile("pyramid_mesh.obj"), out = dir.file("out.obj");
  const std::string huge = movedPyramid(dir.file("huge.obj"), 0.0, 1000.0);
  expectWarningExitsThreeUnderStrict({"deform", "--cage", cage, "--posed", cage, "--mesh", huge, "--out", out},
                                     "are the two files in different units", out);
  const std::string flipped = dataFile("cube_cage_flipped_faces.obj");
  expectWarningExitsThreeUnderStrict({"deform", "--cage", flipped, "--posed", flipped, "--mesh", mesh, "--out", out},
                                     "somicage: note: " + flipped + ": flipped 3 faces", out);
  const std::string pierced = dataFile("cube_pierced_by_spike.obj");
  expectWarningExitsThreeUnderStrict({"deform", "--cage", pierced, "--posed", pierced, "--mesh", mesh, "--out", out},
                                     "the cage intersects itself", out);
  expectWarningExitsThreeUnderStrict({"analyze", "--cage", pierced, "--posed", pierced, "--mesh", mesh},
                                     "the cage intersects itself");
  for (const bool strict : {false, true}) {
    const RunResult r = runSomicage(withStrict({"check", "--cage", pierced}, strict));
    EXPECT_EQ(r.exitCode, strict ? 3 : 0) << r;
    EXPECT_NE(r.out.find("warnings:\n  - the cage intersects itself"), std::string::npos) << r;
  }
}

// 1e-6 diagonals is far below the voxel size of a 100-face budget: the cage is made at a wider margin, a warning.
// (The same run without --strict, which exits 0, is in QuietOption: a cage takes seconds.)
TEST(StrictOption, CageMadeAtAWiderMarginThanAskedFor) {
  ScratchDir dir;
  const std::string out = dir.file("cage.obj");
  const RunResult r = runSomicage(
      {"cage", "--mesh", dataFile("pyramid_mesh.obj"), "--out", out, "--faces", "100", "--margin", "1e-6", "--strict"});
  EXPECT_EQ(r.exitCode, 3) << r;
  EXPECT_NE(r.err.find("not the 1e-06 asked for (--margin)"), std::string::npos) << r;
  EXPECT_TRUE(fs::exists(out)) << "the cage is written before exit 3";
}

TEST(StrictOption, CleanRunsStayZeroAndOtherCodesAreKept) {
  ScratchDir dir;
  const RunResult clean = runSomicage(cubeDeformArgs(dir.file("out.obj"), {"--strict"}));
  EXPECT_EQ(clean.exitCode, 0) << clean;
  const RunResult cleanCheck =
      runSomicage({"check", "--cage", dataFile("cube_cage.obj"), "--mesh", dataFile("pyramid_mesh.obj"), "--strict"});
  EXPECT_EQ(cleanCheck.exitCode, 0) << cleanCheck;
  const RunResult bad = runSomicage(cubeDeformArgs(dir.file("out.obj"), {"--strict", "--nu", "0.7"}));
  EXPECT_EQ(bad.exitCode, 2) << bad;
  const RunResult problems = runSomicage({"check", "--cage", dataFile("cube_cage_flipped_faces.obj"), "--strict"});
  EXPECT_EQ(problems.exitCode, 1) << "a cage with problems stays 1: " << problems;
}

// The memory estimate is printed when the precompute takes 10% of the free memory or more: with the free memory set
// to 40 kB (SOMICAGE_MEMORY_LIMIT_BYTES) the pyramid's few coordinates pass the 10% but still fit (28 kB in all on two
// threads, each with a pack of rows).
TEST(QuietOption, SilencesTheEstimateAndSummaryButKeepsWarnings) {
  ScratchDir dir;
  ASSERT_EQ(::setenv("SOMICAGE_MEMORY_LIMIT_BYTES", "40000", 1), 0);
  const RunResult loud = runSomicage(cubeDeformArgs(dir.file("out.obj"), {"--threads", "2"}));
  const RunResult quiet = runSomicage(cubeDeformArgs(dir.file("out.obj"), {"--quiet", "--threads", "2"}));
  ::unsetenv("SOMICAGE_MEMORY_LIMIT_BYTES");
  ASSERT_EQ(loud.exitCode, 0) << loud;
  EXPECT_NE(loud.err.find("somicage deform: estimated memory:"), std::string::npos) << loud;
  EXPECT_NE(loud.err.find("; wrote "), std::string::npos) << loud;
  ASSERT_EQ(quiet.exitCode, 0) << quiet;
  EXPECT_EQ(quiet.err, "") << quiet;

  const std::string outside = movedPyramid(dir.file("outside.obj"), 0.8);
  std::vector<std::string> args = cubeDeformArgs(dir.file("out.obj"), {"--quiet"});
  args[6] = outside;
  const RunResult warned = runSomicage(args);
  ASSERT_EQ(warned.exitCode, 0) << warned;
  EXPECT_EQ(warned.errLines(), 1) << "only the warning: " << warned;
  EXPECT_NE(warned.err.find("2 of 5 points lie outside the cage"), std::string::npos) << warned;

  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"analyze", "--cage", dataFile("cube_cage.obj"), "--posed", dataFile("cube_cage.obj"),
                                 "--mesh", dataFile("pyramid_mesh.obj"), "--json", "--quiet"},
        {"check", "--cage", dataFile("cube_cage.obj"), "--mesh", dataFile("pyramid_mesh.obj"), "--quiet"}}) {
    const RunResult r = runSomicage(command);
    EXPECT_EQ(r.exitCode, 0) << r;
    EXPECT_EQ(r.err, "") << r;
  }
  // The cage made at a wider margin than asked (StrictOption): without --strict, exit 0 and only the warning.
  const RunResult cage = runSomicage({"cage", "--mesh", dataFile("pyramid_mesh.obj"), "--out", dir.file("cage.obj"),
                                      "--faces", "100", "--margin", "1e-6", "--quiet"});
  EXPECT_EQ(cage.exitCode, 0) << cage;
  EXPECT_EQ(cage.errLines(), 1) << cage;
  EXPECT_EQ(cage.err.rfind("somicage: warning: " + dir.file("cage.obj") + ": the cage was made at a margin of ", 0), 0u)
      << cage;
}

// Progress lines appear (off a terminal) once a computation has run for a second; a silent reporter prints none.
TEST(QuietOption, SilentProgressReporterPrintsNothing) {
  ScratchDir dir;
  const std::string captured = dir.file("stderr");
  std::fflush(stderr);
  const int saved = ::dup(STDERR_FILENO);
  const int file = ::open(captured.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ASSERT_GE(saved, 0);
  ASSERT_GE(file, 0);
  ::dup2(file, STDERR_FILENO);
  {
    ProgressReporter loud("loud step"), silent("silent step", true);
    ::usleep(1100000);
    loud.callback()(0.5);
    silent.callback()(0.5);
  }
  std::fflush(stderr);
  ::dup2(saved, STDERR_FILENO);
  ::close(file);
  ::close(saved);
  const std::string text = readFile(captured);
  EXPECT_NE(text.find("loud step: 50%"), std::string::npos) << text;
  EXPECT_EQ(text.find("silent step"), std::string::npos) << text;
}

// Ctrl-C (SIGINT) during a command: the computation stops at its next progress report, the process exits 130 with
// one line saying so, and no output (nor a temporary) is left. The signal is sent once the cage's progress shows
// (after a second), so the handler is in place; a machine that makes the cage before that skips.
TEST(InterruptOption, CtrlCExits130AndLeavesNoOutput) {
  ScratchDir dir;
  const std::string out = dir.file("cage.obj"), errPath = dir.file("stderr");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> storage = {SOMICAGE_EXE, "cage", "--mesh",  dataFile("pyramid_mesh.obj"),
                                      "--out",      out,    "--faces", "40"};
  std::vector<char*> argv;
  for (std::string& arg : storage) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, SOMICAGE_EXE, &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  bool sent = false, ended = false;
  for (int wait = 0; wait < 6000 && !sent && !ended; ++wait) {  // up to a minute on a loaded machine
    ::usleep(10000);
    ended = ::waitpid(pid, &status, WNOHANG) == pid;
    if (!ended && readFile(errPath).find("making the cage: ") != std::string::npos) sent = ::kill(pid, SIGINT) == 0;
  }
  if (!ended) ::waitpid(pid, &status, 0);
  if (!sent) GTEST_SKIP() << "the cage was made before its progress showed: " << readFile(errPath);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by a signal, not by the handler: " << readFile(errPath);
  EXPECT_EQ(WEXITSTATUS(status), 130) << readFile(errPath);
  EXPECT_NE(readFile(errPath).find("somicage cage: interrupted (Ctrl-C); no output was written"), std::string::npos)
      << readFile(errPath);
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir.path())) left.push_back(entry.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"stderr"}) << "no cage and no temporary";
}

}  // namespace
}  // namespace somicage
