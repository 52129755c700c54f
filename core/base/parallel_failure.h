// An exception thrown inside an OpenMP parallel region ends the process (std::terminate), out of reach of the
// callers' catch blocks (the editor's workers catch bad_alloc and Cancelled). Every parallel region in core whose
// body can throw (an allocation, a callback) runs it through ParallelFailure: the first exception is kept, the
// remaining iterations are skipped, and it is rethrown after the region, on the calling thread.
#pragma once

#include <atomic>
#include <exception>
#include <mutex>

namespace somicage {

class ParallelFailure {
 public:
  // Runs body(); an exception it throws is kept (the first one) instead of leaving the region.
  template <typename Body>
  void run(Body&& body) noexcept {
    try {
      body();
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!failure_) failure_ = std::current_exception();
      failed_.store(true, std::memory_order_relaxed);
    }
  }
  // Whether an iteration failed: the others skip their work (each thread still reaches the loop's barrier).
  bool failed() const { return failed_.load(std::memory_order_relaxed); }
  // After the region: rethrows the kept exception, if any.
  void rethrow() const {
    if (failure_) std::rethrow_exception(failure_);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr failure_;
  std::atomic<bool> failed_{false};
};

}  // namespace somicage
