#include "model/pose_keys.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <exception>
#include <utility>
#include <vector>

#include "model/app_state.h"

namespace somicage::editor {

namespace {

// Playback started by a key, without the frame loop's clock: tickPlayback starts it at its next call.
constexpr double kStartAtNextTick = -1.0;

// Runs an edit of the library or the keys on a copy, so that a failed edit (a taken name) changes nothing and
// records nothing.
template <typename Edit>
void editAnimation(AppState& state, const std::string& label, Edit edit) {
  AnimationState after = state.animation;
  try {
    edit(after);
  } catch (const std::exception& e) {
    state.status.errors.push_back(e.what());
    return;
  }
  state.animation = std::move(after);
  commitEdit(state, label);
  state.status.message = label;
}

bool samePose(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() && a == b;
}

bool sameTopology(const Cage& a, const Cage& b) {
  return a.numVertices() == b.numVertices() && a.faces.rows() == b.faces.rows() && a.faces.cols() == b.faces.cols() &&
         a.faces == b.faces;
}

}  // namespace

std::string keepPosesThatFit(AnimationState& animation, const Cage& cage, const Cage* madeFor) {
  const bool fits = !madeFor || sameTopology(*madeFor, cage);
  PoseLibrary kept;
  std::size_t droppedPoses = 0;
  for (const NamedPose& pose : animation.poses.poses()) {
    if (fits && pose.vertices.rows() == cage.vertices.rows() && pose.vertices.cols() == cage.vertices.cols()) {
      kept.store(pose.name, pose.vertices);
    } else {
      ++droppedPoses;
    }
  }
  std::vector<Keyframe>& keys = animation.timeline.keys;
  const std::size_t keyCount = keys.size();
  keys.erase(std::remove_if(keys.begin(), keys.end(), [&](const Keyframe& k) { return !kept.find(k.pose); }),
             keys.end());
  const std::size_t droppedKeys = keyCount - keys.size();
  animation.poses = std::move(kept);
  animation.newPoseName.clear();
  animation.renaming.clear();
  if (keys.empty()) {
    animation.playing = false;
    animation.frame = animation.timeline.firstFrame;
  }
  if (droppedPoses == 0 && droppedKeys == 0) return "";
  const auto count = [](std::size_t n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
  };
  return "dropped " + count(droppedPoses, "pose") + " and " + count(droppedKeys, "key") +
         " of the pose library that do not fit this cage (" + std::to_string(cage.numVertices()) + " vertices" +
         (fits ? "" : ", another topology") + ")";
}

void storeCurrentPose(AppState& state, const std::string& name) {
  editAnimation(state, "Store pose " + name, [&](AnimationState& a) { a.poses.store(name, state.document.pose); });
}

void applyNamedPose(AppState& state, const std::string& name) {
  const NamedPose* pose = state.animation.poses.find(name);
  if (!pose || pose->vertices.rows() != state.document.pose.rows() ||
      pose->vertices.cols() != state.document.pose.cols()) {
    state.status.errors.push_back("pose library: \"" + name + "\" does not fit the current cage");
    return;
  }
  setPose(state, pose->vertices);
  commitEdit(state, "Apply pose " + name);
}

void renameNamedPose(AppState& state, const std::string& from, const std::string& to) {
  editAnimation(state, "Rename pose " + from, [&](AnimationState& a) {
    a.poses.rename(from, to);
    for (Keyframe& key : a.timeline.keys) {
      if (key.pose == from) key.pose = to;
    }
  });
}

void deleteNamedPose(AppState& state, const std::string& name) {
  editAnimation(state, "Delete pose " + name, [&](AnimationState& a) {
    a.poses.remove(name);
    std::vector<Keyframe>& keys = a.timeline.keys;
    keys.erase(std::remove_if(keys.begin(), keys.end(), [&](const Keyframe& k) { return k.pose == name; }), keys.end());
  });
}

void keyCurrentPose(AppState& state) {
  const double frame = std::round(state.animation.frame);
  editAnimation(state, "Key frame " + std::to_string(static_cast<int>(frame)), [&](AnimationState& a) {
    // A pose the library holds already is keyed by its name: keying one cage at several frames adds one pose.
    std::string name;
    for (const NamedPose& pose : a.poses.poses())
      if (name.empty() && samePose(pose.vertices, state.document.pose)) name = pose.name;
    if (name.empty()) {
      name = a.poses.freshName();
      a.poses.store(name, state.document.pose);
    }
    Keyframe key;
    key.frame = frame;
    key.pose = name;
    if (a.keyParams) key.nu = state.document.params.nu, key.gamma = state.document.params.gamma;
    a.timeline.setKey(key);
  });
}

void deleteKeyAtFrame(AppState& state) {
  const double frame = std::round(state.animation.frame);
  editAnimation(state, "Delete key", [&](AnimationState& a) { a.timeline.removeKey(frame); });
}

void setInterpolation(AppState& state, Interpolation interpolation) {
  const bool shown = showsTimeline(state);
  state.animation.timeline.interpolation = interpolation;
  if (shown) showTimelineFrame(state, state.animation.frame);  // the new curve's cage, in the same step
  commitEdit(state, "Interpolation");
  state.status.message = "Interpolation";
}

bool showTimelineFrame(AppState& state, double frame) {
  AnimationState& a = state.animation;
  a.frame = frame;
  if (!state.model.scene || a.timeline.keys.empty()) return false;
  try {
    const FrameState at = evaluateTimeline(a.timeline, a.poses, frame, state.document.params,
                                           state.document.pose.rows(), state.document.pose.cols());
    setPose(state, at.cage);
    setParams(state, at.params);
    return true;
  } catch (const std::exception& e) {
    stopPlayback(state);
    state.status.errors.push_back(e.what());
    return false;
  }
}

void scrubTo(AppState& state, double frame) {
  // A pose the timeline does not give at the cursor (Reset pose, a drag, Apply) is replaced, as in Blender, but as
  // an undo step that says so: Ctrl+Z brings it back.
  const bool unkeyed = !showsTimeline(state);
  if (!showTimelineFrame(state, frame) || !unkeyed) return;
  const std::string step = "Frame " + std::to_string(static_cast<int>(std::lround(frame)));
  commitEdit(state, step);
  state.status.message =
      step + ": the unkeyed pose was replaced by the timeline's (Ctrl+Z brings it back; Key pose keeps a pose)";
}

bool showsTimeline(const AppState& state) {
  const AnimationState& a = state.animation;
  if (!state.model.scene || a.timeline.keys.empty()) return true;
  try {
    return samePose(evaluateTimeline(a.timeline, a.poses, a.frame, state.document.params, state.document.pose.rows(),
                                     state.document.pose.cols())
                        .cage,
                    state.document.pose);
  } catch (const std::exception&) {
    return true;  // a timeline that cannot be evaluated replaces nothing (scrubTo reports it)
  }
}

void startPlayback(AppState& state, double now) {
  state.animation.playing = true;
  state.animation.playStartFrame = state.animation.frame;
  state.animation.playStartTime = now;
}

void stopPlayback(AppState& state) { state.animation.playing = false; }

void togglePlayback(AppState& state) {
  if (state.animation.playing) {
    stopPlayback(state);
  } else if (state.animation.timeline.keys.empty()) {
    state.status.message = "nothing to play: key a pose first (Timeline: Key pose)";
  } else {
    startPlayback(state, kStartAtNextTick);
  }
}

void tickPlayback(AppState& state, double now) {
  if (!state.animation.playing) return;
  if (state.animation.playStartTime == kStartAtNextTick) state.animation.playStartTime = now;
  const Timeline& timeline = state.animation.timeline;
  const double frame = playbackFrame(timeline, state.animation.playStartFrame, now - state.animation.playStartTime);
  scrubTo(state, std::floor(frame));  // whole frames, as the export samples them
  if (!timeline.loop && frame >= timeline.lastFrame) stopPlayback(state);
}

}  // namespace somicage::editor
