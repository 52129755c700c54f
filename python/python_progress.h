// The engine's progress callback (core/base/progress.h) for a computation that runs with the GIL released: at most
// every kInterval seconds (and at the end) it takes the GIL back, runs Python's signal handlers (so Ctrl-C stops the
// computation) and calls the user's callback(fraction). The callback returning False, or raising (KeyboardInterrupt
// included), asks the engine to stop; finish() then raises that exception, or somicage.Cancelled.
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>
#include <optional>

#include "base/progress.h"

namespace somicage {

// A progress= argument: None or a callable, shown with its real type in help() and signatures.
struct ProgressArgument {
  pybind11::object callback = pybind11::none();
};

class PythonProgress {
 public:
  static constexpr double kInterval = 0.1;  // seconds between calls into Python

  explicit PythonProgress(const ProgressArgument& argument) : callback_(argument.callback) {}

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

namespace pybind11::detail {
template <>
struct type_caster<somicage::ProgressArgument> {
  PYBIND11_TYPE_CASTER(somicage::ProgressArgument, const_name("Optional[Callable[[float], Optional[bool]]]"));
  bool load(handle source, bool) {
    if (!source.is_none() && !PyCallable_Check(source.ptr())) return false;  // TypeError naming the signature
    value.callback = reinterpret_borrow<object>(source);
    return true;
  }
  static handle cast(const somicage::ProgressArgument& argument, return_value_policy, handle) {
    return argument.callback.inc_ref();
  }
};
}  // namespace pybind11::detail
