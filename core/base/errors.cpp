#include "base/errors.h"

#include <sstream>

namespace somicage {

namespace {
std::string formatInputError(const std::string& source, long line, const std::string& what, const std::string& hint) {
  std::ostringstream out;
  out << source;
  if (line >= 0) out << ":" << line;
  out << ": " << what;
  if (!hint.empty()) out << " (" << hint << ")";
  return out.str();
}
}  // namespace

InputError::InputError(std::string source, long line, std::string what, std::string hint)
    : std::runtime_error(formatInputError(source, line, what, hint)),
      source_(std::move(source)),
      line_(line),
      problem_(std::move(what)),
      hint_(std::move(hint)) {}

namespace detail {
void assertionFailed(const char* cond, const std::string& msg, const char* file, int line) {
  std::ostringstream out;
  out << "internal error at " << file << ":" << line << ": " << msg << " [" << cond << "]";
  throw std::logic_error(out.str());
}
}  // namespace detail

}  // namespace somicage
