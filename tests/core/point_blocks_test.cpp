// The precomputes' parallel loop (core/base/point_blocks.h): every point once, and an exception thrown on an OpenMP
// thread (a point that fails, a scratch buffer that cannot be allocated) reaches the caller as that exception,
// instead of ending the process (std::terminate, which an exception leaving a parallel region calls).
#include "base/point_blocks.h"

#include <gtest/gtest.h>

#include <atomic>
#include <new>
#include <vector>

#include "base/errors.h"
#include "base/parallel_failure.h"

namespace somicage {
namespace {

const ProgressCallback kNoProgress = [](double) { return true; };

TEST(PointBlocks, VisitsEveryPointOnce) {
  const int n = 20000;
  std::vector<std::atomic<int>> visits(n);
  forEachPointInBlocks(
      n, 100, 2, kNoProgress, [] { return 0; }, [&](int&, int p) { ++visits[static_cast<std::size_t>(p)]; });
  for (int p = 0; p < n; ++p) ASSERT_EQ(visits[static_cast<std::size_t>(p)].load(), 1) << "point " << p;
}

TEST(PointBlocks, AnExceptionOfOnePointReachesTheCaller) {
  // On two threads, which points run before and after the failure depends on the schedule (a descheduled thread may
  // hold point 1500 while the other computes the rest), so only the exception itself is asserted there. On one
  // thread the order is fixed: points 0..1500 run, and none after the one that threw.
  for (const int threads : {2, 1}) {
    std::atomic<int> visited{0};
    try {
      forEachPointInBlocks(
          5000, 100, threads, kNoProgress, [] { return 0; },
          [&](int&, int p) {
            ++visited;
            if (p == 1500) throw InputError("point 1500", -1, "cannot be computed", "none");
          });
      FAIL() << "no exception on " << threads << " threads";
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "point 1500");
    }
    if (threads == 1) {
      EXPECT_EQ(visited.load(), 1501);
    }
  }
}

TEST(PointBlocks, AScratchBufferThatCannotBeMadeIsBadAlloc) {
  std::atomic<int> made{0};
  // 1000 faces per point: blocks of 65 points, so the second scratch buffer is made whatever the thread count.
  EXPECT_THROW(forEachPointInBlocks(
                   1000, 1000, 2, kNoProgress,
                   [&] {
                     if (++made == 2) throw std::bad_alloc();
                     return 0;
                   },
                   [](int&, int) {}),
               std::bad_alloc);
}

TEST(ParallelFailure, AnExceptionInAnOpenMpLoopIsRethrownAfterTheRegion) {
  // The guard the other parallel regions of core use (exterior points, the CUDA rows' sink): iteration 700 of 2000
  // throws bad_alloc on whichever thread runs it; the loop ends, the others skip their work once it is seen, and the
  // caller catches bad_alloc after the region (without the guard: std::terminate).
  ParallelFailure failure;
  std::atomic<int> ran{0};
#pragma omp parallel for schedule(static, 1) num_threads(2)
  for (int i = 0; i < 2000; ++i) {
    if (failure.failed()) continue;
    failure.run([&] {
      ++ran;
      if (i == 700) throw std::bad_alloc();
    });
  }
  EXPECT_TRUE(failure.failed());
  EXPECT_THROW(failure.rethrow(), std::bad_alloc);
  EXPECT_GE(ran.load(), 1);
  EXPECT_LT(ran.load(), 2000);  // it stopped early
  ParallelFailure clean;
  clean.run([] {});
  EXPECT_FALSE(clean.failed());
  EXPECT_NO_THROW(clean.rethrow());
}

}  // namespace
}  // namespace somicage
