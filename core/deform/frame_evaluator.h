// One frame on some device: the deformed points from a deformer's precomputed coordinates C and a pose's frame
// weights W (frame_evaluation.h: y = C W, then the per-point solve and the exterior blend). The CPU evaluator is
// here; the OpenGL one is render/gl_frame_evaluator.h, the CUDA one core/cuda/cuda_backend.h. A front end picks
// the devices it offers (FrameDevice) and hands them to whatever evaluates frames: nothing is global.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "deform/deformer.h"
#include "deform/frame_evaluation.h"
#include "geometry/integration_options.h"

namespace somicage {

class FrameEvaluator {
 public:
  virtual ~FrameEvaluator() = default;
  // out: the deformer's #P points (#P by d, resized) for W = deformer.frameWeights(pose, params).
  virtual void evaluate(const FrameWeights& W, Eigen::MatrixXd& out) = 0;
};

// A device cannot evaluate frames here (no OpenGL 4.3 context, no CUDA device, built without it): what() says why.
class FrameDeviceUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A device that can evaluate frames: `make` uploads a deformer's coordinates (the deformer must outlive the
// evaluator) or throws FrameDeviceUnavailable.
struct FrameDevice {
  std::string name;      // what `--device` takes: "cpu", "opengl", "cuda"
  std::string benchKey;  // `somicage bench`'s deform_ms.KEY_global / KEY_local: "cpu", "gpu", "cuda"
  std::function<std::unique_ptr<FrameEvaluator>(const CageDeformer& deformer)> make;
  // Why the device cannot be used here, empty when it can or when only `make` can tell (cheap: asked before a
  // precompute, so that a missing device fails before the work); may be empty.
  std::function<std::string()> unavailable;
  // The device's Somigliana row integrator (PrecomputeOptions::rowIntegrator), empty for the CPU's.
  RowIntegrator rowIntegrator;
};
using FrameDevices = std::vector<FrameDevice>;

// evaluateFrame on the CPU, with the deformer's thread count (the result does not depend on it).
class CpuFrameEvaluator final : public FrameEvaluator {
 public:
  explicit CpuFrameEvaluator(const CageDeformer& deformer) : deformer_(deformer) {}
  void evaluate(const FrameWeights& W, Eigen::MatrixXd& out) override;

 private:
  const CageDeformer& deformer_;
};
FrameDevice cpuFrameDevice();

// The device called `name`, or nullptr.
const FrameDevice* findFrameDevice(const FrameDevices& devices, const std::string& name);
// The device called `name` (what `--device` took); throws InputError("--device") listing the offered devices.
const FrameDevice& frameDeviceOption(const FrameDevices& devices, const std::string& name);

}  // namespace somicage
