// somicage.load_session: an editor session (core/engine/session.h, the reader the editor and `somicage animate` use) as
// plain Python values, with its timeline evaluated frame by frame as the editor plays it.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace somicage {

pybind11::dict loadSessionForPython(const std::string& path);

}  // namespace somicage
