// Small helpers shared by the commands.
#pragma once

#include <Eigen/Core>
#include <chrono>
#include <string>

#include "deformer.h"
#include "engine.h"
#include "obj_io.h"

namespace somicage {

using CliClock = std::chrono::steady_clock;

double secondsSince(CliClock::time_point start);

// "0.0123 s", "1.23 s", "12.3 s".
std::string formatSeconds(double seconds);

// %g with the given significant digits.
std::string formatNumber(double value, int digits = 6);

// Sets the OpenMP thread count for everything that follows; 0 keeps the OpenMP default.
void setThreadCount(int threads);

// Prints an engine notice (engine.h) on stderr: "somicage: note: PATH: ..." for a repair, "somicage: warning:
// PATH: ..." for a warning. The commands load through the engine facade with it.
void printNotice(const Notice& notice);

// Before a precompute: throws InputError naming meshPath when it would not fit in the free memory
// (core/memory_estimate.h); else, when it takes 1 GB or more, or 10% of the free memory or more, prints
// "COMMAND: estimated memory: X of coordinates, Y in all (Z free)" on stderr.
void requirePrecomputeMemory(const std::string& command, Method method, const Cage& cage, std::size_t points,
                             const PrecomputeOptions& options, const std::string& meshPath);

}  // namespace somicage
