// What a precompute will allocate, how much memory is free, and a refusal with a clear message when it would not
// fit, checked before the precompute starts (a bad_alloc or the OOM killer halfway through helps nobody).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "deform/method.h"
#include "geometry/volume_mesh.h"

namespace somicage {

// `vertices` below: the vertices the method's layout has columns for (coordinate_layout.h): the cage's, or for a
// method on a volume mesh (MethodDescriptor::needsVolumeMesh) the mesh's (layoutVertices).
int layoutVertices(Method method, const Cage& cage, const VolumeMesh* mesh);

// Bytes of the coordinate matrix C (frame_evaluation.h) that makeDeformer(method, ...) stores for `points` points:
// #P rows of the method's layout (coordinate_layout.h), in float or double. Equals deformer->frameCoordinates().bytes()
// for P points. Should a deformer store extra rows for points outside the cage, this is a lower bound by those rows.
std::size_t estimateCoordinateBytes(Method method, int dim, int vertices, int cageFaces, std::size_t points,
                                    bool floatStorage);

// The peak memory of one makeDeformer() call plus one deform() output, in bytes.
struct MemoryEstimate {
  std::size_t points = 0;
  std::size_t coordinates = 0;  // C, kept for the deformer's lifetime (estimateCoordinateBytes)
  std::size_t working = 0;      // freed or small: double-precision copies made before C (Green, mean value),
                                // per-thread row buffers, the diagnostics vectors
  std::size_t output = 0;       // one deformed frame (#P by d doubles) and the kernel's row-major buffer
  std::size_t gradients = 0;    // while a J-based quantity is in use (jacobian.h): d gradient matrices of C's point
                                // rows and one frame's J and raw outputs; 0 otherwise

  std::size_t total() const { return coordinates + working + output + gradients; }
  MemoryEstimate& operator+=(const MemoryEstimate& other);  // several deformers over the same points
};

// threads: the precompute's OpenMP threads (0 = the OpenMP default), each with its own row buffer.
MemoryEstimate estimatePrecomputeMemory(Method method, int dim, int vertices, int cageFaces, std::size_t points,
                                        bool floatStorage, int threads = 0);

// What DeformationGradients (jacobian.h) adds for `points` points on top of the precompute: d times the point rows
// of C (at most d = 3 times the coordinates' bytes) plus one frame's J (#P by d^2) and raw outputs (d + 1 times
// #P by d^2 + d), in double.
std::size_t estimateGradientBytes(Method method, int dim, int vertices, int cageFaces, std::size_t points,
                                  bool floatStorage);

// The environment variable that replaces the free memory (a number of bytes), so tests can trigger a refusal.
constexpr const char* kMemoryLimitVariable = "SOMICAGE_MEMORY_LIMIT_BYTES";

// Bytes this process can still allocate: $SOMICAGE_MEMORY_LIMIT_BYTES when set; else the smaller of MemAvailable
// (/proc/meminfo) and the cgroup's headroom (memory.max - memory.current, when memory.max is a number); nullopt
// when neither is known. Throws InputError naming the variable when it is set but not a whole number.
std::optional<std::size_t> availableMemoryBytes();

// Share of the free memory a precompute may take: the rest is headroom for the system, the UI and estimation slack.
constexpr double kMemorySafetyFraction = 0.85;

// Throws InputError(source, ...) when estimate.total() exceeds kMemorySafetyFraction of `available`, e.g.
// "the coordinates of 12,000,000 points need 41.2 GB but only 22.9 GB are free", with `hint` (what to do). Does
// nothing when the free memory is unknown.
void requireMemory(const MemoryEstimate& estimate, std::optional<std::size_t> available, const std::string& source,
                   const std::string& hint);

// The usual hint: fewer points, a smaller cage, and float storage when the caller can choose it.
std::string memoryHint(bool floatStorageAvailable);

// "137 MB", "41.2 GB" (decimal units, like the bench output).
std::string formatBytes(std::size_t bytes);
// "12,000,000".
std::string formatCount(std::size_t count);

}  // namespace somicage
