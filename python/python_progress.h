// The engine's progress callback (core/progress.h) for a computation that runs with the GIL released: at most every
// kInterval seconds (and at the end) it takes the GIL back, runs Python's signal handlers (so Ctrl-C stops the
// computation) and calls the user's callback(fraction). The callback returning False, or raising (KeyboardInterrupt
// included), asks the engine to stop; finish() then raises that exception, or somicage.Cancelled.
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>
#include <optional>

#include "progress.h"

namespace somicage {

class PythonProgress {
 public:
  static constexpr double kInterval = 0.1;  // seconds between calls into Python

  explicit PythonProgress(pybind11::object callback) : callback_(std::move(callback)) {}

  // For the engine; call it with the GIL released. Valid while this object lives.
  ProgressCallback callback();

  // With the GIL held, after the engine threw Cancelled: rethrows the exception that stopped it, if Python raised.
  void rethrowPythonError();

 private:
  bool report(double fraction);

  pybind11::object callback_;  // None: signals only
  std::chrono::steady_clock::time_point lastCall_{};
  std::optional<pybind11::error_already_set> error_;
};

}  // namespace somicage
