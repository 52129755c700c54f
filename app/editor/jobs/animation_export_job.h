// File > Export animation in the editor, three kinds of output. A GLB or an OBJ sequence of the deformed mesh runs
// on the export worker (export_worker.h) through the same core calls as `somicage animate` (deformTimelineFrames,
// deformTimelineNormals, writeAnimation), so the window keeps drawing its progress bar with Cancel. A PNG image
// sequence of the viewports as drawn (the compare view included) needs the frame loop: one timeline frame per editor
// frame, each image written into a temporary folder that is renamed into place at the end; Cancel or an error
// removes it, and the pose, parameters and cursor are restored.
#pragma once

#include <Eigen/Core>
#include <string>

#include "deform/deform_params.h"

namespace somicage::editor {

struct AppState;

struct AnimationExportJob {  // the PNG sequence in progress
  enum class Kind { Glb, ObjSequence, PngSequence };
  std::string out;
  int first = 0, last = 0, next = 0;  // next: the frame shown this editor frame
  std::string pngFolder;              // the temporary folder
  Eigen::MatrixXd savedPose;
  DeformParams savedParams;
  double savedFrame = 0;
  bool cancelRequested = false;
};

// Checks the request (a mesh file scene with keys; a GLB path ending in .glb) and starts; errors go to state.errors.
void startAnimationExport(AppState& state, AnimationExportJob::Kind kind, const std::string& out);
// Frame loop hooks of the PNG sequence: before the deformation (shows the next frame's pose) and after drawing
// (takes the frame).
void showNextExportFrame(AppState& state);
void captureExportFrame(AppState& state, int framebufferWidth, int framebufferHeight);

}  // namespace somicage::editor
