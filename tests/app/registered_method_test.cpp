// Issue 23: a parameter row and a method registered from test code (tests/core/constant_method.h) reach the command
// line with no other file touched: `somicage deform --method constant --test-shift S` runs in-process through
// runCli and moves the mesh by the closed form x + u, the help lists both, and another method notes that it
// ignores the new option.
#include <gtest/gtest.h>

#include "../core/constant_method.h"
#include "cli/cli.h"
#include "cli_test_support.h"
#include "io/mesh_formats.h"
#include "io/obj_io.h"

namespace somicage {
namespace {

using namespace somicage::test;

// runCli in this process (where the registration lives), with its stdout and stderr.
RunResult runInProcess(const std::vector<std::string>& args) {
  std::vector<std::string> all = {"somicage"};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  RunResult r;
  r.exitCode = runCli(static_cast<int>(argv.size()), argv.data(), {cpuFrameDevice()});
  r.out = testing::internal::GetCapturedStdout();
  r.err = testing::internal::GetCapturedStderr();
  return r;
}

TEST(RegisteredMethod, DeformsThroughTheCommandLineByItsClosedForm) {
  const ConstantMethodRegistration registration;
  ScratchDir dir;
  const Cage cage = loadCage(dataFile("cube_cage.obj"));
  // A pose that moves each vertex differently: the mean displacement is what the method applies.
  Eigen::MatrixXd posed = cage.vertices;
  for (Eigen::Index v = 0; v < posed.rows(); ++v) posed.row(v) += Eigen::RowVector3d(0.1 * v, -0.2, 0.05 * v * v);
  const std::string posedFile = dir.file("posed.obj");
  saveObj(posedFile, posed, cageTopology(cage));
  const std::string out = dir.file("out.obj");
  const RunResult r = runInProcess({"deform", "--cage", dataFile("cube_cage.obj"), "--posed", posedFile, "--mesh",
                                    dataFile("pyramid_mesh.obj"), "--out", out, "--method", "constant",
                                    "--test-shift", "0.25"});
  ASSERT_EQ(r.exitCode, 0) << r;
  EXPECT_EQ(r.err.find("ignores"), std::string::npos) << r;
  Eigen::RowVector3d u = (posed - cage.vertices).colwise().mean();
  u.x() += 0.25;
  const Eigen::MatrixXd mesh = loadMesh(dataFile("pyramid_mesh.obj")).vertices;
  const Eigen::MatrixXd moved = loadMesh(out).vertices;
  ASSERT_EQ(moved.rows(), mesh.rows());
  EXPECT_LE(((mesh.rowwise() + u) - moved).cwiseAbs().maxCoeff(), 1e-12);

  // The row's range holds on the command line; another method notes that it ignores the option.
  const RunResult bad = runInProcess(cubeDeformArgs(out, {"--method", "constant", "--test-shift", "2"}));
  EXPECT_EQ(bad.exitCode, 2) << bad;
  EXPECT_NE(bad.err.find("--test-shift: test shift 2 is out of range (use a value in [-1, 1]"), std::string::npos)
      << bad;
  const RunResult ignored = runInProcess(cubeDeformArgs(out, {"--test-shift", "0.5"}));
  EXPECT_EQ(ignored.exitCode, 0) << ignored;
  EXPECT_NE(ignored.err.find("somigliana ignores --test-shift (constant only)"), std::string::npos) << ignored;
}

TEST(RegisteredMethod, TheHelpListsTheMethodAndTheParameter) {
  const ConstantMethodRegistration registration;
  const RunResult help = runInProcess({"deform", "--help"});
  EXPECT_EQ(help.exitCode, 0) << help;
  const std::string text = help.out + help.err;
  EXPECT_NE(text.find("--test-shift V"), std::string::npos) << text;
  EXPECT_NE(text.find("moves the constant method's points along x: a value in [-1, 1] (default 0); constant only"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("Constant: test: every point moved"), std::string::npos) << text;
}

}  // namespace
}  // namespace somicage
