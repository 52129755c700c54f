// The OpenGL frame device ("opengl", bench key "gpu"): GpuDeformer's compute shader (float C, gpu_deformer.h) in
// its own hidden OpenGL 4.3 context (offscreen_context.h), with the points read back after every frame. Like
// every OffscreenGlContext it must not live while the editor (or anything else using GLFW) runs in the process.
#pragma once

#include "deform/frame_evaluator.h"

namespace somicage::render {

FrameDevice openGlFrameDevice();

}  // namespace somicage::render
