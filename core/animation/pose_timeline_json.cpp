#include "animation/pose_timeline_json.h"

#include <cmath>
#include <limits>

#include "base/errors.h"

namespace somicage {

namespace {

[[noreturn]] void fail(const std::string& source, const std::string& what) {
  throw InputError(source, -1, what, "fix the session file, or save it again from the editor");
}

const JsonValue& member(const JsonValue& object, const std::string& key, const std::string& source) {
  const JsonValue* value = object.find(key);
  if (!value) fail(source, "missing field \"" + key + "\"");
  return *value;
}

double numberOf(const JsonValue& value, const std::string& what, const std::string& source) {
  if (value.isString() && (value.asString() == "inf" || value.asString() == "-inf"))
    return value.asString() == "inf" ? std::numeric_limits<double>::infinity()
                                     : -std::numeric_limits<double>::infinity();
  if (!value.isNumber()) fail(source, what + " must be a number");
  return value.asNumber();
}

JsonValue numberOrInfinity(double x) {
  if (std::isinf(x)) return JsonValue::string(x > 0 ? "inf" : "-inf");
  return JsonValue::number(x);
}

const char* interpolationName(Interpolation interpolation) {
  return interpolation == Interpolation::Linear ? "linear" : "catmull-rom";
}

}  // namespace

JsonValue poseLibraryToJson(const PoseLibrary& library) {
  JsonValue poses = JsonValue::array();
  for (const NamedPose& pose : library.poses()) {
    JsonValue rows = JsonValue::array();
    for (Eigen::Index i = 0; i < pose.vertices.rows(); ++i) {
      JsonValue row = JsonValue::array();
      for (Eigen::Index c = 0; c < pose.vertices.cols(); ++c) row.push(JsonValue::number(pose.vertices(i, c)));
      rows.push(std::move(row));
    }
    JsonValue entry = JsonValue::object();
    entry.set("name", JsonValue::string(pose.name));
    entry.set("vertices", std::move(rows));
    poses.push(std::move(entry));
  }
  return poses;
}

JsonValue timelineToJson(const Timeline& timeline) {
  JsonValue keys = JsonValue::array();
  for (const Keyframe& key : timeline.keys) {
    JsonValue entry = JsonValue::object();
    entry.set("frame", JsonValue::number(key.frame));
    entry.set("pose", JsonValue::string(key.pose));
    if (key.nu) entry.set("nu", numberOrInfinity(*key.nu));
    if (key.gamma) entry.set("gamma", JsonValue::number(*key.gamma));
    keys.push(std::move(entry));
  }
  JsonValue out = JsonValue::object();
  out.set("fps", JsonValue::number(timeline.fps));
  out.set("first", JsonValue::number(timeline.firstFrame));
  out.set("last", JsonValue::number(timeline.lastFrame));
  out.set("loop", JsonValue::boolean(timeline.loop));
  out.set("interpolation", JsonValue::string(interpolationName(timeline.interpolation)));
  out.set("keys", std::move(keys));
  return out;
}

PoseLibrary poseLibraryFromJson(const JsonValue& value, const std::string& source) {
  if (!value.isArray()) fail(source, "\"poses\" must be an array");
  PoseLibrary library;
  for (const JsonValue& entry : value.items()) {
    const JsonValue& name = member(entry, "name", source);
    if (!name.isString() || name.asString().empty()) fail(source, "a pose's \"name\" must be a non-empty string");
    if (library.find(name.asString())) fail(source, "two poses are named \"" + name.asString() + "\"");
    const JsonValue& rows = member(entry, "vertices", source);
    const std::string what = "the vertices of pose \"" + name.asString() + "\"";
    if (!rows.isArray() || rows.items().empty()) fail(source, what + " must be a non-empty array of rows");
    const size_t cols = rows.items()[0].items().size();
    if (cols != 2 && cols != 3) fail(source, what + " must have 2 or 3 numbers per row");
    Eigen::MatrixXd vertices(static_cast<Eigen::Index>(rows.items().size()), static_cast<Eigen::Index>(cols));
    for (size_t i = 0; i < rows.items().size(); ++i) {
      const JsonValue& row = rows.items()[i];
      if (!row.isArray() || row.items().size() != cols)
        fail(source, what + ": row " + std::to_string(i) + " has the wrong size");
      for (size_t c = 0; c < cols; ++c) {
        const double x = numberOf(row.items()[c], what, source);
        if (!std::isfinite(x)) fail(source, what + " must be finite");
        vertices(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(c)) = x;
      }
    }
    library.store(name.asString(), vertices);
  }
  return library;
}

Timeline timelineFromJson(const JsonValue& value, const std::string& source) {
  if (!value.isObject()) fail(source, "\"timeline\" must be an object");
  Timeline timeline;
  timeline.fps = numberOf(member(value, "fps", source), "\"fps\"", source);
  if (!(timeline.fps > 0 && timeline.fps <= 1000)) fail(source, "\"fps\" must be in (0, 1000]");
  const double first = numberOf(member(value, "first", source), "\"first\"", source);
  const double last = numberOf(member(value, "last", source), "\"last\"", source);
  if (!(std::abs(first) < 1e7 && std::abs(last) < 1e7 && first <= last)) fail(source, "\"first\" must be <= \"last\"");
  timeline.firstFrame = static_cast<int>(first);
  timeline.lastFrame = static_cast<int>(last);
  const JsonValue& loop = member(value, "loop", source);
  if (loop.type() != JsonValue::Type::Bool) fail(source, "\"loop\" must be true or false");
  timeline.loop = loop.asBool();
  const JsonValue& interpolation = member(value, "interpolation", source);
  if (!interpolation.isString() || (interpolation.asString() != "linear" && interpolation.asString() != "catmull-rom"))
    fail(source, "\"interpolation\" must be \"linear\" or \"catmull-rom\"");
  timeline.interpolation = interpolation.asString() == "linear" ? Interpolation::Linear : Interpolation::CatmullRom;
  const JsonValue& keys = member(value, "keys", source);
  if (!keys.isArray()) fail(source, "\"keys\" must be an array");
  for (const JsonValue& entry : keys.items()) {
    Keyframe key;
    key.frame = numberOf(member(entry, "frame", source), "a key's \"frame\"", source);
    if (!std::isfinite(key.frame)) fail(source, "a key's \"frame\" must be finite");
    const JsonValue& pose = member(entry, "pose", source);
    if (!pose.isString()) fail(source, "a key's \"pose\" must be a string");
    key.pose = pose.asString();
    if (const JsonValue* nu = entry.find("nu")) key.nu = numberOf(*nu, "a key's \"nu\"", source);
    if (const JsonValue* gamma = entry.find("gamma")) key.gamma = numberOf(*gamma, "a key's \"gamma\"", source);
    DeformParams check;
    check.nu = key.nu.value_or(0.0);
    check.gamma = key.gamma.value_or(0.0);
    try {
      validateDeformParams(check);
    } catch (const InputError& e) {
      fail(source, "the key at frame " + std::to_string(key.frame) + ": " + e.problem());
    }
    timeline.setKey(key);
  }
  return timeline;
}

}  // namespace somicage
