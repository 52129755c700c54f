// How a frame's summed outputs y = C_p W become a point (frame_evaluation.h): stated once by each method's descriptor
// (MethodDescriptor::finish) and carried by its FrameWeights, and switched on in one place per evaluator:
// finishFramePoint (frame_point_kernel.h: the CPU, the CUDA kernel and J) and shaders/deform_frame.comp.glsl (its
// FINISH define, set by render/gpu_deformer.cpp).
#pragma once

#include "base/portable.h"

namespace somicage {

enum class FrameFinish : int {
  Linear = 0,  // the point is y (d outputs): Green, mean value, BEM, Phong
  SolveT = 1,  // the point is o + T^-1 b (d^2 + d outputs, Eq. 11): Somigliana
};

// The outputs a frame of that finish has in dimension dim.
SOMICAGE_HD constexpr int frameOutputs(FrameFinish finish, int dim) {
  return finish == FrameFinish::Linear ? dim : dim * dim + dim;
}

}  // namespace somicage
