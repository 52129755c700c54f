// cuda_device.h for a build without CUDA (SOMICAGE_CUDA=OFF, or AUTO without nvcc): no device, and every other
// call is unreachable because cuda_backend.cpp checks cudaStatus() first.
#include "cuda/cuda_device.h"

namespace somicage {
namespace cuda_device {

namespace {
[[noreturn]] void unavailable() {
  throw CudaError("SomiCage was built without CUDA: reconfigure with -DSOMICAGE_CUDA=ON on a machine with nvcc");
}
}  // namespace

DeviceInfo queryDevice() {
  DeviceInfo info;
  info.reason = "built without CUDA (SOMICAGE_CUDA=OFF, or no nvcc found at configure time)";
  return info;
}

struct DeviceFrame {};
DeviceFrame* uploadCoordinates(const void*, const int32_t*, bool, int, int, int) { unavailable(); }
void releaseCoordinates(DeviceFrame*) noexcept {}
void evaluateFrame(DeviceFrame*, const FrameLaunch&, double*) { unavailable(); }
void integrateSomiglianaRows(const PortableFace*, int, int, const double*, int, double*, double*) { unavailable(); }

}  // namespace cuda_device
}  // namespace somicage
