// A saved editing session (JSON): which files, the rest cage when no file holds it, the cage pose, the method and its
// parameters, the compare views, the camera, the poses and the timeline. The one reader and writer of session files:
// the editor, `somicage animate`, Python's somicage.load_session and the session fuzz target all use it.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "animation/pose_timeline.h"
#include "deform/deformer.h"
#include "engine/camera_state.h"
#include "engine/engine.h"
#include "engine/view_spec.h"
#include "geometry/cage.h"

namespace somicage {

// Side-by-side views the layout offers, and the ones a new session compares: the registry's first few methods.
constexpr std::size_t kMaxCompareViews = 3;
std::vector<Method> defaultCompareMethods();

struct Session {
  std::string meshPath, cagePath;  // both empty: the built-in demo of dimension demoDim
  int demoDim = 3;
  // The rest cage when it has no file (File > Make cage, a mesh opened without a cage, the demos): written inline so
  // that loading gives back this very cage, not a new default one. Empty (no vertices) when cagePath names its file.
  Cage restCage;
  // Read, not written: what loading repaired in restCage and warned about (prepareCage).
  std::vector<Notice> cageNotices;
  Eigen::MatrixXd pose;  // #V by d posed cage vertices; empty = the rest pose
  Method method;         // the registry's first (method.h)
  // The method's own precompute options (MethodDescriptor::options), e.g. Phong's {"tets": "T.mesh", "tet-level":
  // "2"}; a relative "tets" file is looked up like the mesh (loadSession).
  MethodOptions methodOptions;
  DeformParams params;
  bool compare = false;
  std::vector<ViewSpec> compareViews = viewsOf(defaultCompareMethods());  // the compare view's panes
  CameraState camera;
  PoseLibrary poses;  // named poses and the keyframes that use them (core/animation/pose_timeline.h)
  Timeline timeline;
};

// JSON text with "format": "somicage-session", "version": 3 (version 2 adds "poses" and "timeline",
// core/animation/pose_timeline_json.h; version 3 adds "restCage": {"vertices": [[x, y, z], ...], "faces": [[a, b, c],
// ...]}, 0-based, when the cage has no file; and "views": [{"method": "somigliana", "nu": 0.45, "gamma": 1, "variant":
// "local", "tractionCorrection": false, "bulging": "reference", "normals": "angle"}, ...], each parameter only when
// the view has its own; and "methodOptions": {"tets": "T.mesh", "tet-level": "2"}, the method's own options as
// text, when it has any). Versions 1 and 2
// load with an empty library and timeline and no inline cage; a session without "views" compares the methods of
// "compareMethods" (still written, for older builds) with the shared parameters.
// nu = +-infinity is written as "inf" / "-inf"; every number as the shortest text that reads back to the same double
// (json.h). What only the editor's view needs ("demoDim", "pose", "compare", "compareMethods", "camera") may be
// absent: a new session's values then.
std::string sessionToJson(const Session& session);
// Throws InputError naming `source` on a syntax error, a missing or mistyped field, an unknown method or method
// option (one the method does not have), or an inline
// cage that is malformed or that a cage file with the same content would be refused for (prepareCage, engine.h).
Session sessionFromJson(const std::string& text, const std::string& source);

void saveSession(const std::string& path, const Session& session);  // atomic
// The files it names (mesh, cage, a method's FILE options such as Phong's "tets", the views' too) come back
// resolved: a relative name is looked up next to the session first, then as given (the editor saves names as it
// opened them, relative to its working folder).
Session loadSession(const std::string& path);

}  // namespace somicage
