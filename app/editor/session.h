// A saved editing session (JSON): which files, the cage pose, the method and its parameters, the view.
// Pure, no GL.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "camera.h"
#include "deformer.h"
#include "pose_timeline.h"

namespace somicage::editor {

// Side-by-side views the layout offers, and the ones a new session compares: the registry's first few methods.
constexpr std::size_t kMaxCompareViews = 3;
std::vector<Method> defaultCompareMethods();

struct Session {
  std::string meshPath, cagePath;  // both empty: the built-in demo of dimension demoDim
  int demoDim = 3;
  Eigen::MatrixXd pose;  // #V by d posed cage vertices; empty = the rest pose
  Method method;         // the registry's first (method.h)
  DeformParams params;
  bool compare = false;
  std::vector<Method> compareMethods = defaultCompareMethods();
  CameraState camera;
  PoseLibrary poses;  // named poses and the keyframes that use them (core/pose_timeline.h)
  Timeline timeline;
};

// JSON text with "format": "somicage-session", "version": 2 (version 2 adds "poses" and "timeline",
// core/pose_timeline_json.h; version 1 files load with an empty library and timeline). nu = +-infinity is written as
// "inf" / "-inf".
std::string sessionToJson(const Session& session);
// Throws InputError naming `source` on a syntax error, a missing or mistyped field, or an unknown method.
Session sessionFromJson(const std::string& text, const std::string& source);

void saveSession(const std::string& path, const Session& session);  // atomic
Session loadSession(const std::string& path);

}  // namespace somicage::editor
