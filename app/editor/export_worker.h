// File exports run on a worker thread (File > Export deformed mesh, File > Export animation as GLB or OBJ sequence),
// so that the window keeps drawing a progress bar with Cancel while the gradients are integrated, the frames
// deformed and the files written. A job takes its inputs by value (copies and shared pointers to the immutable
// scene, document and deformers), never the AppState. It writes through core's atomic writers (a temporary file or
// folder renamed into place at the end), so a Cancel (Cancelled thrown from its progress callback) or an error
// leaves nothing behind. No GL, no ImGui.
#pragma once

#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "progress.h"

namespace somicage::editor {

struct ExportOutcome {
  std::string target;  // the file or folder written (or not)
  bool cancelled = false;
  std::string error;               // non-empty on failure
  std::vector<std::string> notes;  // what the format could not carry (mesh_formats.h), on success
  std::string doneMessage;         // the status line on success
};

class ExportWorker {
 public:
  // The work: reports progress in [0, 1] (returning false means stop: throw Cancelled) and returns the notes.
  using Job = std::function<std::vector<std::string>(const ProgressCallback& progress)>;

  ExportWorker() = default;
  ~ExportWorker();  // cancels and joins
  ExportWorker(const ExportWorker&) = delete;
  ExportWorker& operator=(const ExportWorker&) = delete;

  // Starts job on the worker; false (nothing started) while another export runs.
  bool start(std::string target, std::string doneMessage, Job job);
  void cancel();  // the running job stops at its next progress report, with cancelled = true
  bool busy() const { return busy_.load(); }
  double progress() const { return progress_.load(); }
  std::string target() const;

  // The outcome of the finished job, once; empty while running or when already taken.
  std::optional<ExportOutcome> poll();
  // Blocks until the running job ends and returns its outcome (empty when nothing ran).
  std::optional<ExportOutcome> wait();

 private:
  std::thread thread_;
  std::atomic<bool> busy_{false}, cancel_{false};
  std::atomic<double> progress_{0.0};
  mutable std::mutex mutex_;
  std::optional<ExportOutcome> outcome_;
  std::string target_;
};

// Progress of one stage of a job: maps the stage's [0, 1] onto [from, to] of the whole.
ProgressCallback stageProgress(const ProgressCallback& whole, double from, double to);

}  // namespace somicage::editor
