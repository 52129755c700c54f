// Progress of a long computation on stderr: a live percentage when stderr is a terminal, otherwise a line every
// 10% once the computation has taken more than a second (so that logs of quick runs stay clean); nothing when silent
// (--quiet: command_log.h).
#pragma once

#include <chrono>
#include <string>

#include "base/progress.h"

namespace somicage {

class ProgressReporter {
 public:
  explicit ProgressReporter(std::string label, bool silent = false);
  ~ProgressReporter();
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  // A callback for core functions; it refers to this reporter, which must outlive the computation. It returns false
  // (stop) once Ctrl-C was pressed (interrupt.h).
  ProgressCallback callback();
  // Ends the progress line, if one was started.
  void finish();

 private:
  bool report(double fraction);

  using Clock = std::chrono::steady_clock;
  std::string label_;
  bool terminal_, silent_;
  Clock::time_point start_, lastPrint_;
  int lastTenth_ = -1;
  bool printed_ = false;
  bool finished_ = false;
};

}  // namespace somicage
