// The pose library and the timeline in session files (JSON), and what `somicage animate` reads of a session.
//   "poses":    [{"name": "...", "vertices": [[x, y, z], ...]}, ...]
//   "timeline": {"fps": 24, "first": 0, "last": 48, "loop": true, "interpolation": "catmull-rom" | "linear",
//                "keys": [{"frame": 0, "pose": "...", "nu": 0.2 (optional), "gamma": 1 (optional)}, ...]}
// Both are optional in a session (version 1 sessions have neither).
#pragma once

#include <string>

#include "json.h"
#include "pose_timeline.h"

namespace somicage {

JsonValue poseLibraryToJson(const PoseLibrary& library);
JsonValue timelineToJson(const Timeline& timeline);
// Throw InputError naming source on a mistyped or missing field.
PoseLibrary poseLibraryFromJson(const JsonValue& value, const std::string& source);
Timeline timelineFromJson(const JsonValue& value, const std::string& source);

// What an animation needs from a session file: the files, the method and parameters, the poses and the keys.
struct AnimationSource {
  std::string meshPath, cagePath;
  Method method;  // the registry's first (Somigliana) when the session names none
  DeformParams params;
  PoseLibrary poses;
  Timeline timeline;
};
// Reads those fields of a session file's JSON (the editor's session.h reads the rest).
AnimationSource animationSourceFromSessionJson(const std::string& text, const std::string& source);

}  // namespace somicage
