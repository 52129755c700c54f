#include "python_session.h"

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "animation/pose_timeline.h"
#include "deform/parameter_schema.h"
#include "engine/engine.h"
#include "engine/session.h"
#include "io/mesh_formats.h"
#include "io/obj_io.h"
#include "python_cage.h"

namespace py = pybind11;

namespace somicage {

namespace {

// Deformer.deform's keyword arguments, one per row of parameter_schema.h: `deformer.deform(posed, **params)`
// deforms as the session does (the variant by name, then the blend that overrides it).
py::dict deformKeywords(const DeformParams& params) {
  py::dict out;
  for (const ParameterSpec& spec : parameterSchema()) {
    const double value = parameterValue(spec, params);
    switch (spec.type) {
      case ParameterType::Number:
        out[spec.pythonKeyword] = value;
        break;
      case ParameterType::Switch:
        out[spec.pythonKeyword] = value != 0;
        break;
      case ParameterType::Choice:
        out[spec.pythonKeyword] = parameterText(spec, value);
        break;
    }
  }
  return out;
}

py::dict timelineDict(const Timeline& timeline) {
  py::list keys;
  for (const Keyframe& key : timeline.keys) {
    py::dict entry;
    entry["frame"] = key.frame;
    entry["pose"] = key.pose;
    entry["nu"] = key.nu ? py::object(py::float_(*key.nu)) : py::object(py::none());
    entry["gamma"] = key.gamma ? py::object(py::float_(*key.gamma)) : py::object(py::none());
    keys.append(entry);
  }
  py::dict out;
  out["fps"] = timeline.fps;
  out["first"] = timeline.firstFrame;
  out["last"] = timeline.lastFrame;
  out["loop"] = timeline.loop;
  out["interpolation"] = timeline.interpolation == Interpolation::Linear ? "linear" : "catmull-rom";
  out["keys"] = keys;
  return out;
}

}  // namespace

py::dict loadSessionForPython(const std::string& path) {
  const Session session = loadSession(path);
  const std::string& meshPath = session.meshPath;  // resolved next to the session by loadSession
  const std::string& cagePath = session.cagePath;
  py::object cage = py::none();  // a demo, or an old session of a mesh opened alone (the editor generates its cage)
  if (session.restCage.numVertices() > 0) {
    cage = py::cast(makeUsableCage(session.restCage, path + " (restCage)"));
  } else if (!cagePath.empty()) {
    cage = py::cast(makeUsableCage(cageFromMesh(loadAnyMesh(cagePath), cagePath), cagePath));
  }
  py::dict poses;
  for (const NamedPose& pose : session.poses.poses()) poses[pose.name.c_str()] = pose.vertices;
  // Every whole frame of the timeline's range, as the editor plays it and `somicage animate` writes it.
  py::list frames;
  if (!cage.is_none() && !session.timeline.keys.empty()) {
    const Cage& rest = cage.cast<const PythonCage&>().cage;
    for (int frame = session.timeline.firstFrame; frame <= session.timeline.lastFrame; ++frame) {
      const FrameState state =
          evaluateTimeline(session.timeline, session.poses, frame, session.params, rest.numVertices(), rest.dim());
      validateDeformParams(state.params);
      frames.append(py::make_tuple(state.cage, deformKeywords(state.params)));
    }
  }
  py::dict out;
  out["source"] = path;
  out["mesh"] = meshPath;
  out["cage_path"] = cagePath;
  out["cage"] = cage;
  out["method"] = methodName(session.method);
  const auto tets = session.methodOptions.find("tets");  // Deformer's tets=, next to the session as animate finds it
  out["tets"] = tets == session.methodOptions.end() ? std::string() : tets->second;
  out["params"] = deformKeywords(session.params);
  out["pose"] = session.pose.size() > 0 ? py::cast(session.pose) : py::object(py::none());
  out["poses"] = poses;
  out["timeline"] = timelineDict(session.timeline);
  out["frames"] = frames;
  return out;
}

}  // namespace somicage
