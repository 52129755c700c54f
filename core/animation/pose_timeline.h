// Poses and keyframes: a library of named cage poses and a timeline of keys that hold a pose and, optionally,
// the Somigliana parameters nu and gamma. Evaluating the timeline at a (fractional) frame gives the cage and the
// parameters of that frame. Pure data and math; the session file stores both (pose_timeline_json.h).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "deform/deform_params.h"

namespace somicage {

struct NamedPose {
  std::string name;
  Eigen::MatrixXd vertices;  // #V by d posed cage vertices
};

// Named poses in the order they were stored. Names are unique and not empty.
class PoseLibrary {
 public:
  const std::vector<NamedPose>& poses() const { return poses_; }
  const NamedPose* find(const std::string& name) const;
  // Stores (or replaces) a pose under name. Throws InputError for an empty name.
  void store(const std::string& name, const Eigen::MatrixXd& vertices);
  // Throws InputError when `from` is missing or `to` is empty or taken by another pose.
  void rename(const std::string& from, const std::string& to);
  void remove(const std::string& name);  // no-op when missing
  // "pose 1", "pose 2", ...: the first name not taken.
  std::string freshName() const;

 private:
  std::vector<NamedPose> poses_;
};

struct Keyframe {
  double frame = 0;                 // where the key sits on the timeline
  std::string pose;                 // a name in the PoseLibrary
  std::optional<double> nu, gamma;  // unset: see evaluateTimeline
};

enum class Interpolation { Linear, CatmullRom };

struct Timeline {
  std::vector<Keyframe> keys;  // kept sorted by frame, at most one key per frame
  Interpolation interpolation = Interpolation::CatmullRom;
  double fps = 24;
  int firstFrame = 0, lastFrame = 48;  // the playback and export range, inclusive
  bool loop = true;

  // Adds a key or replaces the key at the same frame.
  void setKey(const Keyframe& key);
  void removeKey(double frame);
};

struct FrameState {
  Eigen::MatrixXd cage;  // #V by d
  DeformParams params;
};

// The cage and parameters at `frame`. Before the first key and after the last, the end key holds. Between keys:
// Linear blends the poses of the two keys; CatmullRom is the cubic Hermite spline through the key poses with
// Catmull-Rom tangents (p[k+1] - p[k-1]) / (t[k+1] - t[k-1]) (one-sided at the ends), which passes through every
// key and is C1 across keys even when they are unevenly spaced. nu and gamma are interpolated linearly (a
// cubic could overshoot the valid range of nu); a key without one takes the nearest earlier key's value (else
// the nearest later key's; base's when no key sets it); nu = +-inf holds its value to the next key. Throws InputError
// when a key names a missing pose or a pose has the wrong shape.
FrameState evaluateTimeline(const Timeline& timeline, const PoseLibrary& library, double frame,
                            const DeformParams& base, Eigen::Index vertexCount, Eigen::Index dim);

// The frame to show `elapsedSeconds` after playback started at startFrame: fps frames per second, wrapping
// from lastFrame to firstFrame when looping, else stopping at lastFrame.
double playbackFrame(const Timeline& timeline, double startFrame, double elapsedSeconds);

}  // namespace somicage
