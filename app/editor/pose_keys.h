// The editor's pose library and timeline: storing, applying, renaming and deleting named poses, setting keys,
// scrubbing and playback. Every change to the library or the keys is an edit (undoable, history.h); scrubbing
// and playback show the timeline's evaluation (core/pose_timeline.h) in the viewports without recording edits.
#pragma once

#include <optional>
#include <string>

#include "animation_export_job.h"
#include "pose_timeline.h"

namespace somicage::editor {

struct AppState;

struct AnimationState {
  PoseLibrary poses;
  Timeline timeline;
  double frame = 0;  // the frame under the timeline's cursor
  bool playing = false;
  double playStartFrame = 0;  // where playback started, and when (seconds on the frame loop's clock)
  double playStartTime = 0;
  bool keyParams = false;                       // new keys hold the current nu and gamma
  std::optional<AnimationExportJob> exportJob;  // File > Export animation in progress
  bool showPanels = false;             // the Timeline band and the Pose library (View menu; on when a session has keys)
  bool exportDialogRequested = false;  // set by the File menu, opened by the timeline panel's code
};

// Each is recorded for undo; errors (a taken name...) go to state.errors.
void storeCurrentPose(AppState& state, const std::string& name);
void applyNamedPose(AppState& state, const std::string& name);
void renameNamedPose(AppState& state, const std::string& from, const std::string& to);
void deleteNamedPose(AppState& state, const std::string& name);
// Stores the current cage as a new pose and keys it at the current frame (with nu, gamma when keyParams).
void keyCurrentPose(AppState& state);
void deleteKeyAtFrame(AppState& state);
void setInterpolation(AppState& state, Interpolation interpolation);

// Moves the cursor and shows the timeline's cage and parameters there (not an edit). No-op without keys.
void scrubTo(AppState& state, double frame);
void startPlayback(AppState& state, double now);
void stopPlayback(AppState& state);
// Called once per frame of the editor: advances the cursor while playing.
void tickPlayback(AppState& state, double now);

}  // namespace somicage::editor
