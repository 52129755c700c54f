// Progress reporting for long computations.
#pragma once

#include <functional>

namespace somicage {

// Called with the fraction done in [0, 1]; returns false to ask the computation to stop, which then throws
// somicage::Cancelled. Callbacks are invoked from the calling thread only, never from OpenMP workers.
using ProgressCallback = std::function<bool(double fractionDone)>;

inline bool noProgress(double) { return true; }

}  // namespace somicage
