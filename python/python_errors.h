// The module's exceptions and warnings, registered once by the module (module.cpp):
//   somicage::InputError -> somicage.InputError (a ValueError) with the same message as the command line, and the
//                           attributes source, line (None when not applicable), problem, hint;
//   somicage::Cancelled  -> somicage.Cancelled (a RuntimeError);
//   warnings (repairs, self-intersections, points outside the cage) -> warnings.warn(..., somicage.SomiCageWarning).
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace somicage {

void registerErrors(pybind11::module_& module);

// warnings.warn(message, somicage.SomiCageWarning); raises if the warning filter turns it into an error.
void warn(const std::string& message);

}  // namespace somicage
