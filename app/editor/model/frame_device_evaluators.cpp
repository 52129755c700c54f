#include "model/frame_device_evaluators.h"

#include <exception>
#include <iterator>
#include <utility>

#include "deform/frame_evaluation.h"
#include "model/app_state.h"

namespace somicage::editor {

FrameEvaluator& FrameDeviceEvaluators::get(const FrameDevice& device,
                                           const std::shared_ptr<const CageDeformer>& deformer) {
  for (auto it = evaluators_.begin(); it != evaluators_.end();)
    it = it->second.deformer.expired() ? evaluators_.erase(it) : std::next(it);
  Entry& entry = evaluators_[deformer.get()];  // (an expired entry at a reused address went above)
  if (!entry.evaluator || entry.device != device.name) {
    entry.evaluator.reset();  // the old device's copy of C goes before the new one is made
    entry.evaluator = device.make(*deformer);
    entry.deformer = deformer;
    entry.device = device.name;
  }
  return *entry.evaluator;
}

std::string chooseDevice(DeviceState& state, FrameDevices devices, const std::optional<std::string>& requested,
                         const std::string& preferred, const std::string& inPlaceProblem) {
  if (!findFrameDevice(devices, kCpuDevice)) devices.insert(devices.begin(), cpuFrameDevice());
  state.offered = std::move(devices);
  state.unavailable.clear();
  state.evaluators.clear();
  for (const FrameDevice& device : state.offered) {
    const std::string why = device.name == kInPlaceDevice ? inPlaceProblem
                            : device.unavailable          ? device.unavailable()
                                                          : std::string();
    if (!why.empty()) state.unavailable[device.name] = why;
  }
  state.requested = requested.value_or(preferred);
  if (state.usable(state.requested)) return "";
  const std::string why = findFrameDevice(state.offered, state.requested) ? state.unavailable.at(state.requested)
                                                                          : "not offered by this executable";
  state.requested = kCpuDevice;
  return requested ? why : "";  // the default falls back quietly: the panel says why
}

void deviceFailed(AppState& state, const std::string& name, const std::string& what) {
  state.model.devices.unavailable[name] = "failed: " + what;
  state.model.devices.evaluators.clear();
  state.status.errors.push_back("the " + name + " deformation failed, using the CPU: " + what);
}

void deformOnDevice(AppState& state, const std::shared_ptr<const CageDeformer>& deformer, const DeformParams& params,
                    Eigen::MatrixXd& out) {
  const FrameWeights W = deformer->frameWeights(state.document.pose, params);  // bad parameters throw here
  DeviceState& devices = state.model.devices;
  const std::string name = devices.inPlace() ? kCpuDevice : devices.active();
  if (name != kCpuDevice) {
    try {
      devices.evaluators.get(*findFrameDevice(devices.offered, name), deformer).evaluate(W, out);
      return;
    } catch (const std::exception& e) {  // no device after all, out of its memory, a failed kernel: the CPU for good
      deviceFailed(state, name, e.what());
    }
  }
  devices.evaluators.get(*findFrameDevice(devices.offered, kCpuDevice), deformer).evaluate(W, out);
}

}  // namespace somicage::editor
