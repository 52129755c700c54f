// Memory estimates before a precompute: the coordinate bytes equal what each deformer stores (exactly, every
// method, 2D and 3D, float and double, points inside and outside the cage), and the refusal when the estimate
// exceeds the free memory (made deterministic with SOMICAGE_MEMORY_LIMIT_BYTES).
#include "deform/memory_estimate.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "base/errors.h"
#include "base/point_blocks.h"
#include "deform/deformer.h"
#include "engine/engine.h"
#include "methods/method_descriptors.h"
#include "test_shapes.h"
#include "tetrahedralization/cage_tetrahedralization.h"

namespace somicage {
namespace {

// Sets an environment variable for the scope of a test and restores the previous state.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old, hadOld_ = true;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (hadOld_)
      ::setenv(name_, old_.c_str(), 1);
    else
      ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::string old_;
  bool hadOld_ = false;
};

// Runs check on every (method, dimension, storage) over the L cage, with 57 points drawn from [lo, hi]^d.
template <typename Check>
void forEachDeformer(double lo, double hi, Check check) {
  const Cage cages[] = {test::makeExtrudedL(), makePolygonCage(test::lLoop())};
  for (const Cage& cage : cages) {
    const Eigen::MatrixXd points = test::randomBoxPoints(57, cage.dim(), lo, hi, 7);
    for (Method method : allMethods()) {
      for (bool floatStorage : {false, true}) {
        PrecomputeOptions options;
        options.floatStorage = floatStorage;
        options.threads = 1;
        const std::unique_ptr<CageDeformer> deformer = makeDeformer(method, cage, points, options);
        const int vertices = layoutVertices(method, cage, deformer->volumeMesh().get());
        const std::size_t estimate =
            estimateCoordinateBytes(method, cage.dim(), vertices, cage.numFaces(), points.rows(), floatStorage);
        check(*deformer, estimate,
              methodName(method) + " " + std::to_string(cage.dim()) + "D " + (floatStorage ? "float" : "double"));
      }
    }
  }
}

TEST(MemoryEstimate, CoordinateBytesEqualWhatEachDeformerStoresForPointsInside) {
  // [0.1, 0.9]^d lies inside the L (which spans [0, 2]^2, and z in [0, 1]): one row of C per point.
  forEachDeformer(0.1, 0.9, [](const CageDeformer& deformer, std::size_t estimate, const std::string& name) {
    EXPECT_EQ(estimate, deformer.frameCoordinates().bytes()) << name;
  });
}

TEST(MemoryEstimate, PointsOutsideTheCageOnlyAddWholeRows) {
  // Points from -0.5 to 2.5: some outside. The estimate is exact per point row; rows a deformer adds for its
  // exterior points (frame_evaluation.h) come on top, so the estimate is then a lower bound by those rows.
  forEachDeformer(-0.5, 2.5, [](const CageDeformer& deformer, std::size_t estimate, const std::string& name) {
    const FrameCoordinates& C = deformer.frameCoordinates();
    const std::size_t rowBytes = estimate / static_cast<std::size_t>(deformer.numPoints());
    EXPECT_EQ(rowBytes * static_cast<std::size_t>(deformer.numPoints()), estimate) << name;
    EXPECT_EQ(C.bytes(), rowBytes * static_cast<std::size_t>(C.rows())) << name;
    EXPECT_LE(estimate, C.bytes()) << name;
  });
}

TEST(MemoryEstimate, TheOutputIsTwoOfTheFramesDeformReturns) {
  // One deformed frame, measured here on what deform returns, and the kernel's row-major buffer of the same size.
  const Cage cages[] = {test::makeExtrudedL(), makePolygonCage(test::lLoop())};
  for (const Cage& cage : cages) {
    const Eigen::MatrixXd points = test::randomBoxPoints(57, cage.dim(), 0.1, 0.9, 7);
    for (Method method : allMethods()) {
      // A method on a volume mesh of the cage (Phong) stores columns per mesh vertex: made first, as the engine does.
      PrecomputeOptions options;
      options.volumeMesher = tetrahedralizeCageWithOptions;
      prepareVolumeMesh(method, cage, options, ignoreNotices);
      const std::unique_ptr<CageDeformer> deformer = makeDeformer(method, cage, points, options);
      const Eigen::MatrixXd frame = deformer->deform(cage.vertices, {});
      const int vertices = layoutVertices(method, cage, options.volumeMesh.get());
      if (method->needsVolumeMesh) {
        EXPECT_GT(vertices, cage.numVertices()) << "the mesh's, with Steiner vertices";
      }
      const MemoryEstimate e = estimatePrecomputeMemory(method, cage.dim(), vertices, cage.numFaces(),
                                                        static_cast<std::size_t>(points.rows()), false, 1);
      EXPECT_EQ(e.output, 2 * static_cast<std::size_t>(frame.size()) * sizeof(double)) << methodName(method);
      EXPECT_EQ(e.coordinates, deformer->frameCoordinates().bytes()) << methodName(method);
    }
  }
}

TEST(MemoryEstimate, DoubleCopiesBeforeFloatStorageAreCounted) {
  // Green and mean value coordinates are computed in double and converted: float storage does not halve the peak.
  const std::size_t P = 1000000;
  for (Method method : {methods::green(), methods::mvc()}) {
    const MemoryEstimate f = estimatePrecomputeMemory(method, 3, 49, 94, P, true, 2);
    EXPECT_GE(f.working, 2 * f.coordinates) << methodName(method);
  }
  // Somigliana writes rows straight into C: its working memory grows per point by exactly the diagnostics a real
  // deformer keeps (measured: winding number, unity residual, region), and per thread by less than a group's rows of C
  // and one more, in double (the thread's pack buffer of up to kMaxGroupLanes points' rows and a row buffer).
  const Cage cage = test::makeExtrudedL();
  const auto deformer = makeDeformer(methods::somigliana(), cage, test::randomBoxPoints(57, 3, -0.5, 2.5, 7));
  const PrecomputeDiagnostics& d = deformer->diagnostics();
  const std::size_t perPoint = (static_cast<std::size_t>(d.winding.size() + d.unityResidual.size()) * sizeof(double) +
                                d.regions.size() * sizeof(PointRegion)) /
                               57;
  const auto working = [&](std::size_t points, int threads) {
    return estimatePrecomputeMemory(methods::somigliana(), 3, cage.numVertices(), cage.numFaces(), points, true,
                                    threads)
        .working;
  };
  EXPECT_EQ(working(2 * P, 2) - working(P, 2), P * perPoint);
  const std::size_t perThread = working(P, 3) - working(P, 2);
  EXPECT_GT(perThread, 0u);
  EXPECT_LE(perThread,
            (kMaxGroupLanes + 1) * static_cast<std::size_t>(deformer->frameCoordinates().columns()) * sizeof(double));
  const MemoryEstimate s = estimatePrecomputeMemory(methods::somigliana(), 3, 49, 94, P, true, 2);
  EXPECT_EQ(s.coordinates, P * (49 * 10 + 94 * 4 + 10 + 18 + 4) * sizeof(float));
}

TEST(MemoryEstimate, SeveralDeformersAddTheirCoordinatesNotTheirWorkingMemory) {
  MemoryEstimate sum = estimatePrecomputeMemory(methods::somigliana(), 3, 20, 36, 1000, true, 1);
  const MemoryEstimate green = estimatePrecomputeMemory(methods::green(), 3, 20, 36, 1000, true, 1);
  const std::size_t coordinates = sum.coordinates + green.coordinates, working = std::max(sum.working, green.working);
  sum += green;
  EXPECT_EQ(sum.coordinates, coordinates);
  EXPECT_EQ(sum.working, working);  // built one after the other
}

TEST(MemoryEstimate, RefusesWithTheSizesAndAHintWhenItDoesNotFit) {
  const MemoryEstimate e = estimatePrecomputeMemory(methods::somigliana(), 3, 49, 94, 12000000, false, 2);
  ASSERT_GT(e.total(), 40000000000u);  // about 86 GB in double
  try {
    requireMemory(e, std::size_t(22900000000), "mesh.obj", memoryHint(true));
    FAIL() << "no refusal";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(error.source(), "mesh.obj");
    EXPECT_NE(message.find("12,000,000 points need"), std::string::npos) << message;
    EXPECT_NE(message.find("but only 22.9 GB are free"), std::string::npos) << message;
    EXPECT_NE(message.find("decimate the mesh"), std::string::npos) << message;
    EXPECT_NE(message.find("store the coordinates in float"), std::string::npos) << message;
  }
  // The safety margin: 85% of the free memory may be used, not more.
  const double limit = e.total() / kMemorySafetyFraction;
  EXPECT_NO_THROW(requireMemory(e, static_cast<std::size_t>(limit * 1.001), "mesh.obj", ""));
  EXPECT_THROW(requireMemory(e, static_cast<std::size_t>(limit * 0.999), "mesh.obj", ""), InputError);
  EXPECT_NO_THROW(requireMemory(e, std::nullopt, "mesh.obj", ""));  // unknown: no refusal
}

TEST(MemoryEstimate, TheEnvironmentOverridesTheFreeMemory) {
  {
    ScopedEnv limit(kMemoryLimitVariable, "123456789");
    EXPECT_EQ(availableMemoryBytes(), std::optional<std::size_t>(123456789));
  }
  for (const char* bad : {"", "12 GB", "-5", "1e9", "99999999999999999999999"}) {
    ScopedEnv limit(kMemoryLimitVariable, bad);
    EXPECT_THROW(availableMemoryBytes(), InputError) << "'" << bad << "'";
  }
}

TEST(MemoryEstimate, FreeMemoryOfThisMachineIsKnownOnLinux) {
  if (std::getenv(kMemoryLimitVariable)) GTEST_SKIP() << kMemoryLimitVariable << " is set";
#ifdef __linux__
  const std::optional<std::size_t> free = availableMemoryBytes();
  ASSERT_TRUE(free.has_value());
  EXPECT_GT(*free, std::size_t(1) << 24);  // a test machine has more than 16 MiB free
#else
  GTEST_SKIP() << "not Linux";
#endif
}

TEST(MemoryEstimate, Formatting) {
  EXPECT_EQ(formatCount(0), "0");
  EXPECT_EQ(formatCount(999), "999");
  EXPECT_EQ(formatCount(1000), "1,000");
  EXPECT_EQ(formatCount(12000000), "12,000,000");
  EXPECT_EQ(formatBytes(137000000), "137 MB");
  EXPECT_EQ(formatBytes(41230000000), "41.2 GB");
  EXPECT_EQ(formatBytes(512), "512 bytes");
}

}  // namespace
}  // namespace somicage
