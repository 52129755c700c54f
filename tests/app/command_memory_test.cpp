// The memory check of somicage deform, analyze and bench, run as a process with SOMICAGE_MEMORY_LIMIT_BYTES standing in
// for the free memory: a precompute that would not fit is refused (exit 2, one line naming the mesh, the sizes and what
// to do, nothing written); a big one announces its estimate first; a small one keeps its single summary line.
#include <cstdlib>

#include "cli_test_support.h"
#include "deform/memory_estimate.h"
#include "io/obj_io.h"
#include "methods/method_descriptors.h"

namespace somicage {
namespace {

using namespace somicage::test;

// SOMICAGE_MEMORY_LIMIT_BYTES for the processes started in a scope (runSomicage passes the environment on).
class MemoryLimit {
 public:
  explicit MemoryLimit(const std::string& bytes) { ::setenv("SOMICAGE_MEMORY_LIMIT_BYTES", bytes.c_str(), 1); }
  ~MemoryLimit() { ::unsetenv("SOMICAGE_MEMORY_LIMIT_BYTES"); }
};

std::vector<std::string> benchArgs() {
  return {"bench",    "--cage", dataFile("cube_cage.obj"), "--mesh", dataFile("pyramid_mesh.obj"), "--frames", "1",
          "--repeat", "1",      "--baseline-points",       "0"};
}

// The pyramid's 5 points in the cube cage need about 8 kB (double, somigliana) and 5 kB (float, bench).
TEST(CliMemory, RefusesAPrecomputeThatDoesNotFit) {
  ScratchDir dir;
  const MemoryLimit limit("1000");
  for (const std::vector<std::string>& args : {cubeDeformArgs(dir.file("out.obj")), benchArgs()}) {
    SCOPED_TRACE(args[0]);
    const RunResult r = runSomicage(args);
    EXPECT_EQ(r.exitCode, 2) << r;
    EXPECT_TRUE(r.out.empty()) << r;
    EXPECT_EQ(r.errLines(), 1) << r;
    for (const char* part : {"pyramid_mesh.obj: the coordinates of 5 points need", "but only 1 kB are free",
                             "decimate the mesh", "SOMICAGE_MEMORY_LIMIT_BYTES"})
      EXPECT_NE(r.err.find(part), std::string::npos) << part << "\n" << r;
  }
  EXPECT_FALSE(fs::exists(dir.file("out.obj"))) << "nothing may be written when the precompute is refused";
}

TEST(CliMemory, ABigPrecomputeAnnouncesItsEstimate) {
  ScratchDir dir;
  const MemoryLimit limit("50000");  // the ~28 kB needed on two threads fit in 85% of it, and take more than 10%
  const RunResult r = runSomicage(cubeDeformArgs(dir.file("out.obj"), {"--threads", "2"}));
  EXPECT_EQ(r.exitCode, 0) << r;
  // 5 points by 142 columns (8 vertices, 12 faces) in double; the rest depends on the thread count.
  EXPECT_NE(r.err.find("somicage deform: estimated memory: 6 kB of coordinates, "), std::string::npos) << r;
  EXPECT_NE(r.err.find(" in all (50 kB free)\n"), std::string::npos) << r;
  EXPECT_LT(r.err.find("estimated memory"), r.err.find("precompute")) << "the estimate comes first: " << r;
  EXPECT_TRUE(fs::exists(dir.file("out.obj")));
}

// analyze checks the deformation gradients too (3 more matrices the size of C): at a limit where deform's ~28 kB
// fit, analyze's ~49 kB do not, and it is refused before its precompute with the same message. Two threads: each
// thread's working memory (a pack of rows) is counted.
TEST(CliMemory, AnalyzeCountsTheGradients) {
  ScratchDir dir;
  const MemoryLimit limit("40000");
  const RunResult deform = runSomicage(cubeDeformArgs(dir.file("out.obj"), {"--threads", "2"}));
  EXPECT_EQ(deform.exitCode, 0) << deform;
  const RunResult analyze = runSomicage({"analyze", "--cage", dataFile("cube_cage.obj"), "--posed",
                                         dataFile("cube_cage.obj"), "--mesh", dataFile("pyramid_mesh.obj"),
                                         "--threads", "2"});
  EXPECT_EQ(analyze.exitCode, 2) << analyze;
  EXPECT_EQ(analyze.errLines(), 1) << analyze;
  for (const char* part : {"somicage analyze: ", "pyramid_mesh.obj: the coordinates of 5 points need",
                           "but only 40 kB are free", "decimate the mesh"})
    EXPECT_NE(analyze.err.find(part), std::string::npos) << part << "\n" << analyze;
  EXPECT_EQ(analyze.err.find("store the coordinates in float"), std::string::npos) << "no such option: " << analyze;
}

TEST(CliMemory, ASmallPrecomputeKeepsItsSingleSummaryLine) {
  ScratchDir dir;
  const RunResult r = runSomicage(cubeDeformArgs(dir.file("out.obj")));
  EXPECT_EQ(r.exitCode, 0) << r;
  EXPECT_EQ(r.errLines(), 1) << r;
  EXPECT_EQ(r.err.find("estimated memory"), std::string::npos) << r;
}

TEST(CliMemory, AMalformedLimitIsABadInput) {
  ScratchDir dir;
  const MemoryLimit limit("8 GB");
  const RunResult r = runSomicage(cubeDeformArgs(dir.file("out.obj")));
  EXPECT_EQ(r.exitCode, 2) << r;
  EXPECT_EQ(r.errLines(), 1) << r;
  EXPECT_NE(r.err.find("SOMICAGE_MEMORY_LIMIT_BYTES: '8 GB' is not a whole number of bytes"), std::string::npos) << r;
}

// A mesh with normals whose coordinates fit but whose gradients (for the normals carried by J) do not: deform still
// runs, says the normals are recomputed, and writes the recomputed normals (equal to --recompute-normals' file).
TEST(CliMemory, NormalsAreRecomputedWhenTheGradientsDoNotFit) {
  ScratchDir dir;
  const std::string mesh = dir.file("tet.obj");
  std::ofstream(mesh) << kTetWithNormals;
  MemoryEstimate without = estimatePrecomputeMemory(methods::somigliana(), 3, 8, 12, 4, false, 1);
  MemoryEstimate with = without;
  with.gradients = estimateGradientBytes(methods::somigliana(), 3, 8, 12, 4, false);
  ASSERT_GT(with.total(), without.total() + 100);
  const std::string posed = dir.file("posed.obj");
  PolygonMesh cage = loadMesh(dataFile("cube_cage.obj"));
  saveObj(posed, cage.vertices * 1.1, cage);
  std::vector<std::string> args = {
      "deform", "--cage", dataFile("cube_cage.obj"), "--posed", posed, "--mesh", mesh, "--threads", "1", "--out"};
  std::vector<std::string> recomputeArgs = args;
  recomputeArgs.insert(recomputeArgs.end(), {dir.file("recomputed.obj"), "--recompute-normals"});
  const RunResult recomputed = runSomicage(recomputeArgs);
  ASSERT_EQ(recomputed.exitCode, 0) << recomputed;
  {
    // Between the two totals, at the 85 % the check allows.
    const MemoryLimit limit(std::to_string((without.total() + with.total()) / 2 * 100 / 85));
    args.push_back(dir.file("out.obj"));
    const RunResult r = runSomicage(args);
    ASSERT_EQ(r.exitCode, 0) << r;
    EXPECT_NE(r.err.find("the normals are recomputed from the deformed faces"), std::string::npos) << r;
  }
  EXPECT_EQ(readFile(dir.file("out.obj")), readFile(dir.file("recomputed.obj")));
}

}  // namespace
}  // namespace somicage
