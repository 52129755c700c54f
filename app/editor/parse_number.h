// The editor's numbers on the command line and in --view specs: a number or an infinity (nu = +-inf is the
// incompressible limit). Its own file so that the session reader (and its fuzz target) needs nothing else of the
// editor's options. No GL.
#pragma once

#include <string>

namespace somicage::editor {

// "inf", "+inf", "infinity", "-inf" or a number; throws InputError(option, ...) otherwise.
double parseNumber(const std::string& text, const std::string& option);

}  // namespace somicage::editor
