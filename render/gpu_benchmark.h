// Timing the GPU deformation (render/gpu_deformer.h) for `somicage bench`: opens its own hidden window and
// OpenGL 4.3 context (render/offscreen_context.h, GLFW), so it must not run while the editor (or anything else
// that initialises GLFW itself) is open in the same process. No GL or GLFW types in this header.
#pragma once

#include <Eigen/Core>
#include <string>

#include "deform/deformer.h"
#include "gpu_deformer.h"

namespace somicage::render {

struct GpuFrameTiming {
  bool ok = false;
  std::string reason;  // why not, when !ok (no display, no OpenGL 4.3, shader compile error, out of memory)
  std::string device;  // GL_RENDERER (GL_VERSION)
  std::string layout;  // the kernel's work layout, "1 x 64" = invocations per point x points per group
  int frames = 0;
  double uploadMs = 0.0;  // the one-time upload of C (converted to float)
  // Medians over the frames, in milliseconds. A frame is what the editor does for one changed pose: frameWeights
  // on the CPU, the W upload, the deformation and both normal passes, bracketed by glFinish (wall time).
  double frameMs = 0.0;
  double gpuMs = 0.0;      // the same frame's GPU time (GL_TIME_ELAPSED; software renderers: glFinish wall time,
                           // see GpuDeformer::lastGpuMilliseconds)
  double weightsMs = 0.0;  // frameWeights alone (CPU)
};

// Deforms `frames` times (after two warm-up frames) with the posed cage (#V by d) and params. triangles (#P by 3
// indices into the deformer's points, may be empty) adds the two normal passes the editor runs.
// layout picks the kernel's work layout (default: automatic, GpuDeformer::chooseLayout).
GpuFrameTiming benchmarkGpuDeform(const CageDeformer& deformer, const Eigen::MatrixXd& posed,
                                  const DeformParams& params, int frames,
                                  const Eigen::MatrixXi& triangles = Eigen::MatrixXi(), GpuDeformerLayout layout = {});

// The median frame time in milliseconds (GpuFrameTiming::frameMs), or NaN when no OpenGL 4.3 context can be made
// (or the deformer cannot run on it); then *reason, when given, says why.
double timeGpuDeformMs(const CageDeformer& deformer, const Eigen::MatrixXd& posed, const DeformParams& params,
                       int frames, std::string* reason = nullptr);

}  // namespace somicage::render
