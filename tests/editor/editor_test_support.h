// The editor model tests' one way to get a scene without a window (run the worker's request to its end and install
// the outcome, as the frame loop's pollWorker does), to finish opening a session (and a session reader a test
// steers), and the stand-in for the Renderer's in-place OpenGL device.
#pragma once

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "job_waiting.h"
#include "jobs/session_read.h"
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

// Until the session being opened (loadSessionFile) has been read, then applies it as the frame loop does
// (pollSessionRead); its scene, if another, then loads on the precompute worker.
inline void finishSessionRead(AppState& state) {
  waitUntilDone(state.jobs.session);
  pollSessionRead(state);
}

// A session reader the test steers (loadSessionFile's `read`; declare it before the AppState, which outlives its
// job): it says when it runs, then holds until released or cancelled and reads the file (a cancel
// drops what it read). Held 10 s without either, it gives up and says so: something waited for it.
struct SteeredSessionReader {
  std::atomic<bool> entered{false}, released{false}, timedOut{false};
  SessionReader reader() {
    return [this](const std::string& path, JobContext& context) {
      entered = true;
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
      while (!released && !context.cancelled() && !timedOut) {
        timedOut = std::chrono::steady_clock::now() > deadline;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
      return readSessionFile(path, context);
    };
  }
};

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
