// Errors raised at input boundaries (files, command line, settings) and on cancellation.
#pragma once

#include <stdexcept>
#include <string>

namespace somicage {

// A problem with something the user gave us. The message names the source (file or option), where in it
// (line or element; -1 when not applicable), what is wrong and what to do about it.
class InputError : public std::runtime_error {
 public:
  InputError(std::string source, long line, std::string what, std::string hint);

  const std::string& source() const { return source_; }
  long line() const { return line_; }
  const std::string& problem() const { return problem_; }
  const std::string& hint() const { return hint_; }

 private:
  std::string source_;
  long line_;
  std::string problem_;
  std::string hint_;
};

// Thrown out of a long computation when its progress callback asked to stop.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled by the user") {}
};

// Internal invariant check that reports file:line; never compiled out.
#define SOMICAGE_ASSERT(cond, msg) \
  ((cond) ? (void)0 : ::somicage::detail::assertionFailed(#cond, msg, __FILE__, __LINE__))

namespace detail {
[[noreturn]] void assertionFailed(const char* cond, const std::string& msg, const char* file, int line);
}

}  // namespace somicage
