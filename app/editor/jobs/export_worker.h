// File exports run on a worker thread (File > Export deformed mesh, File > Export animation as GLB or OBJ sequence),
// so that the window keeps drawing a progress bar with Cancel while the gradients are integrated, the frames
// deformed and the files written. A job takes its inputs by value (copies and shared pointers to the immutable
// scene, document and deformers), never the AppState. It writes through core's atomic writers (a temporary file or
// folder renamed into place at the end), so a Cancel (Cancelled thrown from its progress callback) or an error
// leaves nothing behind. No GL, no ImGui.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/progress.h"
#include "jobs/background_job.h"

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

  // Starts job on the worker; false (nothing started) while another export runs: an export is never cancelled by
  // starting another one.
  bool start(std::string target, std::string doneMessage, Job job);
  void cancel() { job_.cancel(); }  // the running job stops at its next progress report, with cancelled = true
  bool busy() const { return job_.busy(); }
  // Called on the worker thread when a request has finished (background_job.h).
  void setOnFinished(std::function<void()> onFinished) { job_.setOnFinished(std::move(onFinished)); }
  double progress() const { return job_.progress(); }
  const std::string& target() const { return target_; }  // of the last export started

  // The outcome of the finished job, once; empty while running or when already taken.
  std::optional<ExportOutcome> poll() { return job_.poll(); }

 private:
  std::string target_;  // written and read by the UI thread only
  BackgroundJob<ExportOutcome> job_;
};

// Progress of one stage of a job: maps the stage's [0, 1] onto [from, to] of the whole.
ProgressCallback stageProgress(const ProgressCallback& whole, double from, double to);

}  // namespace somicage::editor
