// The deformation backend switch of AppState, without GL: which backend is active, what the GPU path leaves for
// the Renderer (stale CPU points, a bumped generation), and that framing/export still get exact CPU numbers.
// The GPU kernel itself is tested in gpu_deformer_test.cpp (under Xvfb).
#include <gtest/gtest.h>

#include "app_state.h"
#include "editor_options.h"
#include "errors.h"
#include "methods/method_descriptors.h"

using namespace somicage;
using namespace somicage::editor;

namespace {
void loadDemo(AppState& state, int dim) {
  requestDemo(state, dim);
  std::optional<PrecomputeOutcome> out = state.worker.wait();
  EXPECT_TRUE(out.has_value());
  if (out) installOutcome(state, std::move(*out));
  EXPECT_TRUE(state.errors.empty());
}
}  // namespace

TEST(EditorBackend, GpuIsUsedOnlyWhenAvailable) {
  AppState state;
  EXPECT_EQ(state.activeBackend(), DeformBackend::Cpu);  // no GL context yet
  EXPECT_FALSE(state.backend.gpuNote.empty());
  state.backend.requested = DeformBackend::Gpu;
  EXPECT_EQ(state.activeBackend(), DeformBackend::Cpu);
  state.backend.gpuAvailable = true;
  EXPECT_EQ(state.activeBackend(), DeformBackend::Gpu);
  state.deformDirty = false;
  setBackend(state, DeformBackend::Cpu);
  EXPECT_TRUE(state.deformDirty);
  EXPECT_EQ(state.activeBackend(), DeformBackend::Cpu);
}

TEST(EditorBackend, GpuPathLeavesCpuPointsStaleUntilNeeded) {
  AppState state;
  loadDemo(state, 3);
  ASSERT_TRUE(state.scene);
  state.backend.gpuAvailable = true;
  state.backend.requested = DeformBackend::Gpu;
  Eigen::MatrixXd pose = state.pose;
  for (Eigen::Index i = 0; i < pose.rows(); ++i)
    if (pose(i, 0) > 2.0) pose(i, 1) += 0.5;
  setPose(state, pose);
  const std::uint64_t generation = state.deformGeneration;
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_EQ(state.deformGeneration, generation + 1);  // the Renderer deforms on the GPU
  ASSERT_EQ(state.cpuStale.size(), 1u);
  EXPECT_EQ(state.cpuStale.front(), 0u);      // the one view (Somigliana)
  EXPECT_EQ(state.deformed.at(0).size(), 0);  // nothing computed on the CPU

  ensureCpuPoints(state, 0);  // what framing and export call
  EXPECT_TRUE(state.cpuStale.empty());
  const Eigen::MatrixXd expected = state.deformers.at(methods::somigliana())->deform(state.pose, state.params);
  EXPECT_EQ((displayedPoints(state, 0) - expected).cwiseAbs().maxCoeff(), 0.0);

  // Back to the CPU: the next update computes on the CPU again.
  setBackend(state, DeformBackend::Cpu);
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_TRUE(state.cpuStale.empty());
  EXPECT_EQ((displayedPoints(state, 0) - expected).cwiseAbs().maxCoeff(), 0.0);
}

TEST(EditorBackend, CommandLineOption) {
  EXPECT_FALSE(parseEditorArgs({}).backend.has_value());
  EXPECT_EQ(parseEditorArgs({"--backend", "gpu"}).backend, DeformBackend::Gpu);
  EXPECT_EQ(parseEditorArgs({"--backend", "cpu"}).backend, DeformBackend::Cpu);
  EXPECT_THROW(parseEditorArgs({"--backend", "cuda"}), InputError);
}
