// Files dropped on the window: which is the mesh, the cage and the posed cage. Pure, no GL (the frame loop acts
// on the plan, see openDroppedFiles in app_state.h).
#pragma once

#include <string>
#include <vector>

namespace somicage::editor {

struct DropPlan {
  enum class Kind {
    Error,    // nothing to open; `message` says what to drop instead
    Scene,    // mesh + cage (+ posed cage): loaded on the worker like the Open panel
    Pose,     // one posed cage for the current scene
    Session,  // one session .json
  };
  Kind kind = Kind::Error;
  std::string mesh, cage, posed;  // Scene (posed may be empty); Pose: `posed`
  std::string session;            // Session
  std::string message;            // Error
};

// Decides what dropped `paths` mean (extensions compared case-insensitively):
//  - one .json: a session;
//  - two .obj: mesh + cage; three .obj: mesh + cage + posed cage. Names decide first, on the file name only (never
//    the folders): "pose"/"posed"/"deformed" marks the posed cage, "cage" a cage, neither the mesh; a role that the
//    names do not settle uniquely takes the remaining files in the order given;
//  - one .obj: a posed cage when it has as many vertices as the current cage (`currentCageVertices`, -1 when there
//    is no current scene; `singleObjVertices` is that file's vertex count, -1 when unknown), else an error saying
//    what to drop;
//  - anything else (other extensions, more files, a .json with other files): an error saying what to drop.
DropPlan planDrop(const std::vector<std::string>& paths, int currentCageVertices, int singleObjVertices);

// Lower-case extension with the dot (".obj"), "" when none.
std::string lowerExtension(const std::string& path);

// Counts the `v` lines of an OBJ file, stopping early once the count exceeds `limit` (returns limit + 1 then), so a
// large mesh is not read in full on the UI thread. -1 when the file cannot be read.
int countObjVertices(const std::string& path, int limit);

}  // namespace somicage::editor
