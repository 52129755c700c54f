#include "animation/pose_timeline.h"

#include <algorithm>
#include <cmath>

#include "base/errors.h"

namespace somicage {

const NamedPose* PoseLibrary::find(const std::string& name) const {
  for (const NamedPose& pose : poses_) {
    if (pose.name == name) return &pose;
  }
  return nullptr;
}

void PoseLibrary::store(const std::string& name, const Eigen::MatrixXd& vertices) {
  if (name.empty()) throw InputError("pose library", -1, "a pose needs a name", "type a name for the pose");
  for (NamedPose& pose : poses_) {
    if (pose.name == name) {
      pose.vertices = vertices;
      return;
    }
  }
  poses_.push_back({name, vertices});
}

void PoseLibrary::rename(const std::string& from, const std::string& to) {
  if (to.empty()) throw InputError("pose library", -1, "a pose needs a name", "type a name for the pose");
  if (from == to) return;
  if (find(to)) throw InputError("pose library", -1, "a pose named \"" + to + "\" exists already", "pick another name");
  for (NamedPose& pose : poses_) {
    if (pose.name == from) {
      pose.name = to;
      return;
    }
  }
  throw InputError("pose library", -1, "no pose named \"" + from + "\"", "pick a pose of the library");
}

void PoseLibrary::remove(const std::string& name) {
  poses_.erase(std::remove_if(poses_.begin(), poses_.end(), [&](const NamedPose& p) { return p.name == name; }),
               poses_.end());
}

std::string PoseLibrary::freshName() const {
  for (int k = 1;; ++k) {
    const std::string name = "pose " + std::to_string(k);
    if (!find(name)) return name;
  }
}

void Timeline::setKey(const Keyframe& key) {
  removeKey(key.frame);
  keys.insert(std::upper_bound(keys.begin(), keys.end(), key.frame,
                               [](double frame, const Keyframe& k) { return frame < k.frame; }),
              key);
}

void Timeline::removeKey(double frame) {
  keys.erase(std::remove_if(keys.begin(), keys.end(), [&](const Keyframe& k) { return k.frame == frame; }), keys.end());
}

namespace {

const Eigen::MatrixXd& keyPose(const Keyframe& key, const PoseLibrary& library, Eigen::Index rows, Eigen::Index cols) {
  const NamedPose* pose = library.find(key.pose);
  if (!pose) {
    throw InputError("timeline", -1,
                     "the key at frame " + std::to_string(key.frame) + " uses the pose \"" + key.pose +
                         "\", which is not in the pose library",
                     "store a pose under that name, or delete the key");
  }
  if (pose->vertices.rows() != rows || pose->vertices.cols() != cols) {
    throw InputError("timeline", -1, "the pose \"" + key.pose + "\" does not fit this cage",
                     "poses hold one position per cage vertex; store the pose again");
  }
  return pose->vertices;
}

// A key's nu or gamma: its own, else the nearest earlier key's, else the nearest later key's, else base. Keys that
// do not set a parameter so never pull it back to whatever the editor shows at the moment.
double keyValue(const std::vector<Keyframe>& keys, size_t k, std::optional<double> Keyframe::*field, double base) {
  for (size_t j = k + 1; j-- > 0;) {
    if (keys[j].*field) return *(keys[j].*field);
  }
  for (size_t j = k + 1; j < keys.size(); ++j) {
    if (keys[j].*field) return *(keys[j].*field);
  }
  return base;
}

double lerpParameter(double a, double b, double u) {
  if (std::isinf(a) || std::isinf(b)) return u < 1 ? a : b;
  return a + (b - a) * u;
}

}  // namespace

FrameState evaluateTimeline(const Timeline& timeline, const PoseLibrary& library, double frame,
                            const DeformParams& base, Eigen::Index vertexCount, Eigen::Index dim) {
  const std::vector<Keyframe>& keys = timeline.keys;
  if (keys.empty()) throw InputError("timeline", -1, "the timeline has no keys", "add a key with a pose");
  const auto pose = [&](size_t k) -> const Eigen::MatrixXd& { return keyPose(keys[k], library, vertexCount, dim); };
  FrameState state;
  state.params = base;
  // The segment [k, k+1] that holds the frame (clamped to the ends).
  const size_t n = keys.size();
  if (n == 1 || frame <= keys.front().frame || frame >= keys.back().frame) {
    const size_t k = (n == 1 || frame <= keys.front().frame) ? 0 : n - 1;
    state.cage = pose(k);
    state.params.nu = keyValue(keys, k, &Keyframe::nu, base.nu);
    state.params.gamma = keyValue(keys, k, &Keyframe::gamma, base.gamma);
    return state;
  }
  size_t k = static_cast<size_t>(std::upper_bound(keys.begin(), keys.end(), frame,
                                                  [](double f, const Keyframe& key) { return f < key.frame; }) -
                                 keys.begin()) -
             1;
  const double t0 = keys[k].frame, t1 = keys[k + 1].frame, h = t1 - t0;
  const double u = (frame - t0) / h;
  const Eigen::MatrixXd &p0 = pose(k), &p1 = pose(k + 1);
  if (timeline.interpolation == Interpolation::Linear) {
    state.cage = (1 - u) * p0 + u * p1;
  } else {
    // Tangents (per frame) at both ends of the segment: Catmull-Rom, one-sided at the first and last key.
    const Eigen::MatrixXd m0 =
        k == 0 ? Eigen::MatrixXd((p1 - p0) / h) : Eigen::MatrixXd((p1 - pose(k - 1)) / (t1 - keys[k - 1].frame));
    const Eigen::MatrixXd m1 =
        k + 2 == n ? Eigen::MatrixXd((p1 - p0) / h) : Eigen::MatrixXd((pose(k + 2) - p0) / (keys[k + 2].frame - t0));
    const double u2 = u * u, u3 = u2 * u;
    state.cage = (2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * h * m0 + (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * h * m1;
  }
  state.params.nu =
      lerpParameter(keyValue(keys, k, &Keyframe::nu, base.nu), keyValue(keys, k + 1, &Keyframe::nu, base.nu), u);
  state.params.gamma = lerpParameter(keyValue(keys, k, &Keyframe::gamma, base.gamma),
                                     keyValue(keys, k + 1, &Keyframe::gamma, base.gamma), u);
  return state;
}

double playbackFrame(const Timeline& timeline, double startFrame, double elapsedSeconds) {
  const double frame = startFrame + elapsedSeconds * timeline.fps;
  const double first = timeline.firstFrame, last = timeline.lastFrame;
  if (last <= first) return first;
  if (!timeline.loop) return std::min(frame, last);
  const double span = last - first + 1;  // frame `last` shows for one frame before the wrap
  return first + std::fmod(std::max(frame - first, 0.0), span);
}

}  // namespace somicage
