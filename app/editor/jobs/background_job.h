// The editor's one job abstraction: work on a worker thread, with progress, a stage text, cancellation and a lease
// of cores (thread_budget.h), so that the UI keeps drawing while it runs. Every background worker of the editor (the
// precompute, the measurement and the nu sweep, Make cage's generation, the exports) is a BackgroundJob, and
// startJobThread is the only place the editor starts a thread.
//
// The UI thread never waits for a job: start() supersedes the running job (cancelled; its outcome never arrives)
// and returns at once; the new job's thread first joins the superseded one's (which stops at its next progress
// check and gives its cores back), then takes its cores from the budget and runs. There is no call that waits for
// a job's end: the frame loop polls (busy, poll), scripted screenshots too (editor.cpp); only the destructor (at
// exit) joins, and tests wait by polling (tests/editor/job_waiting.h). When a job ends, its outcome is stored first
// and then the finish callback runs on the job's thread: the editor's wakes the frame loop, which would otherwise
// sleep until the next input with the outcome untaken (docs/editor.md, "Idle and the redraw rule"). No GL.
#pragma once

#include <algorithm>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "base/progress.h"
#include "jobs/thread_budget.h"

namespace somicage::editor {

class JobContext {
 public:
  // Sets the fraction done (0..1); returns false once the job was cancelled.
  bool report(double fraction) {
    progress_ = fraction;
    return !cancel_.load();
  }
  // The fraction [from, to] of the whole job as a core ProgressCallback.
  ProgressCallback span(double from, double to) {
    return [this, from, to](double f) { return report(from + (to - from) * f); };
  }
  bool cancelled() const { return cancel_.load(); }
  void setStage(std::string stage) {
    std::lock_guard<std::mutex> lock(mutex_);
    stage_ = std::move(stage);
  }
  // The cores granted to this job: its OpenMP regions run with this many threads (core's `threads = 0`).
  int threads() const { return threads_.load(); }

 private:
  template <typename>
  friend class BackgroundJob;
  std::atomic<bool> cancel_{false};
  std::atomic<double> progress_{0.0};
  std::atomic<int> threads_{0};  // 0 while waiting for cores
  mutable std::mutex mutex_;
  std::string stage_;
};

// Starts `body` on a new thread: the only place the editor starts threads.
std::thread startJobThread(std::function<void()> body);

template <typename Outcome>
class BackgroundJob {
 public:
  using Work = std::function<Outcome(JobContext&)>;

  explicit BackgroundJob(ThreadBudget& budget = ThreadBudget::machine()) : budget_(&budget) {}
  ~BackgroundJob() {  // cancels, then waits for the threads (the running job's and those it joins)
    cancel();
    if (thread_.joinable()) thread_.join();
  }
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;

  // Called on the job's thread after each job's outcome is ready (ready() is true by then), not for a superseded
  // job. Set it before the first start(); it must be safe to call from any thread (glfwPostEmptyEvent is).
  void setOnFinished(std::function<void()> onFinished) {
    onFinished_ = std::make_shared<const std::function<void()>>(std::move(onFinished));
  }

  // Supersedes the running job (cancelled, its outcome dropped) without waiting for it, then runs `work` on a new
  // thread with up to `threads` cores of the budget (at least 1; it waits there while none is free). The work
  // should check context.cancelled() before anything slow: a job superseded while it waited still runs it.
  void start(Work work, int threads) {
    supersede();
    cancel();
    auto run = std::make_shared<Run>();
    run_ = run;
    auto previous = std::make_shared<std::thread>(std::move(thread_));  // shared: a std::function is copyable
    thread_ = startJobThread(
        [run, work = std::move(work), budget = budget_, threads, onFinished = onFinished_, previous]() mutable {
          if (previous->joinable()) previous->join();  // a superseded job: it ends at its next progress check
          run->context.threads_ = std::max(1, budget->acquire(run->lease, threads, run->context.cancel_));
          useThreads(run->context.threads_);
          std::optional<Outcome> out = work(run->context);
          budget->release(run->lease);
          bool current;
          {
            std::lock_guard<std::mutex> lock(run->mutex);
            current = !run->superseded;
            if (current) run->outcome = std::move(out);
            run->finished = true;
          }
          if (current && onFinished && *onFinished) (*onFinished)();
        });
  }
  // Asks the running job to stop at its next progress report; its outcome (the work's own "cancelled" one) arrives.
  void cancel() {
    if (!run_) return;
    run_->context.cancel_ = true;
    budget_->cancelled(run_->lease);
  }
  // Cancels the running job and drops its outcome, stored or still to come: nothing of it arrives, as when superseded
  // (a scene load the user cancelled after its scene had loaded: PrecomputeWorker::discard).
  void discard() {
    if (!run_) return;
    {
      std::lock_guard<std::mutex> lock(run_->mutex);
      run_->superseded = true;
      run_->outcome.reset();
    }
    cancel();
  }
  bool busy() const {
    if (!run_) return false;
    std::lock_guard<std::mutex> lock(run_->mutex);
    return !run_->finished;
  }
  bool ready() const {  // finished with an outcome not taken yet
    if (!run_) return false;
    std::lock_guard<std::mutex> lock(run_->mutex);
    return run_->finished && run_->outcome.has_value();
  }
  double progress() const { return run_ ? run_->context.progress_.load() : 0.0; }
  std::string stage() const {
    if (!run_) return {};
    std::lock_guard<std::mutex> lock(run_->context.mutex_);
    return run_->context.stage_;
  }
  int threads() const { return run_ ? run_->context.threads() : 0; }  // the running job's cores (0: waiting)
  int cores() const { return budget_->cores(); }                      // the budget's
  // The outcome of the finished job, once; empty while running or when already taken.
  std::optional<Outcome> poll() {
    if (!run_) return std::nullopt;
    std::lock_guard<std::mutex> lock(run_->mutex);
    if (!run_->finished) return std::nullopt;
    return std::exchange(run_->outcome, std::nullopt);
  }

 private:
  // One started job, shared by its thread and (until superseded) the BackgroundJob.
  struct Run {
    JobContext context;
    ThreadBudget::Lease lease;
    std::mutex mutex;
    bool finished = false;  // the outcome is stored
    bool superseded = false;
    std::optional<Outcome> outcome;
  };
  void supersede() {
    if (!run_) return;
    std::lock_guard<std::mutex> lock(run_->mutex);
    run_->superseded = true;
  }

  ThreadBudget* budget_;
  std::shared_ptr<const std::function<void()>> onFinished_;
  std::shared_ptr<Run> run_;
  std::thread thread_;  // the latest job's; it joins the one before
};

}  // namespace somicage::editor
