// The parallel loop every precompute shares: points on OpenMP threads, in blocks, with progress and cancellation
// handled on the calling thread between blocks.
#pragma once

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <optional>

#include "base/errors.h"
#include "base/parallel_failure.h"
#include "base/progress.h"
#include "base/simd_pack.h"

namespace somicage {

// Calls perPoint(state, p) once for every p in [0, numPoints). Each thread makes its own state with makeState()
// (scratch buffers). Each point is computed on its own, so results do not depend on the thread count (threads = 0:
// the OpenMP default). One parallel region for all points: its threads meet at one barrier, at the end. (A region
// per block of points, as before, cost a barrier every few milliseconds, where on a loaded machine the threads that
// finished first spin, as OpenMP's default wait policy has them, against the one still computing: the closed-form
// precompute of 39,028 points took 0.35-0.69 s in wall time on two loaded cores, 0.17 s with one region.) The
// calling thread, which is the region's first, reports progress about every 2^16 (point, face) pairs it passes and
// throws Cancelled when progress returns false (the other threads skip their remaining points).
// An exception from makeState or perPoint (bad_alloc, an InputError) does not leave the parallel region, which
// would end the process (parallel_failure.h): the first one is kept, the remaining points are skipped, and it is
// rethrown here, on the calling thread, where the callers' catch blocks (the editor's workers) see it.
template <typename MakeState, typename PerPoint>
void forEachPointInBlocks(int numPoints, int facesPerPoint, int threads, const ProgressCallback& progress,
                          MakeState makeState, PerPoint perPoint) {
  const int reportEvery = std::max(64, (1 << 16) / std::max(1, facesPerPoint));
  const int numThreads = threads > 0 ? threads : omp_get_max_threads();
  if (!progress(0.0)) throw Cancelled();
  ParallelFailure failure;
  std::atomic<bool> cancelled{false};
#pragma omp parallel num_threads(numThreads)
  {
    std::optional<decltype(makeState())> state;
    failure.run([&] { state.emplace(makeState()); });
    const bool callingThread = omp_get_thread_num() == 0;
    int nextReport = reportEvery;
    // Every thread reaches the loop, failed or not; a failed or cancelled run skips the remaining points.
#pragma omp for schedule(dynamic, 16) nowait
    for (int p = 0; p < numPoints; ++p) {
      if (failure.failed() || cancelled.load(std::memory_order_relaxed) || !state) continue;
      failure.run([&] { perPoint(*state, p); });
      if (callingThread && p >= nextReport) {
        nextReport = p + reportEvery;
        failure.run([&] {
          if (!progress(static_cast<double>(p) / numPoints)) cancelled.store(true, std::memory_order_relaxed);
        });
      }
    }
  }
  failure.rethrow();
  if (cancelled.load()) throw Cancelled();
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
