#include "deform/frame_evaluator.h"

#include "base/errors.h"

namespace somicage {

void CpuFrameEvaluator::evaluate(const FrameWeights& W, Eigen::MatrixXd& out) {
  evaluateFrame(deformer_.frameCoordinates(), W, deformer_.dim(), deformer_.threads(), out);
}

FrameDevice cpuFrameDevice() {
  return {
      "cpu", "cpu", [](const CageDeformer& deformer) { return std::make_unique<CpuFrameEvaluator>(deformer); }, {}, {}};
}

const FrameDevice* findFrameDevice(const FrameDevices& devices, const std::string& name) {
  for (const FrameDevice& device : devices)
    if (device.name == name) return &device;
  return nullptr;
}

const FrameDevice& frameDeviceOption(const FrameDevices& devices, const std::string& name) {
  if (const FrameDevice* device = findFrameDevice(devices, name)) return *device;
  std::string offered;
  for (const FrameDevice& d : devices) offered += (offered.empty() ? "" : ", ") + d.name;
  throw InputError("--device", -1, "unknown device '" + name + "'", "this executable offers " + offered);
}

}  // namespace somicage
