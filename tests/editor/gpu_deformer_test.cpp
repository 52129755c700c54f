// The GPU deformer (render/gpu_deformer.h) against the CPU: the positions that the compute shader writes into the
// mesh renderer's vertex buffer, read back, equal CageDeformer::deform() within 1e-5 of the posed cage's diameter
// (the kernel works in float: C converted once, K float products summed per output, Eq. 11 solved in float),
// for every method and parameter family, 2D and 3D, double and float storage, both work layouts; and the GPU
// vertex normals equal render/mesh_normals.h within 1e-3 (unit vectors; float positions, see kNormalTolerance).
//
// Needs an OpenGL 4.3 context: ctest runs this binary under xvfb-run (Mesa llvmpipe). Every test skips visibly when
// no context can be made, or when the shared models are absent (FIREHYDRANT).
#include "gpu_deformer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "base/errors.h"
#include "core/method_cases.h"
#include "core/test_shapes.h"
#include "deform/deformer.h"
#include "gpu_benchmark.h"
#include "io/mesh_formats.h"
#include "mesh_normals.h"
#include "mesh_renderer.h"
#include "methods/method_descriptors.h"
#include "model/scene.h"
#include "offscreen_context.h"

namespace somicage {
namespace {

constexpr double kPositionTolerance = 1e-5;  // of the posed cage's diameter
// Per component of unit normals. The GPU takes cross products of float positions: on FIREHYDRANT's small triangles
// (edges ~1e-2 of the coordinates) that alone moves normals by up to ~2e-4 against the CPU's double positions.
constexpr double kNormalTolerance = 1e-3;

// One hidden window for the whole binary (GLFW is process-wide).
render::OffscreenGlContext& glContext() {
  static render::OffscreenGlContext context(4, 3);
  return context;
}

#define REQUIRE_GPU()                                                                         \
  do {                                                                                        \
    if (!glContext().ok()) GTEST_SKIP() << "no OpenGL 4.3 context: " << glContext().reason(); \
    std::string why;                                                                          \
    if (!render::GpuDeformer::available(&why)) GTEST_SKIP() << why;                           \
  } while (0)

struct TestScene {
  std::string name;
  Cage cage;
  Eigen::MatrixXd points;     // #P by d
  Eigen::MatrixXi triangles;  // #T by 3 over the points
  Eigen::MatrixXd posed;
};

// 3D: an icosphere mesh of radius 0.5 inside a bumpy-sphere cage, bent and moved by a similarity.
TestScene scene3d() {
  TestScene s;
  s.name = "3d";
  s.cage = test::makeBumpySphere(1);
  const Cage mesh = test::makeIcosphere(2);
  s.points = 0.5 * mesh.vertices;
  s.triangles = mesh.faces;
  s.posed = test::randomSimilarity(3, 7).apply(test::bendPose(s.cage.vertices, 0.3, 11));
  return s;
}

// 2D: a triangulated grid (with a few points outside the cage: they follow the cage's similarity) inside a star.
TestScene scene2d() {
  TestScene s;
  s.name = "2d";
  s.cage = test::makeStarPolygon(6);
  const int n = 12;
  s.points.resize(n * n, 2);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) s.points.row(i * n + j) << -0.4 + 0.8 * i / (n - 1), -0.4 + 0.8 * j / (n - 1);
  s.points.row(0) << 1.5, 1.5;  // outside
  s.triangles.resize(2 * (n - 1) * (n - 1), 3);
  int t = 0;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j, b = a + n, c = b + 1, d = a + 1;
      s.triangles.row(t++) << a, b, c;
      s.triangles.row(t++) << a, c, d;
    }
  s.posed = test::randomSimilarity(2, 5).apply(test::bendPose(s.cage.vertices, 0.3, 13));
  return s;
}

struct Comparison {
  double positionError = 0;  // max |gpu - cpu| / diameter
  double normalError = 0;    // max component difference of the normals
  int worstPoint = -1;
};

// Deforms on the CPU and on the GPU (layout) and compares.
Comparison compare(const CageDeformer& deformer, const Eigen::MatrixXd& posed, const DeformParams& params,
                   const Eigen::MatrixXi& triangles, render::GpuDeformerLayout layout = {}) {
  render::MeshRenderer mesh;
  mesh.setTopology(triangles);
  render::GpuDeformer gpu(layout);
  gpu.upload(deformer);
  gpu.deform(posed, params, mesh);
  const Eigen::MatrixXd onGpu = gpu.readBack(mesh);
  const Eigen::MatrixXd onCpu = deformer.deform(posed, params);
  Comparison c;
  EXPECT_EQ(onGpu.rows(), onCpu.rows());
  EXPECT_EQ(onGpu.cols(), onCpu.cols());
  if (onGpu.rows() != onCpu.rows() || onGpu.cols() != onCpu.cols()) return c;
  const double diameter = cageDiameter(posed);
  Eigen::Index worst = 0;
  c.positionError = (onGpu - onCpu).rowwise().norm().maxCoeff(&worst) / diameter;
  c.worstPoint = static_cast<int>(worst);
  if (!onGpu.allFinite()) c.positionError = std::numeric_limits<double>::infinity();
  if (triangles.rows() > 0) {
    const Eigen::MatrixXd normalsGpu = gpu.readBackNormals(mesh);
    const Eigen::MatrixXd normalsCpu = render::vertexNormals(onCpu, triangles).cast<double>();
    c.normalError = (normalsGpu - normalsCpu).cwiseAbs().maxCoeff();
  }
  return c;
}

std::string describe(const DeformParams& p) {
  std::ostringstream s;
  s << "blend " << p.blend << " nu " << p.nu << " gamma " << p.gamma;
  return s.str();
}

std::vector<DeformParams> somiglianaParams() {
  std::vector<DeformParams> all;
  for (double blend : {0.0, 0.5, 1.0})
    for (double nu : {0.3, std::numeric_limits<double>::infinity()})
      for (double gamma : {0.0, 2.0}) all.push_back({blend, nu, gamma, true});
  return all;
}

using Case = test::MethodCase;

std::vector<Case> allCases() {
  std::vector<Case> cases;
  for (int dim : {2, 3})
    for (Method method : allMethods())
      cases.push_back({methodName(method) + "_" + std::to_string(dim) + "d", dim, method});
  return cases;
}

class GpuDeformerTest : public ::testing::TestWithParam<Case> {};

// Every parameter family, with C stored in double (the editor's choice: converted at upload) and in float, and the
// kernel in three work layouts (1, 8 and 32 invocations per point: no reduction, llvmpipe's, GPUs').
TEST_P(GpuDeformerTest, MatchesCpu) {
  REQUIRE_GPU();
  const Case& c = GetParam();
  const TestScene scene = c.dim == 3 ? scene3d() : scene2d();
  const std::vector<DeformParams> params =
      c.method == methods::somigliana() ? somiglianaParams() : std::vector<DeformParams>{DeformParams{}};
  double worst = 0;
  for (bool floatStorage : {false, true}) {
    PrecomputeOptions options;
    options.floatStorage = floatStorage;
    const auto deformer = makeDeformer(c.method, scene.cage, scene.points, options);
    for (int rowThreads : {1, 8, 32}) {
      render::GpuDeformerLayout layout;
      layout.rowThreads = rowThreads;
      for (const DeformParams& p : params) {
        const Comparison r = compare(*deformer, scene.posed, p, scene.triangles, layout);
        const std::string where = describe(p) + (floatStorage ? ", float C" : ", double C") + ", " +
                                  std::to_string(rowThreads) + " invocations per point";
        EXPECT_LE(r.positionError, kPositionTolerance) << where << ", worst point " << r.worstPoint;
        EXPECT_LE(r.normalError, kNormalTolerance) << where;
        worst = std::max(worst, r.positionError);
      }
    }
  }
  RecordProperty("max_relative_error", std::to_string(worst));
  std::printf("[ %s ] largest GPU - CPU difference: %.3g of the cage diameter\n", c.name.c_str(), worst);
}

INSTANTIATE_TEST_SUITE_P(AllMethods, GpuDeformerTest, ::testing::ValuesIn(allCases()), test::methodCaseName);

// Points outside the cage, in the blend band and beyond, and exactly on it (core/deform/exterior_points.h): the GPU's
// second pass (shaders/exterior_blend.comp.glsl) gives what the CPU's blend gives, within the same tolerance.
TEST(GpuDeformer, ExteriorPointsMatchCpu) {
  REQUIRE_GPU();
  for (int dim : {3, 2}) {
    TestScene scene = dim == 3 ? scene3d() : scene2d();
    const Eigen::Index n = scene.points.rows();
    for (Eigen::Index p = 1; p < n; p += 9) scene.points.row(p) *= (p % 2 == 0 ? 2.8 : 5.0);  // band and beyond
    scene.points.row(n - 1) = scene.cage.vertices.row(0);                                     // on the cage
    scene.points.row(n - 2) = 0.5 * (scene.cage.vertices.row(0) + scene.cage.vertices.row(1));
    for (Method method : {methods::somigliana(), methods::green()}) {
      for (bool floatStorage : {false, true}) {
        PrecomputeOptions options;
        options.floatStorage = floatStorage;
        const auto deformer = makeDeformer(method, scene.cage, scene.points, options);
        ASSERT_GE(deformer->frameCoordinates().exteriorBlends.size(), static_cast<std::size_t>(n / 9));
        for (int rowThreads : {1, 32}) {
          render::GpuDeformerLayout layout;
          layout.rowThreads = rowThreads;
          const Comparison r = compare(*deformer, scene.posed, {0.5, 0.3, 1.0, true}, scene.triangles, layout);
          EXPECT_LE(r.positionError, kPositionTolerance)
              << dim << "D " << methodName(method) << (floatStorage ? ", float C, " : ", double C, ") << rowThreads
              << " invocations per point, worst point " << r.worstPoint;
        }
      }
    }
  }
}

// Several frames in a row reuse the uploaded C and the compiled kernels; switching the variant (global <-> local
// changes W's shape and the kernel) and the pose between frames must not leave stale state behind.
TEST(GpuDeformer, FramesInARowAndRestPose) {
  REQUIRE_GPU();
  const TestScene scene = scene3d();
  const auto deformer = makeDeformer(methods::somigliana(), scene.cage, scene.points);
  render::MeshRenderer mesh;
  mesh.setTopology(scene.triangles);
  render::GpuDeformer gpu;
  gpu.upload(*deformer);
  const double diameter = cageDiameter(scene.cage.vertices);
  for (int frame = 0; frame < 6; ++frame) {
    const DeformParams p{frame % 2 == 0 ? 0.0 : 1.0, 0.3, 0.5 * frame, true};
    const Eigen::MatrixXd posed = frame % 3 == 2 ? scene.cage.vertices : scene.posed;
    gpu.deform(posed, p, mesh);
    const double err = (gpu.readBack(mesh) - deformer->deform(posed, p)).rowwise().norm().maxCoeff() / diameter;
    EXPECT_LE(err, kPositionTolerance) << "frame " << frame;
  }
  EXPECT_GE(gpu.lastCpuMilliseconds(), 0.0);
  // At rest, every method of the registry reproduces the points (identity at rest), on the GPU too; and on the
  // pose, the GPU frame is the CPU frame of that method (the kernel's finish is the method's: linear or Eq. 11's).
  for (Method m : allMethods()) {
    SCOPED_TRACE(methodName(m));
    const auto other = makeDeformer(m, scene.cage, scene.points);
    gpu.upload(*other);
    gpu.deform(scene.cage.vertices, {}, mesh);
    EXPECT_LE((gpu.readBack(mesh) - scene.points).cwiseAbs().maxCoeff() / diameter, kPositionTolerance);
    gpu.deform(scene.posed, {}, mesh);
    EXPECT_LE((gpu.readBack(mesh) - other->deform(scene.posed, {})).rowwise().norm().maxCoeff() / diameter,
              kPositionTolerance);
  }
}

// Bad parameters throw like the CPU path (frameWeights validates them) and leave the GPU usable.
TEST(GpuDeformer, InvalidParametersThrow) {
  REQUIRE_GPU();
  const TestScene scene = scene2d();
  const auto deformer = makeDeformer(methods::somigliana(), scene.cage, scene.points);
  render::MeshRenderer mesh;
  mesh.setTopology(scene.triangles);
  render::GpuDeformer gpu;
  gpu.upload(*deformer);
  EXPECT_THROW(gpu.deform(scene.posed, {0.0, 0.7, 0.0, true}, mesh), InputError);
  gpu.deform(scene.posed, {}, mesh);
  EXPECT_LE(
      (gpu.readBack(mesh) - deformer->deform(scene.posed, {})).rowwise().norm().maxCoeff() / cageDiameter(scene.posed),
      kPositionTolerance);
}

// The benchmark entry point opens its own (nested) context and gives ours back afterwards.
TEST(GpuDeformer, BenchmarkTimesAFrameAndRestoresTheContext) {
  REQUIRE_GPU();
  const TestScene scene = scene3d();
  const auto deformer = makeDeformer(methods::green(), scene.cage, scene.points);
  std::string reason;
  const double ms = render::timeGpuDeformMs(*deformer, scene.posed, {}, 5, &reason);
  EXPECT_TRUE(std::isfinite(ms) && ms > 0) << reason;
  const render::GpuFrameTiming t = render::benchmarkGpuDeform(*deformer, scene.posed, {}, 5, scene.triangles);
  ASSERT_TRUE(t.ok) << t.reason;
  EXPECT_EQ(t.frames, 5);
  EXPECT_GT(t.frameMs, 0.0);
  EXPECT_GE(t.gpuMs, 0.0);
  // Our context still works.
  const Comparison r = compare(*deformer, scene.posed, {}, scene.triangles);
  EXPECT_LE(r.positionError, kPositionTolerance);
}

// ---- FIREHYDRANT (shared models): the real editor case, 39k points, 49-vertex cage ----

struct Hydrant {
  editor::Scene scene;
  Eigen::MatrixXd posed;
  std::map<Method, std::shared_ptr<const CageDeformer>> deformers;
};

const Hydrant* hydrant() {
  static std::unique_ptr<Hydrant> h;
  static bool tried = false;
  if (tried) return h.get();
  tried = true;
  const std::filesystem::path dir = std::filesystem::path(SOMICAGE_MODELS_DIR) / "firehydrant";
  if (!std::filesystem::exists(dir / "fireHydrant.obj")) return nullptr;
  h = std::make_unique<Hydrant>();
  h->scene =
      editor::loadScene((dir / "fireHydrant.obj").string(), (dir / "fireHydrant_cages_triangulated.obj").string());
  h->posed = loadPosedVertices((dir / "fireHydrant_cages_triangulated_deformed.obj").string(), h->scene.restCage);
  // Not Phong: FIREHYDRANT's cage is not star-shaped, and C over its generated tetrahedra (d + 1 columns per mesh
  // vertex) would take gigabytes; its GPU frame is the same C W kernel, checked on the small scenes above.
  for (Method m : allMethods())
    if (!m->needsVolumeMesh) h->deformers[m] = makeDeformer(m, h->scene.restCage, h->scene.meshVertices);
  return h.get();
}

TEST(GpuDeformerFireHydrant, MatchesCpu) {
  REQUIRE_GPU();
  const Hydrant* h = hydrant();
  if (!h) GTEST_SKIP() << "shared models not found at " << SOMICAGE_MODELS_DIR << "/firehydrant";
  for (const auto& [method, deformer] : h->deformers) {
    const std::vector<DeformParams> params =
        method == methods::somigliana() ? somiglianaParams() : std::vector<DeformParams>{DeformParams{}};
    for (const DeformParams& p : params) {
      const Comparison r = compare(*deformer, h->posed, p, h->scene.meshTriangles);
      EXPECT_LE(r.positionError, kPositionTolerance)
          << methodName(method) << " " << describe(p) << ", worst point " << r.worstPoint;
      EXPECT_LE(r.normalError, kNormalTolerance) << methodName(method) << " " << describe(p);
      std::printf("[ firehydrant %s %s ] GPU - CPU: %.3g of the diameter, normals %.3g\n", methodName(method).c_str(),
                  describe(p).c_str(), r.positionError, r.normalError);
    }
  }
}

}  // namespace
}  // namespace somicage
