#include "cli/progress_reporter.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "cli/interrupt.h"

namespace somicage {

ProgressReporter::ProgressReporter(std::string label, bool silent)
    : label_(std::move(label)),
      terminal_(::isatty(STDERR_FILENO) == 1),
      silent_(silent),
      start_(Clock::now()),
      lastPrint_(start_) {}

ProgressReporter::~ProgressReporter() { finish(); }

ProgressCallback ProgressReporter::callback() {
  return [this](double fraction) { return report(fraction); };
}

bool ProgressReporter::report(double fraction) {
  if (interruptRequested()) return false;  // Ctrl-C: the computation throws Cancelled (interrupt.h)
  if (finished_ || silent_ || !std::isfinite(fraction)) return true;
  const Clock::time_point now = Clock::now();
  const double percent = 100.0 * std::min(1.0, std::max(0.0, fraction));
  if (terminal_) {
    if (printed_ && now - lastPrint_ < std::chrono::milliseconds(100)) return true;
    std::fprintf(stderr, "\r%s: %3.0f%%", label_.c_str(), percent);
    std::fflush(stderr);
    printed_ = true;
    lastPrint_ = now;
    return true;
  }
  const int tenth = static_cast<int>(percent / 10.0);
  if (now - start_ < std::chrono::seconds(1) || tenth <= lastTenth_) return true;
  std::fprintf(stderr, "%s: %d%%\n", label_.c_str(), 10 * tenth);
  std::fflush(stderr);
  printed_ = true;
  lastTenth_ = tenth;
  return true;
}

void ProgressReporter::finish() {
  if (finished_) return;
  finished_ = true;
  if (!printed_) return;
  if (terminal_) {
    std::fprintf(stderr, "\r%s: 100%%\n", label_.c_str());
  } else if (lastTenth_ < 10) {
    std::fprintf(stderr, "%s: 100%%\n", label_.c_str());
  }
  std::fflush(stderr);
}

}  // namespace somicage
