// The editor's pose library and timeline: storing, applying, renaming and deleting named poses, setting keys,
// scrubbing and playback. Every change to the library or the keys is an edit (undoable, history.h); scrubbing
// and playback show the timeline's evaluation (core/animation/pose_timeline.h) in the viewports without recording
// edits.
#pragma once

#include <optional>
#include <string>

#include "animation/pose_timeline.h"
#include "geometry/cage.h"
#include "jobs/animation_export_job.h"

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
  // The panels' text fields (timeline_panel.cpp): the name for Store current ("": the library's fresh name), the
  // pose being renamed and its new name, the Export animation dialog's path and kind (AnimationExportJob::Kind).
  std::string newPoseName, renaming, renameTo;
  std::string exportPath = "animation.glb";
  int exportKind = 0;
};

// Another scene opened: keeps the poses that fit its cage and the keys on them, drops the others. A pose fits when
// it has the cage's shape (#V by d) and, when `madeFor` (the cage the library was made on) is given, that cage has
// the new one's topology (the same faces): a 52-vertex bunny pose means nothing on another 52-vertex cage. Not an
// edit: the caller makes it part of the opened state. Returns the notice ("" when nothing was dropped).
std::string keepPosesThatFit(AnimationState& animation, const Cage& cage, const Cage* madeFor);

// Each is recorded for undo; errors (a taken name...) go to state.errors.
void storeCurrentPose(AppState& state, const std::string& name);
void applyNamedPose(AppState& state, const std::string& name);
void renameNamedPose(AppState& state, const std::string& from, const std::string& to);
void deleteNamedPose(AppState& state, const std::string& name);
// Stores the current cage as a new pose and keys it at the current frame (with nu, gamma when keyParams).
void keyCurrentPose(AppState& state);
void deleteKeyAtFrame(AppState& state);
void setInterpolation(AppState& state, Interpolation interpolation);

// Moves the cursor and shows the timeline's cage and parameters there, recording nothing (the PNG export, a new
// interpolation). False (an error reported) when the timeline cannot be evaluated; no-op without keys.
bool showTimelineFrame(AppState& state, double frame);
// Scrubbing: showTimelineFrame, not an edit. No-op without keys. A pose
// the timeline did not give (an unkeyed change: Reset pose, a drag) is replaced as an undo step named "Frame N",
// with a status line that says so.
void scrubTo(AppState& state, double frame);
// Whether the cage is the timeline's at the cursor (or there are no keys): nothing unkeyed to lose.
bool showsTimeline(const AppState& state);
void startPlayback(AppState& state, double now);
void stopPlayback(AppState& state);
// Space: plays from the cursor (the clock starts at the next tick) or stops; says so when there are no keys.
void togglePlayback(AppState& state);
// Called once per frame of the editor: advances the cursor while playing.
void tickPlayback(AppState& state, double now);

}  // namespace somicage::editor
