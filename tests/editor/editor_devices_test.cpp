// The editor's frame devices (frame_device_evaluators.h), without GL: the chosen device's evaluator is what
// computes the frames, an unusable device is refused with its reason and the CPU deforms, a device failing at run
// time hands over to the CPU, the in-place OpenGL path leaves the CPU points to the Renderer, and --device.
// The GPU kernel itself is tested in gpu_deformer_test.cpp (under Xvfb).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "base/errors.h"
#include "coordinates/somigliana_coordinates.h"
#include "cuda/cuda_backend.h"
#include "editor_options.h"
#include "editor_test_support.h"
#include "engine/engine.h"
#include "jobs/precompute_worker.h"
#include "jobs/thread_budget.h"
#include "methods/method_descriptors.h"
#include "model/app_state.h"
#include "model/frame_device_evaluators.h"
#include "ui/panels.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

struct Counts {
  int made = 0, frames = 0;
};

// The CPU's evaluator, counting the frames it evaluates.
class CountingEvaluator final : public FrameEvaluator {
 public:
  CountingEvaluator(const CageDeformer& deformer, Counts& counts) : cpu_(deformer), counts_(counts) {}
  void evaluate(const FrameWeights& W, Eigen::MatrixXd& out) override {
    ++counts_.frames;
    cpu_.evaluate(W, out);
  }

 private:
  CpuFrameEvaluator cpu_;
  Counts& counts_;
};

FrameDevice countingDevice(const std::string& name, const std::shared_ptr<Counts>& counts) {
  return {name,
          name,
          [counts](const CageDeformer& deformer) {
            ++counts->made;
            return std::make_unique<CountingEvaluator>(deformer, *counts);
          },
          {},
          {}};
}

// A device whose factory refuses (no device after all), optionally saying so beforehand too.
FrameDevice refusingDevice(const std::string& name, const std::string& reason, bool saysSoBeforehand) {
  FrameDevice device{
      name,
      name,
      [reason](const CageDeformer&) -> std::unique_ptr<FrameEvaluator> { throw FrameDeviceUnavailable(reason); },
      {},
      {}};
  if (saysSoBeforehand) device.unavailable = [reason] { return reason; };
  return device;
}

// The demo cage with its right half sheared upwards: not a similarity, so every coordinate block matters.
Eigen::MatrixXd shearedPose(const AppState& state) {
  Eigen::MatrixXd pose = state.document.pose;
  for (Eigen::Index i = 0; i < pose.rows(); ++i)
    if (pose(i, 0) > 0.0) pose(i, 1) += 0.4 * pose(i, 0);
  return pose;
}

double maxDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  EXPECT_EQ(a.rows(), b.rows());
  EXPECT_EQ(a.cols(), b.cols());
  return a.rows() == b.rows() && a.cols() == b.cols() ? (a - b).cwiseAbs().maxCoeff() : HUGE_VAL;
}

// What view v should show: its deformer's own CPU deformation of the current pose with the view's parameters.
Eigen::MatrixXd expectedPoints(const AppState& state, std::size_t v) {
  return state.model.deformers.at(state.views()[v].method)->deform(state.document.pose, state.viewParams(v));
}

}  // namespace

TEST(EditorDevices, FramesAreEvaluatedOnTheChosenDevice) {
  AppState state;
  auto counts = std::make_shared<Counts>();
  EXPECT_EQ(
      chooseDevice(state.model.devices, {cpuFrameDevice(), countingDevice("fake", counts)}, "fake", kCpuDevice, ""),
      "");
  EXPECT_EQ(state.model.devices.active(), "fake");
  openDemoScene(state, 3);
  setPose(state, shearedPose(state));
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_EQ(counts->made, 1);
  EXPECT_EQ(counts->frames, 1);
  EXPECT_LT(maxDifference(displayedPoints(state, 0), expectedPoints(state, 0)), 1e-12);
  EXPECT_GT(maxDifference(displayedPoints(state, 0), state.model.scene->meshVertices), 0.05);  // it moved

  // The next frame reuses the evaluator (C is uploaded once per deformer).
  DeformParams params = state.document.params;
  params.nu = 0.3;
  params.gamma = 1.0;
  params.blend = 1.0;
  setParams(state, params);
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_EQ(counts->made, 1);
  EXPECT_EQ(counts->frames, 2);
  EXPECT_LT(maxDifference(displayedPoints(state, 0), expectedPoints(state, 0)), 1e-12);

  // Compare views, two of one method at their own nu: one evaluator per deformer, one frame per view.
  std::vector<ViewSpec> compared = viewsOf({methods::somigliana(), methods::somigliana(), methods::green()});
  compared[1].own["nu"] = 0.45;
  setCompareViews(state, compared);  // (turns compare on)
  installNextOutcome(state);
  ASSERT_TRUE(updateDeformation(state));
  const std::size_t views = state.views().size();
  ASSERT_EQ(views, 3u);
  EXPECT_EQ(counts->made, 2);  // Somigliana's evaluator is kept, Green's is new
  EXPECT_EQ(counts->frames, 2 + static_cast<int>(views));
  for (std::size_t v = 0; v < views; ++v)
    EXPECT_LT(maxDifference(displayedPoints(state, v), expectedPoints(state, v)), 1e-12) << "view " << v;
  EXPECT_GT(maxDifference(displayedPoints(state, 0), displayedPoints(state, 1)), 1e-3);  // nu 0.3 vs 0.45
  EXPECT_TRUE(state.status.errors.empty());

  // Back to the CPU: the device's evaluators go, the CPU evaluates.
  setDevice(state, kCpuDevice);
  EXPECT_EQ(state.model.devices.evaluators.size(), 0u);
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_EQ(counts->frames, 2 + static_cast<int>(views));
}

TEST(EditorDevices, UnavailableDeviceIsRefusedWithItsReason) {
  AppState state;
  auto counts = std::make_shared<Counts>();
  const FrameDevices devices = {cpuFrameDevice(), inPlaceDevice(), refusingDevice("cuda", "no CUDA device", true),
                                countingDevice("fake", counts)};
  EXPECT_EQ(chooseDevice(state.model.devices, devices, "cuda", kInPlaceDevice, "no OpenGL 4.3 context"),
            "no CUDA device");
  EXPECT_EQ(state.model.devices.active(), kCpuDevice);
  EXPECT_EQ(state.model.devices.requested, kCpuDevice);  // the panel shows the device that deforms
  EXPECT_EQ(state.model.devices.unavailable.at("cuda"), "no CUDA device");
  EXPECT_EQ(state.model.devices.unavailable.at(kInPlaceDevice), "no OpenGL 4.3 context");
  EXPECT_FALSE(state.model.devices.usable(kInPlaceDevice));
  EXPECT_TRUE(state.model.devices.usable("fake"));
  // Without --device the preferred device falls back quietly (the panel says why).
  EXPECT_EQ(chooseDevice(state.model.devices, devices, std::nullopt, kInPlaceDevice, "no OpenGL 4.3 context"), "");
  EXPECT_EQ(state.model.devices.active(), kCpuDevice);
  // A device not offered at all (an editor without CUDA's entry) is refused too.
  EXPECT_EQ(chooseDevice(state.model.devices, {cpuFrameDevice()}, "cuda", kCpuDevice, ""),
            "not offered by this executable");
  EXPECT_EQ(chooseDevice(state.model.devices, devices, "cuda", kCpuDevice, ""), "no CUDA device");

  openDemoScene(state, 3);
  setDevice(state, "cuda");  // what a disabled radio button cannot do: the CPU still deforms
  EXPECT_EQ(state.model.devices.active(), kCpuDevice);
  setPose(state, shearedPose(state));
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_TRUE(state.status.errors.empty());
  EXPECT_EQ(counts->frames, 0);
  EXPECT_LT(maxDifference(displayedPoints(state, 0), expectedPoints(state, 0)), 1e-12);
}

TEST(EditorDevices, DeviceFailingAtRunTimeHandsOverToTheCpu) {
  AppState state;
  // The cheap check cannot tell; making the evaluator throws.
  EXPECT_EQ(chooseDevice(state.model.devices, {cpuFrameDevice(), refusingDevice("cuda", "out of device memory", false)},
                         "cuda", kCpuDevice, ""),
            "");
  EXPECT_EQ(state.model.devices.active(), "cuda");
  openDemoScene(state, 3);
  setPose(state, shearedPose(state));
  ASSERT_TRUE(updateDeformation(state));
  ASSERT_EQ(state.status.errors.size(), 1u);
  EXPECT_NE(state.status.errors.front().find("cuda deformation failed, using the CPU: out of device memory"),
            std::string::npos)
      << state.status.errors.front();
  EXPECT_NE(state.model.devices.unavailable.at("cuda").find("out of device memory"), std::string::npos);
  EXPECT_EQ(state.model.devices.active(), kCpuDevice);
  EXPECT_LT(maxDifference(displayedPoints(state, 0), expectedPoints(state, 0)), 1e-12);
}

TEST(EditorDevices, BadParametersAreReportedNotBlamedOnTheDevice) {
  AppState state;
  auto counts = std::make_shared<Counts>();
  chooseDevice(state.model.devices, {cpuFrameDevice(), countingDevice("fake", counts)}, "fake", kCpuDevice, "");
  openDemoScene(state, 3);
  DeformParams params = state.document.params;
  params.nu = 0.7;  // outside (-1, 0.5)
  setParams(state, params);
  updateDeformation(state);
  ASSERT_EQ(state.status.errors.size(), 1u);
  EXPECT_NE(state.status.errors.front().find("deformation failed"), std::string::npos) << state.status.errors.front();
  EXPECT_EQ(counts->frames, 0);
  EXPECT_EQ(state.model.devices.active(), "fake");  // still usable
}

// A device with its own row integrator (CUDA's) computes the editor's coordinates too, so the whole pipeline runs on
// it. The counting integrator wraps the CPU's: the result must equal an independent CPU precompute of the scene.
TEST(EditorDevices, TheChosenDevicesIntegratorComputesTheCoordinates) {
  auto integrations = std::make_shared<int>(0);
  FrameDevice device = countingDevice("fake", std::make_shared<Counts>());
  device.rowIntegrator = [integrations](const Cage& cage, const Eigen::MatrixXd& points,
                                        const IntegrationOptions& options, const ProgressCallback& progress,
                                        const CoordinateRowSink& sink) {
    ++*integrations;
    integrateSomiglianaCoordinates(cage, points, options, progress, sink);
  };
  AppState state;
  ASSERT_EQ(chooseDevice(state.model.devices, {cpuFrameDevice(), device}, "fake", kCpuDevice, ""), "");
  openDemoScene(state, 3);
  ASSERT_EQ(state.views()[0].method, Method(methods::somigliana()));
  EXPECT_EQ(*integrations, 1);  // the one Somigliana deformer of the one view
  setPose(state, shearedPose(state));
  ASSERT_TRUE(updateDeformation(state));

  const std::unique_ptr<CageDeformer> cpu = precompute(state.views()[0].method, state.model.scene->restCage,
                                                       state.model.scene->meshVertices, interactiveOptions(), "test");
  EXPECT_LT(maxDifference(displayedPoints(state, 0), cpu->deform(state.document.pose, state.viewParams(0))), 1e-12);
}

TEST(EditorDevices, InPlaceOpenGlLeavesCpuPointsStaleUntilNeeded) {
  AppState state;
  EXPECT_EQ(chooseDevice(state.model.devices, {cpuFrameDevice(), inPlaceDevice()}, std::nullopt, kInPlaceDevice, ""),
            "");
  EXPECT_TRUE(state.model.devices.inPlace());
  openDemoScene(state, 3);
  setPose(state, shearedPose(state));
  const std::uint64_t generation = state.model.deformGeneration;
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_EQ(state.model.deformGeneration, generation + 1);  // the Renderer deforms on the GPU
  ASSERT_EQ(state.model.cpuStale.size(), 1u);
  EXPECT_EQ(state.model.cpuStale.front(), 0u);      // the one view (Somigliana)
  EXPECT_EQ(state.model.deformed.at(0).size(), 0);  // nothing computed on the CPU

  ensureCpuPoints(state, 0);  // what framing and export call: the CPU, never opengl's make()
  EXPECT_TRUE(state.model.cpuStale.empty());
  const Eigen::MatrixXd expected = expectedPoints(state, 0);
  EXPECT_LT(maxDifference(displayedPoints(state, 0), expected), 1e-12);

  // Back to the CPU: the next update computes on the CPU again.
  state.model.deformDirty = false;
  setDevice(state, kCpuDevice);
  EXPECT_TRUE(state.model.deformDirty);
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_TRUE(state.model.cpuStale.empty());
  EXPECT_LT(maxDifference(displayedPoints(state, 0), expected), 1e-12);
}

// This executable's CUDA entry: offered, and refused with CUDA's own reason where there is no usable device.
TEST(EditorDevices, CudaIsListedAndSaysWhyItCannotRun) {
  if (cudaStatus().available) GTEST_SKIP() << "a CUDA device is here: " << cudaStatus().deviceName;
  AppState state;
  EXPECT_EQ(chooseDevice(state.model.devices, {cpuFrameDevice(), cudaFrameDevice()}, "cuda", kCpuDevice, ""),
            cudaStatus().reason);
  EXPECT_FALSE(cudaStatus().reason.empty());
  ASSERT_NE(findFrameDevice(state.model.devices.offered, "cuda"), nullptr);
  EXPECT_EQ(state.model.devices.unavailable.at("cuda"), cudaStatus().reason);
  EXPECT_EQ(state.model.devices.active(), kCpuDevice);
}

// With a usable CUDA device the editor's frames are computed there: the CPU's points within 1e-9 cage diameters
// (double C on both; only the order of the sums differs, cuda_backend_test.cpp).
TEST(EditorDevices, CudaDeviceDeformsLikeTheCpu) {
  if (!cudaStatus().available) GTEST_SKIP() << "no CUDA device: " << cudaStatus().reason;
  AppState state;
  ASSERT_EQ(chooseDevice(state.model.devices, {cpuFrameDevice(), cudaFrameDevice()}, "cuda", kCpuDevice, ""), "");
  openDemoScene(state, 3);
  setPose(state, shearedPose(state));
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  EXPECT_EQ(state.model.devices.active(), "cuda");
  EXPECT_EQ(state.model.devices.evaluators.size(), 1u);
  const Cage& cage = state.model.scene->restCage;
  const double diameter = (cage.vertices.colwise().maxCoeff() - cage.vertices.colwise().minCoeff()).norm();
  EXPECT_LT(maxDifference(displayedPoints(state, 0), expectedPoints(state, 0)), 1e-9 * diameter);
}

TEST(EditorDevices, CommandLineOption) {
  EXPECT_FALSE(parseEditorArgs({}).device.has_value());
  EXPECT_EQ(parseEditorArgs({"--device", "cuda"}).device.value_or(""), "cuda");
  EXPECT_THROW(parseEditorArgs({"--device"}), InputError);
  EXPECT_THROW(parseEditorArgs({"--backend", "gpu"}), InputError);  // replaced by --device

  const FrameDevices devices = {cpuFrameDevice(), inPlaceDevice(), refusingDevice("cuda", "no CUDA device", true)};
  EXPECT_NO_THROW(checkDeviceOption(parseEditorArgs({}), devices));
  EXPECT_NO_THROW(checkDeviceOption(parseEditorArgs({"--device", "opengl"}), devices));
  EXPECT_NO_THROW(checkDeviceOption(parseEditorArgs({"--device", "cuda"}), devices));  // refused later, with why
  try {
    checkDeviceOption(parseEditorArgs({"--device", "gpu"}), devices);
    ADD_FAILURE() << "an unknown device was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("--device"), std::string::npos) << what;
    EXPECT_NE(what.find("'gpu'"), std::string::npos) << what;
    EXPECT_NE(what.find("cpu, opengl, cuda"), std::string::npos) << what;
  }
}

// Issue 24, row 15: the status bar said "cpu (OpenMP, 1 threads)".
TEST(EditorDevices, TheStatusBarCountsThreadsInGoodEnglish) {
  AppState state;
  state.model.scene = std::make_shared<const Scene>(makeDemoScene(2));
  state.status.message = "loaded demo";
  const int cores = ThreadBudget::machine().cores();
  state.status.stats.deformThreads = 1;  // a job holds the other cores
  const std::string one = statusBarText(state);
  const std::string oneText =
      cores == 1 ? "cpu (OpenMP, 1 thread)" : "cpu (OpenMP, 1 of " + std::to_string(cores) + " threads)";
  EXPECT_NE(one.find(oneText), std::string::npos) << one;
  EXPECT_EQ(one.rfind("loaded demo   |", 0), 0u) << one;
  state.status.stats.deformThreads = cores;
  const std::string all = statusBarText(state);
  const std::string allText = "cpu (OpenMP, " + std::to_string(cores) + (cores == 1 ? " thread)" : " threads)");
  EXPECT_NE(all.find(allText), std::string::npos) << all;
}

// Issue 27: the status bar said "1 threads" on a 2-core machine before the first deformation (the count started at
// 1); it starts at the machine's cores.
TEST(EditorDevices, TheStatusBarCountsTheMachinesCoresBeforeTheFirstDeformation) {
  AppState state;
  state.model.scene = std::make_shared<const Scene>(makeDemoScene(2));
  EXPECT_EQ(state.status.stats.deformThreads, availableCores());
  const std::string text = statusBarText(state);
  if (availableCores() > 1) {
    EXPECT_EQ(text.find("OpenMP, 1 thread"), std::string::npos) << text;
  }
}
