// The interactive editor (GLFW + OpenGL + ImGui).
#pragma once

#include "deform/frame_evaluator.h"

namespace somicage {

// somicage [MESH.obj CAGE.obj [POSED.obj]] [options]: opens the editor (the built-in demo without files),
// or with --screenshot renders one frame to a PNG and exits. Returns the process exit code: 0 ok,
// 1 failure (no display, GL too old, precompute failed), 2 bad command line or input files. devices: where frames can
// be deformed (--device, the panel; main.cpp's list, the one the CLI gets).
int runEditor(int argc, char** argv, const FrameDevices& devices);

}  // namespace somicage
