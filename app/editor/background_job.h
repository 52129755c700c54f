// One job at a time on a worker thread, with progress, a stage text and cancellation, so that the UI keeps drawing
// while it runs (the pattern of precompute_worker.h, for any outcome type). The job receives a JobContext: its
// progress() is a core ProgressCallback (false once cancelled, so core throws Cancelled). When a job ends, its
// outcome is stored first and then the finish callback runs (on the worker thread): the editor's wakes the frame
// loop, which would otherwise sleep until the next input with the outcome untaken (docs/editor.md, "Idle"). No GL.
#pragma once

#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "progress.h"

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

 private:
  template <typename>
  friend class BackgroundJob;
  std::atomic<bool> cancel_{false};
  std::atomic<double> progress_{0.0};
  mutable std::mutex mutex_;
  std::string stage_;
};

template <typename Outcome>
class BackgroundJob {
 public:
  using Work = std::function<Outcome(JobContext&)>;

  BackgroundJob() = default;
  ~BackgroundJob() {  // cancels and joins
    context_.cancel_ = true;
    if (thread_.joinable()) thread_.join();
  }
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;

  // Called on the worker thread after each job's outcome is ready (ready() is true by then). Set it before the first
  // start(); it must be safe to call from any thread (glfwPostEmptyEvent is).
  void setOnFinished(std::function<void()> onFinished) { onFinished_ = std::move(onFinished); }

  // Cancels (and joins) a running job, drops its outcome, then runs `work` on a new thread.
  void start(Work work) {
    context_.cancel_ = true;
    if (thread_.joinable()) thread_.join();
    {
      std::lock_guard<std::mutex> lock(context_.mutex_);
      outcome_.reset();
      context_.stage_.clear();
    }
    context_.cancel_ = false;
    context_.progress_ = 0.0;
    busy_ = true;
    thread_ = std::thread([this, work = std::move(work)] {
      Outcome out = work(context_);
      {
        std::lock_guard<std::mutex> lock(context_.mutex_);
        outcome_ = std::move(out);
        busy_ = false;
      }
      if (onFinished_) onFinished_();
    });
  }
  void cancel() { context_.cancel_ = true; }  // the job sees it at its next progress report
  bool busy() const { return busy_.load(); }
  bool ready() const {  // finished with an outcome not taken yet
    std::lock_guard<std::mutex> lock(context_.mutex_);
    return !busy_ && outcome_.has_value();
  }
  double progress() const { return context_.progress_.load(); }
  std::string stage() const {
    std::lock_guard<std::mutex> lock(context_.mutex_);
    return context_.stage_;
  }
  // The outcome of the finished job, once; empty while running or when already taken.
  std::optional<Outcome> poll() {
    if (busy_) return std::nullopt;
    std::lock_guard<std::mutex> lock(context_.mutex_);
    std::optional<Outcome> out = std::move(outcome_);
    outcome_.reset();
    return out;
  }
  // Blocks until the running job finishes; its outcome stays for poll().
  void join() {
    if (thread_.joinable()) thread_.join();
  }
  // Blocks until the running job finishes and returns its outcome (empty when nothing ran or it was taken).
  std::optional<Outcome> wait() {
    join();
    return poll();
  }

 private:
  JobContext context_;
  std::function<void()> onFinished_;
  std::thread thread_;
  std::atomic<bool> busy_{false};
  std::optional<Outcome> outcome_;
};

}  // namespace somicage::editor
