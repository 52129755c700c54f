#include "jobs/animation_export_job.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <system_error>
#include <utility>

#include "animation/pose_timeline.h"
#include "base/errors.h"
#include "gl_context.h"
#include "jobs/export_jobs.h"
#include "jobs/export_worker.h"
#include "model/app_state.h"
#include "model/pose_keys.h"
#include "ui/screenshot.h"

namespace somicage::editor {

namespace {

namespace fs = std::filesystem;

void finish(AppState& state, const std::string& message) {
  AnimationExportJob& job = *state.animation.exportJob;
  if (!job.pngFolder.empty()) {
    std::error_code ignored;
    fs::remove_all(job.pngFolder, ignored);  // still there: cancelled or failed
  }
  setPose(state, job.savedPose);
  setParams(state, job.savedParams);
  state.animation.frame = job.savedFrame;
  state.animation.exportJob.reset();
  state.status.message = message;
}

void moveImagesIntoPlace(const AnimationExportJob& job) {
  fs::path target(job.out);
  if (target.filename().empty()) target = target.parent_path();
  std::error_code error;
  if (fs::exists(target, error)) fs::remove(target, error);  // empty: checked at the start
  fs::rename(job.pngFolder, target, error);
  if (error)
    throw InputError(job.out, -1, "cannot move the images into place: " + error.message(), "check the permissions");
}

}  // namespace

void startAnimationExport(AppState& state, AnimationExportJob::Kind kind, const std::string& out) {
  const Timeline& timeline = state.animation.timeline;
  if (!state.model.scene || !state.model.scene->document) {
    state.status.errors.push_back(
        "Export animation: open a mesh file first (the built-in demos have no file to export)");
    return;
  }
  if (timeline.keys.empty()) {
    state.status.errors.push_back("Export animation: the timeline has no keys (Timeline panel: Key pose)");
    return;
  }
  if (kind != AnimationExportJob::Kind::PngSequence) {
    if (ExportWorker::Job job = makeAnimationExportJob(state, kind, out)) {
      state.jobs.exporter.start(out,
                                "exported the animation (" +
                                    std::to_string(timeline.lastFrame - timeline.firstFrame + 1) + " frames) to " + out,
                                std::move(job));
      state.status.message = "exporting the animation to " + out;
    }
    return;
  }
  AnimationExportJob job;
  job.out = out;
  job.first = job.next = timeline.firstFrame;
  job.last = timeline.lastFrame;
  job.savedPose = state.document.pose;
  job.savedParams = state.document.params;
  job.savedFrame = state.animation.frame;
  fs::path target(out);
  if (target.filename().empty()) target = target.parent_path();
  std::error_code error;
  if (fs::exists(target, error) && (!fs::is_directory(target, error) || !fs::is_empty(target, error))) {
    state.status.errors.push_back(out + ": exists and is not an empty folder; give a new folder for the images");
    return;
  }
  const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::string pattern = (parent / (target.filename().string() + ".tmp-XXXXXX")).string();
  if (!::mkdtemp(pattern.data())) {
    state.status.errors.push_back(out + ": cannot create a folder next to it");
    return;
  }
  job.pngFolder = pattern;
  stopPlayback(state);
  state.animation.exportJob = std::move(job);
}

void showNextExportFrame(AppState& state) {
  if (!state.animation.exportJob) return;
  AnimationExportJob& job = *state.animation.exportJob;
  if (job.cancelRequested) {
    finish(state, "animation export cancelled; nothing was written");
    return;
  }
  showTimelineFrame(state, job.next);
}

void captureExportFrame(AppState& state, int framebufferWidth, int framebufferHeight) {
  if (!state.animation.exportJob) return;
  AnimationExportJob& job = *state.animation.exportJob;
  try {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", job.next);
    writePng((fs::path(job.pngFolder) / name).string(), framebufferWidth, framebufferHeight,
             render::readPixelsRgba(framebufferWidth, framebufferHeight));
    if (++job.next <= job.last) return;
    moveImagesIntoPlace(job);
    job.pngFolder.clear();
    finish(state, "exported the animation (" + std::to_string(job.last - job.first + 1) + " frames) to " + job.out);
  } catch (const std::exception& e) {
    state.status.errors.push_back(e.what());
    finish(state, "animation export failed; nothing was written");
  }
}

}  // namespace somicage::editor
