#include "cli/command_support.h"

#include <omp.h>

#include <cstdio>
#include <iostream>

#include "memory_estimate.h"

namespace somicage {

constexpr std::size_t kBigPrecomputeBytes = 1000000000;  // 1 GB

double secondsSince(CliClock::time_point start) {
  return std::chrono::duration<double>(CliClock::now() - start).count();
}

std::string formatSeconds(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, seconds < 0.1 ? "%.4f s" : seconds < 10 ? "%.3f s" : "%.1f s", seconds);
  return text;
}

std::string formatNumber(double value, int digits) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

void setThreadCount(int threads) {
  if (threads > 0) omp_set_num_threads(threads);
}

void printNotice(const Notice& notice) {
  std::cerr << "somicage: " << (notice.kind == Notice::Kind::Repair ? "note: " : "warning: ");
  if (!notice.source.empty()) std::cerr << notice.source << ": ";
  std::cerr << notice.text << "\n";
}

void requirePrecomputeMemory(const std::string& command, Method method, const Cage& cage, std::size_t points,
                             const PrecomputeOptions& options, const std::string& meshPath) {
  // Neither command offers another storage.
  const MemoryEstimate estimate = requirePrecomputeMemory(method, cage, points, options, meshPath, memoryHint(false));
  const std::optional<std::size_t> available = availableMemoryBytes();
  // Small runs keep their one summary line; a big one says what it is about to take before it takes a while.
  const bool big = estimate.total() >= kBigPrecomputeBytes || (available && estimate.total() * 10 >= *available);
  if (big)
    std::cerr << command << ": estimated memory: " << formatBytes(estimate.coordinates) << " of coordinates, "
              << formatBytes(estimate.total()) << " in all ("
              << (available ? formatBytes(*available) + " free" : std::string("free memory unknown")) << ")\n";
}

}  // namespace somicage
