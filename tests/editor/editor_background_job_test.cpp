// The editor's job abstraction (background_job.h) and its thread budget (thread_budget.h): the UI thread never waits
// for a job, a superseded job's outcome never arrives, a finished job wakes its caller once, and the cores the jobs
// hold never add up to more than the budget's.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <optional>
#include <thread>
#include <vector>

#include "job_waiting.h"
#include "jobs/background_job.h"
#include "jobs/thread_budget.h"

namespace somicage::editor {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// A job that notices cancellation only every `checkEvery` (a slow core stage between two progress reports).
BackgroundJob<int>::Work slowToCancel(int value, double checkEvery, std::atomic<int>& started) {
  return [value, checkEvery, &started](JobContext& context) {
    ++started;
    for (;;) {
      std::this_thread::sleep_for(std::chrono::duration<double>(checkEvery));
      if (!context.report(0.5)) return -value;  // the work's own "cancelled" outcome
    }
  };
}

TEST(EditorBackgroundJob, SupersedingAJobSlowToCancelDoesNotBlockTheCaller) {
  ThreadBudget budget(2);
  BackgroundJob<int> job(budget);
  std::atomic<int> started{0};
  job.start(slowToCancel(1, 2.0, started), 1);
  waitUntil([&] { return started.load() == 1; });
  // The first job sees the cancellation only after up to 2 s; the caller must not wait for that.
  const Clock::time_point t0 = Clock::now();
  job.start([](JobContext&) { return 2; }, 1);
  const double startSeconds = secondsSince(t0);
  EXPECT_LT(startSeconds, 0.2) << "start() waited for the superseded job";
  EXPECT_TRUE(job.busy());
  const std::optional<int> out = waitForOutcome(job);
  ASSERT_TRUE(out.has_value());
  EXPECT_EQ(*out, 2) << "the superseded job's outcome arrived";
  EXPECT_FALSE(job.poll().has_value());  // once
}

TEST(EditorBackgroundJob, CancelDoesNotBlockTheCallerAndTheOutcomeSaysCancelled) {
  ThreadBudget budget(2);
  BackgroundJob<int> job(budget);
  std::atomic<int> started{0};
  job.start(slowToCancel(7, 1.0, started), 1);
  waitUntil([&] { return started.load() == 1; });
  const Clock::time_point t0 = Clock::now();
  job.cancel();
  EXPECT_LT(secondsSince(t0), 0.2);
  const std::optional<int> out = waitForOutcome(job);
  ASSERT_TRUE(out.has_value());
  EXPECT_EQ(*out, -7);
}

TEST(EditorBackgroundJob, ASupersededJobsOutcomeNeverArrivesAndDoesNotWakeTheLoop) {
  ThreadBudget budget(2);
  BackgroundJob<int> job(budget);
  std::atomic<int> wakes{0};
  job.setOnFinished([&] { ++wakes; });
  std::atomic<int> started{0};
  job.start(slowToCancel(1, 0.3, started), 1);
  waitUntil([&] { return started.load() == 1; });
  job.start([](JobContext&) { return 2; }, 1);
  waitUntil([&] { return job.ready(); });
  std::this_thread::sleep_for(std::chrono::milliseconds(400));  // the superseded job has ended by now
  EXPECT_EQ(wakes.load(), 1) << "one wake-up: the current job's";
  EXPECT_EQ(job.poll(), std::optional<int>(2));
  EXPECT_FALSE(job.poll().has_value());
}

TEST(EditorBackgroundJob, TheCoresHeldNeverExceedTheBudgetAndTheUiKeepsWhatIsLeft) {
  ThreadBudget budget(4);
  EXPECT_EQ(budget.uiThreads(), 4);
  std::atomic<bool> release{false};
  std::atomic<int> peak{0};
  const auto holder = [&](JobContext& context) {
    for (int seen = budget.held(); !release; seen = budget.held()) {
      peak = std::max(peak.load(), seen);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return context.threads();
  };
  BackgroundJob<int> a(budget), b(budget), c(budget);
  a.start(holder, 3);  // a precompute: all but the UI's core
  waitUntil([&] { return a.threads() == 3; });
  EXPECT_EQ(budget.uiThreads(), 1);
  b.start(holder, 3);  // a measurement: what is left
  waitUntil([&] { return b.threads() == 1; });
  c.start(holder, 3);  // nothing is left: it waits for cores
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(c.threads(), 0) << "a third job got cores the others hold";
  EXPECT_EQ(budget.held(), 4);
  EXPECT_EQ(budget.uiThreads(), 1);  // the UI thread itself
  release = true;
  EXPECT_EQ(waitForOutcome(a), std::optional<int>(3));
  EXPECT_EQ(waitForOutcome(b), std::optional<int>(1));
  const std::optional<int> cThreads = waitForOutcome(c);
  ASSERT_TRUE(cThreads.has_value());
  EXPECT_GE(*cThreads, 1);
  EXPECT_LE(peak.load(), 4);
  EXPECT_EQ(budget.held(), 0);
  EXPECT_EQ(budget.uiThreads(), 4);
}

// A job waiting for cores that a cancelled job still holds gets all it asked for once they come back, instead of
// starting with the one core free at that moment.
TEST(EditorBackgroundJob, ANewJobWaitsForTheCoresOfACancelledOne) {
  ThreadBudget budget(4);
  BackgroundJob<int> measure(budget), precompute(budget);
  std::atomic<int> started{0};
  measure.start(slowToCancel(1, 0.3, started), 3);
  waitUntil([&] { return measure.threads() == 3; });
  measure.cancel();
  precompute.start([](JobContext& context) { return context.threads(); }, 4);
  EXPECT_EQ(waitForOutcome(precompute), std::optional<int>(4));
  EXPECT_EQ(waitForOutcome(measure), std::optional<int>(-1));
}

// The job's OpenMP regions run with the cores granted (the thread's own team size), whatever the process default.
TEST(EditorBackgroundJob, AJobsOpenMpRegionsUseItsCores) {
  ThreadBudget budget(3);
  BackgroundJob<int> job(budget);
  job.start(
      [](JobContext&) {
        int team = 0;
#pragma omp parallel
        {
#pragma omp single
          team = omp_get_num_threads();
        }
        return team;
      },
      2);
  EXPECT_EQ(waitForOutcome(job), std::optional<int>(2));
}

TEST(EditorBackgroundJob, TheMachinesBudgetIsItsCores) {
  EXPECT_EQ(ThreadBudget::machine().cores(), availableCores());
  EXPECT_GE(availableCores(), 1);
}

}  // namespace
}  // namespace somicage::editor
