#include "export_worker.h"

#include <exception>
#include <new>

#include "errors.h"

namespace somicage::editor {

ExportWorker::~ExportWorker() {
  cancel_ = true;
  if (thread_.joinable()) thread_.join();
}

bool ExportWorker::start(std::string target, std::string doneMessage, Job job) {
  if (busy_) return false;
  if (thread_.joinable()) thread_.join();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    outcome_.reset();
    target_ = target;
  }
  cancel_ = false;
  progress_ = 0.0;
  busy_ = true;
  thread_ =
      std::thread([this, target = std::move(target), doneMessage = std::move(doneMessage), job = std::move(job)]() {
        ExportOutcome outcome;
        outcome.target = target;
        outcome.doneMessage = doneMessage;
        const ProgressCallback progress = [this](double fraction) {
          progress_ = fraction;
          return !cancel_.load();
        };
        try {
          if (!progress(0.0)) throw Cancelled();
          outcome.notes = job(progress);
        } catch (const Cancelled&) {
          outcome.cancelled = true;
        } catch (const std::bad_alloc&) {
          outcome.error = target + ": not enough memory for the export; nothing was written";
        } catch (const std::exception& e) {
          outcome.error = e.what();
        }
        std::lock_guard<std::mutex> lock(mutex_);
        outcome_ = std::move(outcome);
        busy_ = false;
      });
  return true;
}

void ExportWorker::cancel() { cancel_ = true; }

std::string ExportWorker::target() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return target_;
}

std::optional<ExportOutcome> ExportWorker::poll() {
  if (busy_) return std::nullopt;
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<ExportOutcome> out = std::move(outcome_);
  outcome_.reset();
  return out;
}

std::optional<ExportOutcome> ExportWorker::wait() {
  if (thread_.joinable()) thread_.join();
  return poll();
}

ProgressCallback stageProgress(const ProgressCallback& whole, double from, double to) {
  return [whole, from, to](double fraction) { return whole(from + (to - from) * fraction); };
}

}  // namespace somicage::editor
