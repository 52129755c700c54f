#include "python_progress.h"

namespace py = pybind11;

namespace somicage {

ProgressCallback PythonProgress::callback() {
  return [this](double fraction) { return report(fraction); };
}

bool PythonProgress::report(double fraction) {
  const auto now = std::chrono::steady_clock::now();
  if (fraction < 1 && std::chrono::duration<double>(now - lastCall_).count() < kInterval) return true;
  lastCall_ = now;
  py::gil_scoped_acquire gil;
  try {
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (callback_.is_none()) return true;
    const py::object answer = callback_(fraction);
    if (answer.is_none()) return true;  // a callback that only prints
    const int keepGoing = PyObject_IsTrue(answer.ptr());
    if (keepGoing < 0) throw py::error_already_set();
    return keepGoing != 0;
  } catch (py::error_already_set& error) {
    error_ = std::move(error);
    return false;
  }
}

void PythonProgress::rethrowPythonError() {
  if (!error_) return;
  py::error_already_set error = std::move(*error_);
  error_.reset();
  throw error;
}

}  // namespace somicage
