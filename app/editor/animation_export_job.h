// File > Export animation in the editor: the timeline's frames first..last, one per editor frame, so that the
// window keeps drawing a progress bar with Cancel. Three kinds of output: a GLB or an OBJ sequence of the
// deformed mesh (core/animation_export.h, the same writer as `somicage animate`), or a PNG image sequence of the
// viewports as drawn (the compare view included). Everything goes to a temporary file or folder first and is
// renamed into place at the end; Cancel or an error removes it. The pose, parameters and cursor are restored.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "deformer.h"

namespace somicage::editor {

struct AppState;

struct AnimationExportJob {
  enum class Kind { Glb, ObjSequence, PngSequence };
  Kind kind = Kind::Glb;
  std::string out;
  int first = 0, last = 0, next = 0;    // next: the frame shown this editor frame
  std::vector<Eigen::MatrixXd> frames;  // Glb, ObjSequence: the deformed mesh per frame
  std::string pngFolder;                // PngSequence: the temporary folder
  Eigen::MatrixXd savedPose;
  DeformParams savedParams;
  double savedFrame = 0;
  bool cancelRequested = false;
};

// Checks the request (a mesh file scene with keys) and starts; errors go to state.errors.
void startAnimationExport(AppState& state, AnimationExportJob::Kind kind, const std::string& out);
// Frame loop hooks: before the deformation (shows the next frame's pose) and after drawing (takes the frame).
void showNextExportFrame(AppState& state);
void captureExportFrame(AppState& state, int framebufferWidth, int framebufferHeight);

}  // namespace somicage::editor
