#include "jobs/thread_budget.h"

#include <omp.h>

#include <algorithm>

namespace somicage::editor {

int availableCores() { return std::max(1, omp_get_num_procs()); }

void useThreads(int threads) { omp_set_num_threads(std::max(1, threads)); }

ThreadBudget::ThreadBudget(int cores) : cores_(std::max(1, cores)) {}

ThreadBudget& ThreadBudget::machine() {
  static ThreadBudget budget(availableCores());  // the machine's cores: one budget per process
  return budget;
}

int ThreadBudget::acquire(Lease& lease, int want, const std::atomic<bool>& stop) {
  want = std::clamp(want, 1, cores_);
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] {
    const int free = cores_ - held_;
    return stop.load() || (free >= 1 && (free >= want || cancelledHeld_ == 0));
  });
  if (stop.load()) return 0;
  lease.threads = std::min(want, cores_ - held_);
  lease.cancelled = false;
  held_ += lease.threads;
  return lease.threads;
}

void ThreadBudget::release(Lease& lease) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    held_ -= lease.threads;
    if (lease.cancelled) cancelledHeld_ -= lease.threads;
    lease = Lease{};
  }
  changed_.notify_all();
}

void ThreadBudget::cancelled(Lease& lease) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (lease.threads > 0 && !lease.cancelled) {
      lease.cancelled = true;
      cancelledHeld_ += lease.threads;
    }
  }
  changed_.notify_all();
}

int ThreadBudget::held() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return held_;
}

int ThreadBudget::uiThreads() const { return std::max(1, cores_ - held()); }

}  // namespace somicage::editor
