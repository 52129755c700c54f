#include "gl_frame_evaluator.h"

#include <exception>
#include <memory>
#include <string>

#include "gpu_deformer.h"
#include "mesh_renderer.h"
#include "offscreen_context.h"

namespace somicage::render {

namespace {

class GlFrameEvaluator final : public FrameEvaluator {
 public:
  // The GL objects are made once the context is current, and destroyed (in reverse order) before it.
  explicit GlFrameEvaluator(const CageDeformer& deformer) : context_(4, 3) {
    if (!context_.ok()) throw FrameDeviceUnavailable(context_.reason());
    std::string reason;
    if (!GpuDeformer::available(&reason)) throw FrameDeviceUnavailable(reason);
    points_ = std::make_unique<MeshRenderer>();
    gpu_ = std::make_unique<GpuDeformer>();
    gpu_->upload(deformer);
  }
  void evaluate(const FrameWeights& W, Eigen::MatrixXd& out) override {
    gpu_->deform(W, *points_);
    out = gpu_->readBack(*points_);
  }

 private:
  OffscreenGlContext context_;
  std::unique_ptr<MeshRenderer> points_;  // no triangles: positions only, no normal passes
  std::unique_ptr<GpuDeformer> gpu_;
};

}  // namespace

FrameDevice openGlFrameDevice() {
  return {"opengl",
          "gpu",
          [](const CageDeformer& deformer) { return std::make_unique<GlFrameEvaluator>(deformer); },
          {},
          {}};
}

}  // namespace somicage::render
