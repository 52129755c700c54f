// A number or an infinity, as the editor's command line and --view specs write them (nu = +-inf is the
// incompressible limit).
#pragma once

#include <string>

namespace somicage {

// "inf", "+inf", "infinity", "-inf" or a number; throws InputError(option, ...) otherwise.
double parseNumber(const std::string& text, const std::string& option);

}  // namespace somicage
