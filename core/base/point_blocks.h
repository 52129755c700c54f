// The parallel loop every precompute shares: points on OpenMP threads, in blocks, with progress and cancellation
// handled on the calling thread between blocks.
#pragma once

#include <omp.h>

#include <algorithm>
#include <optional>

#include "base/errors.h"
#include "base/parallel_failure.h"
#include "base/progress.h"
#include "base/simd_pack.h"

namespace somicage {

// Calls perPoint(state, p) once for every p in [0, numPoints). Each thread makes its own state with makeState()
// (scratch buffers). Blocks hold about 2^16 (point, face) pairs, about 10 ms each: frequent enough for
// progress, rare enough that barriers do not stall a busy machine. Each point is computed on its own, so results do
// not depend on the thread count (threads = 0: the OpenMP default). Throws Cancelled when progress returns false.
// An exception from makeState or perPoint (bad_alloc, an InputError) does not leave the parallel region, which
// would end the process (parallel_failure.h): the first one is kept, the remaining points of the block are skipped,
// and it is rethrown here, on the calling thread, where the callers' catch blocks (the editor's workers) see it.
template <typename MakeState, typename PerPoint>
void forEachPointInBlocks(int numPoints, int facesPerPoint, int threads, const ProgressCallback& progress,
                          MakeState makeState, PerPoint perPoint) {
  const int blockSize = std::max(64, (1 << 16) / std::max(1, facesPerPoint));
  const int numThreads = threads > 0 ? threads : omp_get_max_threads();
  ParallelFailure failure;
  for (int blockStart = 0; blockStart < numPoints; blockStart += blockSize) {
    if (!progress(static_cast<double>(blockStart) / numPoints)) throw Cancelled();
    const int blockEnd = std::min(numPoints, blockStart + blockSize);
#pragma omp parallel num_threads(numThreads)
    {
      std::optional<decltype(makeState())> state;
      failure.run([&] { state.emplace(makeState()); });
      // Every thread reaches the loop (its barrier), failed or not; a failed run skips the remaining points.
#pragma omp for schedule(dynamic, 16)
      for (int p = blockStart; p < blockEnd; ++p) {
        if (failure.failed() || !state) continue;
        failure.run([&] { perPoint(*state, p); });
      }
    }
    failure.rethrow();
  }
  progress(1.0);
}

// forEachPointInBlocks over groups of `lanes` points: perGroup(state, first, x) with x[a * lanes + l] the coordinate a
// of point first + l, the last group repeating the last point (its extra lanes are the caller's to drop:
// first + l >= numPoints). Points is an Eigen matrix (#P by 3); lanes at most kMaxGroupLanes.
constexpr int kMaxGroupLanes = 8;
template <typename Points, typename MakeState, typename PerGroup>
void forEachPointGroup(const Points& points, int lanes, int facesPerPoint, int threads,
                       const ProgressCallback& progress, MakeState makeState, PerGroup perGroup) {
  const int numPoints = static_cast<int>(points.rows());
  forEachPointInBlocks((numPoints + lanes - 1) / lanes, facesPerPoint * lanes, threads, progress, makeState,
                       [&](auto& state, int group) {
                         const int first = group * lanes;
                         double x[3 * kMaxGroupLanes];
                         for (int l = 0; l < lanes; ++l)
                           for (int a = 0; a < 3; ++a) x[a * lanes + l] = points(std::min(first + l, numPoints - 1), a);
                         perGroup(state, first, static_cast<const double*>(x));
                       });
}

#if SOMICAGE_SIMD_PACKS
// forEachPointGroup over packs of simd::kLanes points (simd_pack.h): perPack(state, first, x) with x[a] the
// coordinate a of the pack's points.
template <typename Points, typename MakeState, typename PerPack>
void forEachPointPack(const Points& points, int facesPerPoint, int threads, const ProgressCallback& progress,
                      MakeState makeState, PerPack perPack) {
  forEachPointGroup(points, simd::kLanes, facesPerPoint, threads, progress, makeState,
                    [&](auto& state, int first, const double* coordinates) {
                      simd::Pack x[3];
                      for (int a = 0; a < 3; ++a)
                        for (int l = 0; l < simd::kLanes; ++l) x[a].v[l] = coordinates[a * simd::kLanes + l];
                      perPack(state, first, x);
                    });
}
#endif

}  // namespace somicage
