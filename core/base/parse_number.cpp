#include "base/parse_number.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "base/errors.h"

namespace somicage {

double parseNumber(const std::string& text, const std::string& option) {
  if (text == "inf" || text == "+inf" || text == "infinity" || text == "+infinity")
    return std::numeric_limits<double>::infinity();
  if (text == "-inf" || text == "-infinity") return -std::numeric_limits<double>::infinity();
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || std::isnan(x)) {
    throw InputError(option, -1, "'" + text + "' is not a number", "write e.g. 0.3, -0.5 or inf");
  }
  return x;
}

}  // namespace somicage
