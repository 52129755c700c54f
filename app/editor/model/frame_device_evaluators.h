// Where the editor evaluates every frame's deformation: on one of the FrameDevices main.cpp offers
// (frame_evaluator.h: cpu, opengl, cuda), chosen with --device or the panel. The "opengl" device is evaluated in
// place, by the Renderer (editor_renderer.h): its GpuDeformer writes the points straight into the vertex buffers of
// the editor's own context, the zero-copy form of the OpenGL device (whose make() would open a hidden context of its
// own, which must not live beside the editor's window, and read the points back). Every other device (cpu, cuda, any
// later one) goes through a FrameEvaluator made by its make(), one per deformer, into AppState::deformed.
#pragma once

#include <Eigen/Core>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "deform/deformer.h"
#include "deform/frame_evaluator.h"

namespace somicage::editor {

struct AppState;

inline constexpr const char* kCpuDevice = "cpu";         // always offered: the fallback of every other device
inline constexpr const char* kInPlaceDevice = "opengl";  // evaluated by the Renderer, never through make()

// One FrameEvaluator per deformer, made with device.make(deformer) and made again when the deformer or the device
// changes; the evaluators of deformers that are gone are dropped.
class FrameDeviceEvaluators {
 public:
  // The evaluator of `deformer` on `device`. Throws what device.make throws (FrameDeviceUnavailable).
  FrameEvaluator& get(const FrameDevice& device, const std::shared_ptr<const CageDeformer>& deformer);
  void clear() { evaluators_.clear(); }
  std::size_t size() const { return evaluators_.size(); }

 private:
  struct Entry {
    std::weak_ptr<const CageDeformer> deformer;  // not owned: a replaced deformer goes, and so does its evaluator
    std::string device;
    std::unique_ptr<FrameEvaluator> evaluator;
  };
  std::map<const CageDeformer*, Entry> evaluators_;
};

// The devices offered, which one deforms, and why the others cannot run here.
struct DeviceState {
  FrameDevices offered = {cpuFrameDevice()};       // chooseDevice: main.cpp's list (tests offer fakes)
  std::string requested = kCpuDevice;              // the panel's choice (--device)
  std::map<std::string, std::string> unavailable;  // device name -> why it cannot deform here (start, or a failure)
  std::string note;                                // a caveat about a usable device (OpenGL on a software renderer)
  FrameDeviceEvaluators evaluators;                // for the active device (and cpu, its fallback)

  bool usable(const std::string& name) const { return findFrameDevice(offered, name) && !unavailable.count(name); }
  // The device that deforms this frame: the requested one when usable, else the CPU.
  std::string active() const { return usable(requested) ? requested : kCpuDevice; }
  bool inPlace() const { return active() == kInPlaceDevice; }
};

// Offers `devices` (cpu is added when missing), asks each but the in-place one whether it can run here (the in-place
// one cannot when inPlaceProblem says why) and requests `requested` (--device) or, without one, `preferred`.
// Returns why `requested` is refused ("" when it is not): the CPU deforms instead.
std::string chooseDevice(DeviceState& state, FrameDevices devices, const std::optional<std::string>& requested,
                         const std::string& preferred, const std::string& inPlaceProblem);

// After `name` failed with `what`: marks it unusable and reports it in state.errors; the CPU deforms from now on.
void deviceFailed(AppState& state, const std::string& name, const std::string& what);

// out = the deformer's points for state.pose and `params` (a view's) on the active device (the CPU when the active
// one is in place: these are the numbers framing and export need). Bad parameters throw InputError (nothing is
// evaluated); a device that fails is marked unavailable, reported in state.errors, and the CPU evaluates instead.
void deformOnDevice(AppState& state, const std::shared_ptr<const CageDeformer>& deformer, const DeformParams& params,
                    Eigen::MatrixXd& out);

}  // namespace somicage::editor
