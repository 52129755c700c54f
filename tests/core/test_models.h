// The models of ../shared/models (published meshes, cages and poses) that the engine tests run on, the helpers
// that find them under SOMICAGE_MODELS_DIR (skipping visibly when absent), and the precompute checks that every
// coordinate method's tests share.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "base/errors.h"
#include "deform/deformer.h"
#include "geometry/cage.h"
#include "io/mesh_formats.h"

namespace somicage::test {

// ---------------------------------------------------------------------------------------------------------------
// The shared models
// ---------------------------------------------------------------------------------------------------------------

#ifdef SOMICAGE_SANITIZE
constexpr int kMaxModelPoints = 200;  // instrumented code is ~20x slower; a subsample still covers every model
#else
constexpr int kMaxModelPoints = 2000;
#endif

struct ModelCase {
  std::string folder, mesh, cage, pose;  // pose may be empty
  double insideFraction;                 // the share of mesh vertices inside the cage (models/README.md)
};

// Names the case in test output (GoogleTest would print its bytes).
inline void PrintTo(const ModelCase& c, std::ostream* out) { *out << c.folder << "/" << c.cage; }

// Every triangle cage of the shared models, with its mesh and (where published) a posed cage.
inline std::vector<ModelCase> modelCases() {
  return {
      {"firehydrant", "fireHydrant.obj", "fireHydrant_cages_triangulated.obj",
       "fireHydrant_cages_triangulated_deformed.obj", 1.0},
      {"spikybox", "SpikyBox.obj", "spikybox_cages_triangulated.obj", "spikybox_cages_triangulated_deformed.obj", 1.0},
      {"wiresphere", "wireSphere.obj", "wireSphere_cages_triangulated.obj",
       "wireSphere_cages_triangulated_deformed.obj", 1.0},
      {"cactus", "cactus.obj", "cactus_cages_triangulated.obj", "cactus_cages_triangulated_deformed.obj", 1.0},
      {"ogre", "ogre.obj", "ogre_cages_triangulated.obj", "ogre_cages_triangulated_deformed.obj", 1.0},
      {"botijo", "botijo.obj", "botijo_cages_triangulated.obj", "botijo_cages_triangulated_deformed.obj", 1.0},
      {"manhead", "manHead.obj", "manHead_cages_triangulated.obj", "manHead_cages_triangulated_deformed.obj", 1.0},
      {"beast", "Beast.obj", "beast_cages_triangulated.obj", "beast_cages_triangulated_deformed.obj", 1.0},
      {"bench", "Bench.obj", "bench_cages_triangulated.obj", "bench_cages_triangulated_deformed.obj", 1.0},
      {"armadillo", "armadilloman.obj", "bounding_mesh.obj", "deformed_fixed_1.obj", 1.0},
      {"horse", "horse.obj", "bounding_meshb.obj", "deformed_bounding_mesh4b.obj", 1.0},
      {"chessbishop", "chessBishop.obj", "bishop_cages_triangulated.obj", "bishop_cages_triangulated_deformed.obj",
       1.0},
      {"sphere", "sphere.obj", "sphere_cages_triangulated.obj", "sphere_cages_triangulated_deformed.obj", 1.0},
      {"cube", "cube.obj", "cube_cages_triangulated.obj", "", 1.0},
      {"bar", "bar.OBJ", "bar_cage.OBJ", "", 1.0},
      {"bar", "bar.OBJ", "bar_cage_complex.obj", "", 1.0},
      {"bar", "bar.OBJ", "bar_cage_partial.OBJ", "", 0.46},
      {"bunny", "bunny.obj", "bunny-cage-robust.obj", "", 1.0},
  };
}

// The test name of a case: its cage file name up to the first '.', other than letters and digits made '_'.
inline std::string modelCaseName(const ::testing::TestParamInfo<ModelCase>& info) {
  std::string name = info.param.cage.substr(0, info.param.cage.find('.'));
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

// SOMICAGE_MODELS_DIR / the case's folder / file, as a string for the loaders.
inline std::string modelPath(const ModelCase& c, const std::string& file) {
  return (std::filesystem::path(SOMICAGE_MODELS_DIR) / c.folder / file).string();
}

// True, with the calling test marked skipped and the missing path in its message, when the case's cage file is
// absent (the shared folder is optional). Use as `if (test::skipIfModelAbsent(c)) return;`.
inline bool skipIfModelAbsent(const ModelCase& c) {
  const std::string cage = modelPath(c, c.cage);
  if (std::filesystem::exists(cage)) return false;
  [&] { GTEST_SKIP() << "model absent: " << cage; }();
  return true;
}

// The case's cage and every `stride`-th vertex of its mesh, from the first (rows / stride of them); stride 0 picks
// the smallest stride that leaves at most kMaxModelPoints. False, with the test marked skipped when the model is
// absent and failed when its cage is not 3D; use as `if (!test::loadModel(c, cage, points)) return;`.
inline bool loadModel(const ModelCase& c, Cage& cage, Eigen::MatrixXd& points, int stride = 0) {
  if (skipIfModelAbsent(c)) return false;
  cage = loadCage(modelPath(c, c.cage));
  if (cage.dim() != 3) {
    ADD_FAILURE() << c.cage << " is a " << cage.dim() << "D cage, not 3D";
    return false;
  }
  const Eigen::MatrixXd vertices = loadMesh(modelPath(c, c.mesh)).vertices;
  if (stride == 0) stride = static_cast<int>((vertices.rows() + kMaxModelPoints - 1) / kMaxModelPoints);
  points.resize(vertices.rows() / stride, 3);
  for (int p = 0; p < points.rows(); ++p) points.row(p) = vertices.row(p * stride);
  return true;
}

// compute()'s result, with its time recorded as the test property precompute_ms_per_1000_points.
template <class Compute>
auto timedPrecompute(Eigen::Index numPoints, Compute compute) {
  const auto start = std::chrono::steady_clock::now();
  auto result = compute();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ::testing::Test::RecordProperty("precompute_ms_per_1000_points", std::to_string(1e6 * seconds / numPoints));
  return result;
}

// ---------------------------------------------------------------------------------------------------------------
// Precompute checks every method passes
// ---------------------------------------------------------------------------------------------------------------

// Bitwise the same deformed points for a posed cage whether the precompute ran on 1 thread or on 3.
inline void expectDeformIndependentOfThreads(Method method, const Cage& cage, const Eigen::MatrixXd& points,
                                             const Eigen::MatrixXd& posed) {
  PrecomputeOptions options;
  options.threads = 1;
  const Eigen::MatrixXd a = makeDeformer(method, cage, points, options)->deform(posed, {});
  options.threads = 3;
  EXPECT_TRUE(a == makeDeformer(method, cage, points, options)->deform(posed, {})) << methodName(method);
}

// The precompute reports 0, rising fractions and 1, and stops with Cancelled on the second report that says stop.
inline void expectProgressAndCancel(Method method, const Cage& cage, const Eigen::MatrixXd& points) {
  std::vector<double> fractions;
  makeDeformer(method, cage, points, {}, [&](double f) {
    fractions.push_back(f);
    return true;
  });
  ASSERT_GE(fractions.size(), 3u);
  EXPECT_EQ(fractions.front(), 0.0);
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));

  int calls = 0;
  EXPECT_THROW(makeDeformer(method, cage, points, {}, [&](double) { return ++calls < 2; }), Cancelled);
  EXPECT_EQ(calls, 2);
}

}  // namespace somicage::test
