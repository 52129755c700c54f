// The parallel loop every precompute shares: points on OpenMP threads, in blocks, with progress and cancellation
// handled on the calling thread between blocks.
#pragma once

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <optional>

#include "errors.h"
#include "progress.h"

namespace somicage {

// Calls perPoint(state, p) once for every p in [0, numPoints). Each thread makes its own state with makeState()
// (scratch buffers). Blocks hold about 2^16 (point, face) pairs, about 10 ms each: frequent enough for
// progress, rare enough that barriers do not stall a busy machine. Each point is computed on its own, so results do
// not depend on the thread count (threads = 0: the OpenMP default). Throws Cancelled when progress returns false.
// An exception from makeState or perPoint (bad_alloc, an InputError) must not leave the parallel region, which
// would end the process: the first one is kept, the remaining points of the block are skipped, and it is rethrown
// here, on the calling thread, where the callers' catch blocks (the editor's workers) see it.
template <typename MakeState, typename PerPoint>
void forEachPointInBlocks(int numPoints, int facesPerPoint, int threads, const ProgressCallback& progress,
                          MakeState makeState, PerPoint perPoint) {
  const int blockSize = std::max(64, (1 << 16) / std::max(1, facesPerPoint));
  const int numThreads = threads > 0 ? threads : omp_get_max_threads();
  std::exception_ptr failure;
  std::atomic<bool> failed{false};
  const auto keepFirst = [&] {
#pragma omp critical(somicage_point_blocks_failure)
    if (!failure) failure = std::current_exception();
    failed = true;
  };
  for (int blockStart = 0; blockStart < numPoints; blockStart += blockSize) {
    if (!progress(static_cast<double>(blockStart) / numPoints)) throw Cancelled();
    const int blockEnd = std::min(numPoints, blockStart + blockSize);
#pragma omp parallel num_threads(numThreads)
    {
      std::optional<decltype(makeState())> state;
      try {
        state.emplace(makeState());
      } catch (...) {
        keepFirst();
      }
      // Every thread reaches the loop (its barrier), failed or not; a failed run skips the remaining points.
#pragma omp for schedule(dynamic, 16)
      for (int p = blockStart; p < blockEnd; ++p) {
        if (failed.load(std::memory_order_relaxed) || !state) continue;
        try {
          perPoint(*state, p);
        } catch (...) {
          keepFirst();
        }
      }
    }
    if (failure) std::rethrow_exception(failure);
  }
  progress(1.0);
}

}  // namespace somicage
