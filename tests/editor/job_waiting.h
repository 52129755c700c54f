// Waiting for the editor's jobs, for tests only. The editor itself never waits for a job (background_job.h): its
// frame loop, scripted screenshots included, polls them as their wake-ups arrive. A test that needs a job's end
// polls too, here.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <thread>

namespace somicage::editor {

// Polls `done` every millisecond for up to 60 s; fails the test when it never holds. Returns whether it held.
inline bool waitUntil(const std::function<bool()>& done) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline) {
      ADD_FAILURE() << "not within 60 s";
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

// Until the job (a BackgroundJob or a worker over one) has ended: its outcome is then there for poll(). Its finish
// callback runs on its thread right after; a test counting wake-ups waits for the count.
template <typename Job>
void waitUntilDone(const Job& job) {
  waitUntil([&job] { return !job.busy(); });
}

// Waits for the job to end and takes its outcome (empty when nothing ran or it was taken).
template <typename Job>
auto waitForOutcome(Job& job) {
  waitUntilDone(job);
  return job.poll();
}

// Waits for the job to end, then has its owner take the result (CageMaker::poll).
template <typename Owner>
void waitThenPoll(Owner& owner) {
  waitUntilDone(owner);
  owner.poll();
}

}  // namespace somicage::editor
