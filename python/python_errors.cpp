#include "python_errors.h"

#include "base/errors.h"

namespace py = pybind11;

namespace somicage {

namespace {
// Created once at import and kept for the interpreter's lifetime (pybind11 registers its own exceptions the same way).
PyObject* inputErrorType = nullptr;
PyObject* cancelledType = nullptr;
PyObject* warningType = nullptr;

PyObject* newType(py::module_& module, const char* name, PyObject* base, const char* doc) {
  const std::string qualified = std::string("somicage.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, base, nullptr);
  if (!type) throw py::error_already_set();
  module.add_object(name, py::handle(type));  // the module owns a reference; ours is the type's own
  return type;
}
}  // namespace

void registerErrors(py::module_& module) {
  inputErrorType = newType(module, "InputError", PyExc_ValueError,
                           "Bad input: the message names the source (file or argument), where in it, what is wrong "
                           "and what to do. Attributes: source, line (None when not applicable), problem, hint.");
  cancelledType = newType(module, "Cancelled", PyExc_RuntimeError,
                          "A long computation stopped because its progress callback returned False.");
  warningType = newType(module, "SomiCageWarning", PyExc_UserWarning,
                        "Something that makes a deformation poor without making it impossible, or a repair done.");
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const InputError& e) {
      py::object error = py::reinterpret_borrow<py::object>(inputErrorType)(e.what());
      error.attr("source") = e.source();
      error.attr("line") = e.line() >= 0 ? py::object(py::int_(e.line())) : py::object(py::none());
      error.attr("problem") = e.problem();
      error.attr("hint") = e.hint();
      PyErr_SetObject(inputErrorType, error.ptr());
    } catch (const Cancelled& e) {
      PyErr_SetString(cancelledType, e.what());
    }
  });
}

void warn(const std::string& message) {
  if (PyErr_WarnEx(warningType, message.c_str(), 1) != 0) throw py::error_already_set();
}

}  // namespace somicage
