#include "deform/memory_estimate.h"

#include <omp.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "base/errors.h"

namespace somicage {

namespace {

// The first whole number in a line of /proc/meminfo or a cgroup file; nullopt when there is none.
std::optional<std::size_t> readNumber(const std::string& text) {
  const std::size_t start = text.find_first_of("0123456789");
  if (start == std::string::npos) return std::nullopt;
  return static_cast<std::size_t>(std::strtoull(text.c_str() + start, nullptr, 10));
}

std::optional<std::string> readLine(const char* path) {
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line)) return std::nullopt;
  return line;
}

std::optional<std::size_t> memAvailable() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("MemAvailable:", 0) == 0) {
      const std::optional<std::size_t> kib = readNumber(line);
      if (kib) return *kib * 1024;
    }
  }
  return std::nullopt;
}

// cgroup v2: memory.max is "max" (no limit) or a number of bytes; memory.current is what the group uses now.
std::optional<std::size_t> cgroupHeadroom() {
  const std::optional<std::string> max = readLine("/sys/fs/cgroup/memory.max");
  if (!max || max->empty() || max->find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  const std::size_t limit = *readNumber(*max);
  const std::optional<std::string> current = readLine("/sys/fs/cgroup/memory.current");
  const std::size_t used = current ? readNumber(*current).value_or(0) : 0;
  return limit > used ? limit - used : 0;
}

}  // namespace

int layoutVertices(Method method, const Cage& cage, const VolumeMesh* mesh) {
  if (!method->needsVolumeMesh) return cage.numVertices();
  SOMICAGE_ASSERT(mesh, "a volume method's mesh is made before its memory is estimated (engine.h: prepareVolumeMesh)");
  return mesh->numVertices();
}

std::size_t estimateCoordinateBytes(Method method, int dim, int vertices, int cageFaces, std::size_t points,
                                    bool floatStorage) {
  return method->layout(dim, vertices, cageFaces).bytes(points, floatStorage);
}

MemoryEstimate& MemoryEstimate::operator+=(const MemoryEstimate& other) {
  coordinates += other.coordinates;
  working = std::max(working, other.working);  // deformers are built one after the other
  output += other.output;
  gradients += other.gradients;
  return *this;
}

MemoryEstimate estimatePrecomputeMemory(Method method, int dim, int vertices, int cageFaces, std::size_t points,
                                        bool floatStorage, int threads) {
  const CoordinateLayout layout = method->layout(dim, vertices, cageFaces);
  MemoryEstimate e;
  e.points = points;
  e.coordinates = layout.bytes(points, floatStorage);
  e.working = method->workingBytes(layout, dim, points, floatStorage, threads > 0 ? threads : omp_get_max_threads());
  e.output = 2 * points * static_cast<std::size_t>(dim) * sizeof(double);
  return e;
}

std::size_t estimateGradientBytes(Method method, int dim, int vertices, int cageFaces, std::size_t points,
                                  bool floatStorage) {
  const std::size_t d = static_cast<std::size_t>(dim), outputs = d * d + d;
  const std::size_t perFrame = points * (d * d + (d + 1) * outputs) * sizeof(double) + points;  // + defined flags
  return d * estimateCoordinateBytes(method, dim, vertices, cageFaces, points, floatStorage) + perFrame;
}

std::optional<std::size_t> availableMemoryBytes() {
  if (const char* limit = std::getenv(kMemoryLimitVariable)) {
    const std::string text = limit;
    char* end = nullptr;
    errno = 0;
    const unsigned long long bytes = std::strtoull(text.c_str(), &end, 10);
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || errno == ERANGE)
      throw InputError(kMemoryLimitVariable, -1, "'" + text + "' is not a whole number of bytes",
                       "set it to e.g. 8000000000, or unset it to use the free memory of this machine");
    return static_cast<std::size_t>(bytes);
  }
  const std::optional<std::size_t> meminfo = memAvailable(), cgroup = cgroupHeadroom();
  if (meminfo && cgroup) return std::min(*meminfo, *cgroup);
  return meminfo ? meminfo : cgroup;
}

void requireMemory(const MemoryEstimate& estimate, std::optional<std::size_t> available, const std::string& source,
                   const std::string& hint) {
  if (!available || static_cast<double>(estimate.total()) <= kMemorySafetyFraction * static_cast<double>(*available))
    return;
  throw InputError(source, -1,
                   "the coordinates of " + formatCount(estimate.points) + " points need " +
                       formatBytes(estimate.total()) + " but only " + formatBytes(*available) + " are free",
                   hint);
}

std::string memoryHint(bool floatStorageAvailable) {
  return std::string("decimate the mesh to fewer points, use a smaller cage") +
         (floatStorageAvailable ? ", or store the coordinates in float" : "") + "; " + kMemoryLimitVariable +
         "=BYTES overrides the free memory";
}

std::string formatBytes(std::size_t bytes) {
  const double b = static_cast<double>(bytes);
  char text[32];
  if (b >= 1e9)
    std::snprintf(text, sizeof text, "%.1f GB", b / 1e9);
  else if (b >= 1e6)
    std::snprintf(text, sizeof text, "%.0f MB", b / 1e6);
  else if (b >= 1e3)
    std::snprintf(text, sizeof text, "%.0f kB", b / 1e3);
  else
    std::snprintf(text, sizeof text, "%zu bytes", bytes);
  return text;
}

std::string formatCount(std::size_t count) {
  std::string digits = std::to_string(count), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

}  // namespace somicage
