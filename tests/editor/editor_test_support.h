// The editor model tests' one way to get a scene without a window: run the worker's request to its end and install
// the outcome, as the frame loop's pollWorker does.
#pragma once

#include <gtest/gtest.h>

#include <optional>

#include "app_state.h"

namespace somicage::editor {

// Waits for the worker's running request and installs its outcome (fails the test when there is none).
inline void installNextOutcome(AppState& state) {
  std::optional<PrecomputeOutcome> out = state.worker.wait();
  ASSERT_TRUE(out.has_value()) << "the worker had no request";
  installOutcome(state, std::move(*out));
}

// The built-in demo of dimension dim, installed as a freshly opened scene (history: the original only).
inline void openDemoScene(AppState& state, int dim = 3) {
  requestDemo(state, dim);
  installNextOutcome(state);
  ASSERT_TRUE(state.scene) << (state.errors.empty() ? "no scene" : state.errors.front());
}

}  // namespace somicage::editor
