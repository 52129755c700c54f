// The cores the editor's work shares. Every background job (job.h) holds a lease of cores while it runs, granted
// here, and runs its OpenMP regions with that many threads; the UI thread deforms its frames with the cores no job
// holds (uiThreads). So the UI's frames, a precompute and a measurement never ask for more threads than the machine
// has: the leases never sum to more than the cores, and the UI keeps at least its own thread. Thread-safe.
#pragma once

#include <atomic>
#include <condition_variable>
#include <mutex>

namespace somicage::editor {

// The cores OpenMP may use here (omp_get_num_procs: the process's CPU affinity), at least 1.
int availableCores();

// Sets the OpenMP team size of the calling thread's parallel regions (its own ICV: other threads keep theirs).
void useThreads(int threads);

class ThreadBudget {
 public:
  // What one job holds. Changed only by the budget, under its lock.
  struct Lease {
    int threads = 0;
    bool cancelled = false;  // its job was cancelled: the cores come back soon
  };

  explicit ThreadBudget(int cores);
  ThreadBudget(const ThreadBudget&) = delete;
  ThreadBudget& operator=(const ThreadBudget&) = delete;

  // The machine's budget (availableCores()), shared by every job of the process.
  static ThreadBudget& machine();

  int cores() const { return cores_; }
  // Blocks until a core is free, then takes up to `want` free cores (at least 1) into `lease` and returns how many.
  // While a cancelled job still holds cores it waits for `want` (they come back within its next progress check).
  // Returns 0, taking nothing, once `stop` is set (call wake() after setting it).
  int acquire(Lease& lease, int want, const std::atomic<bool>& stop);
  void release(Lease& lease);    // gives the lease's cores back
  void cancelled(Lease& lease);  // the lease's job was cancelled; also wakes acquire() to look at `stop` again
  int held() const;              // cores held by jobs now
  // The threads the UI thread may deform with now: the cores no job holds, and at least its own.
  int uiThreads() const;

 private:
  const int cores_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  int held_ = 0;
  int cancelledHeld_ = 0;  // of held_, by cancelled jobs
};

}  // namespace somicage::editor
