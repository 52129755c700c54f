// The document: what the user edits and what undo / redo / the Undo History restore exactly. Everything that
// is not here (camera, selection, which views are shown, the device) is view state: changing it is not an
// edit and does not make the document "unsaved". Pure, no GL.
//
// To make a new kind of edit undoable, add the field it changes here (with its comparison in operator==) and
// restore it in applyDocument (app_state.cpp); the command itself is then just "change the state, then
// commitEdit(state, name)" (see docs/editor.md).
#pragma once

#include <Eigen/Core>
#include <string>

#include "animation/pose_timeline.h"
#include "deform/deform_params.h"
#include "deform/method.h"
#include "geometry/cage.h"

namespace somicage::editor {

struct Document {
  Eigen::MatrixXd pose;  // #V by d posed cage vertices
  Method method;  // the registry's first (method.h)
  DeformParams params;
  PoseLibrary poses;  // the pose library and the timeline (pose_keys.h)
  Timeline timeline;
  Cage restCage;  // the scene's rest cage: File > Make cage replaces it (cage_maker.h); empty: not recorded
  std::string cagePath;  // the file restCage is read from; empty: none (generated, or the demo's): sessions hold it
};

// Exact comparison (bitwise for the numbers: undo must restore exactly, and "no change" must be no step).
bool operator==(const Document& a, const Document& b);
inline bool operator!=(const Document& a, const Document& b) { return !(a == b); }
bool sameCage(const Cage& a, const Cage& b);  // bitwise

}  // namespace somicage::editor
