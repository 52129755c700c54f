// The editor model tests' one way to get a scene without a window (run the worker's request to its end and install
// the outcome, as the frame loop's pollWorker does), and the stand-in for the Renderer's in-place OpenGL device.
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <optional>

#include "job_waiting.h"
#include "model/app_state.h"
#include "model/frame_device_evaluators.h"
#include "ui/quantity_overlay.h"

namespace somicage::editor {

// Waits for the worker's running request and installs its outcome (fails the test when there is none).
inline void installNextOutcome(AppState& state) {
  std::optional<PrecomputeOutcome> out = waitForOutcome(state.jobs.precompute);
  ASSERT_TRUE(out.has_value()) << "the worker had no request";
  installOutcome(state, std::move(*out));
}

// Until the views' measurements (and a requested sweep) are installed, as a scripted screenshot waits for them.
inline void waitForMeasurements(AppState& state) {
  waitUntil([&state] { return measurementsSettled(state); });
}

// The built-in demo of dimension dim, installed as a freshly opened scene (history: the original only).
inline void openDemoScene(AppState& state, int dim = 3) {
  requestDemo(state, dim);
  installNextOutcome(state);
  ASSERT_TRUE(state.model.scene) << (state.status.errors.empty() ? "no scene" : state.status.errors.front());
}

// The editor evaluates "opengl" in place (the Renderer's GpuDeformer): its factory must never be called.
inline FrameDevice inPlaceDevice() {
  return {kInPlaceDevice,
          "gpu",
          [](const CageDeformer&) -> std::unique_ptr<FrameEvaluator> {
            ADD_FAILURE() << "the editor made the in-place device's evaluator";
            throw FrameDeviceUnavailable("not here");
          },
          {},
          {}};
}

}  // namespace somicage::editor
