#include "pose_keys.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include "app_state.h"

namespace somicage::editor {

namespace {

// Runs an edit of the library or the keys on a copy, so that a failed edit (a taken name) changes nothing and
// records nothing.
template <typename Edit>
void editAnimation(AppState& state, const std::string& label, Edit edit) {
  AnimationState after = state.animation;
  try {
    edit(after);
  } catch (const std::exception& e) {
    state.errors.push_back(e.what());
    return;
  }
  state.animation = std::move(after);
  commitEdit(state, label);
  state.statusMessage = label;
}

}  // namespace

void storeCurrentPose(AppState& state, const std::string& name) {
  editAnimation(state, "Store pose " + name, [&](AnimationState& a) { a.poses.store(name, state.pose); });
}

void applyNamedPose(AppState& state, const std::string& name) {
  const NamedPose* pose = state.animation.poses.find(name);
  if (!pose || pose->vertices.rows() != state.pose.rows() || pose->vertices.cols() != state.pose.cols()) {
    state.errors.push_back("pose library: \"" + name + "\" does not fit the current cage");
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
    const std::string name = a.poses.freshName();
    a.poses.store(name, state.pose);
    Keyframe key;
    key.frame = frame;
    key.pose = name;
    if (a.keyParams) key.nu = state.params.nu, key.gamma = state.params.gamma;
    a.timeline.setKey(key);
  });
}

void deleteKeyAtFrame(AppState& state) {
  const double frame = std::round(state.animation.frame);
  editAnimation(state, "Delete key", [&](AnimationState& a) { a.timeline.removeKey(frame); });
}

void setInterpolation(AppState& state, Interpolation interpolation) {
  editAnimation(state, "Interpolation", [&](AnimationState& a) { a.timeline.interpolation = interpolation; });
  scrubTo(state, state.animation.frame);
}

void scrubTo(AppState& state, double frame) {
  state.animation.frame = frame;
  if (!state.scene || state.animation.timeline.keys.empty()) return;
  try {
    const FrameState at = evaluateTimeline(state.animation.timeline, state.animation.poses, frame, state.params,
                                           state.pose.rows(), state.pose.cols());
    setPose(state, at.cage);
    setParams(state, at.params);
  } catch (const std::exception& e) {
    stopPlayback(state);
    state.errors.push_back(e.what());
  }
}

void startPlayback(AppState& state, double now) {
  state.animation.playing = true;
  state.animation.playStartFrame = state.animation.frame;
  state.animation.playStartTime = now;
}

void stopPlayback(AppState& state) { state.animation.playing = false; }

void tickPlayback(AppState& state, double now) {
  if (!state.animation.playing) return;
  const Timeline& timeline = state.animation.timeline;
  const double frame = playbackFrame(timeline, state.animation.playStartFrame, now - state.animation.playStartTime);
  scrubTo(state, std::floor(frame));  // whole frames, as the export samples them
  if (!timeline.loop && frame >= timeline.lastFrame) stopPlayback(state);
}

}  // namespace somicage::editor
