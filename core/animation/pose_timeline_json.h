// The pose library and the timeline in session files (JSON; the rest of a session: session.h).
//   "poses":    [{"name": "...", "vertices": [[x, y, z], ...]}, ...]
//   "timeline": {"fps": 24, "first": 0, "last": 48, "loop": true, "interpolation": "catmull-rom" | "linear",
//                "keys": [{"frame": 0, "pose": "...", "nu": 0.2 (optional), "gamma": 1 (optional)}, ...]}
// Both are optional in a session (version 1 sessions have neither).
#pragma once

#include <string>

#include "animation/pose_timeline.h"
#include "base/json.h"

namespace somicage {

JsonValue poseLibraryToJson(const PoseLibrary& library);
JsonValue timelineToJson(const Timeline& timeline);
// Throw InputError naming source on a mistyped or missing field.
PoseLibrary poseLibraryFromJson(const JsonValue& value, const std::string& source);
Timeline timelineFromJson(const JsonValue& value, const std::string& source);

}  // namespace somicage
