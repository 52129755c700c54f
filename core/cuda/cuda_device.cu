// CUDA kernels of the optional backend: the frame evaluation (frame_evaluation.h) and the 3D Somigliana
// precompute (somigliana_row_portable.h). The host functions copy synchronously and throw CudaError on failure.
#include <cuda_runtime.h>

#include <algorithm>
#include <string>

#include "cuda/cuda_device.h"
#include "deform/frame_point_kernel.h"

namespace somicage {
namespace cuda_device {

namespace {

constexpr int kWarp = 32;
constexpr int kFrameBlock = 256;      // 8 points per block, one warp each
constexpr int kPrecomputeBlock = 64;  // one point per thread; the per-point work is long and register-heavy

void check(cudaError_t status, const char* call) {
  if (status != cudaSuccess)
    throw CudaError(std::string("CUDA ") + call + " failed: " + cudaGetErrorString(status) +
                    " (check the driver with nvidia-smi, or run on the CPU backend)");
}

// One warp per point: the lanes stride over the row's columns (coalesced reads), their partial sums are reduced
// with shuffles, and lane 0 finishes the point (frame_point_kernel.h).
template <typename Scalar, int Dim>
__global__ void frameKernel(const Scalar* __restrict__ C, int rows, PortableFrameWeights W, double* __restrict__ out) {
  const int p = blockIdx.x * (blockDim.x / kWarp) + threadIdx.x / kWarp;
  const int lane = threadIdx.x % kWarp;
  if (p >= rows) return;  // the whole warp leaves together
  double y[kPortableMaxOutputs] = {0};
  addFramePartialSums(C + static_cast<size_t>(p) * W.columns, W, lane, kWarp, y);
#pragma unroll
  for (int o = 0; o < kPortableMaxOutputs; ++o)
    for (int offset = kWarp / 2; offset > 0; offset /= 2) y[o] += __shfl_down_sync(0xffffffffu, y[o], offset);
  if (lane == 0) finishFramePoint<Dim>(y, W.finish, W.origin, out + static_cast<size_t>(p) * Dim);
}

// The same for sparse rows (coordinate_layout.h) of `entries` (value, column) pairs: the lanes stride over a row's
// entries.
template <typename Scalar, int Dim>
__global__ void sparseFrameKernel(const Scalar* __restrict__ C, const int32_t* __restrict__ entryColumns, int entries,
                                  int rows, PortableFrameWeights W, double* __restrict__ out) {
  const int p = blockIdx.x * (blockDim.x / kWarp) + threadIdx.x / kWarp;
  const int lane = threadIdx.x % kWarp;
  if (p >= rows) return;
  double y[kPortableMaxOutputs] = {0};
  const size_t row = static_cast<size_t>(p) * entries;
  addSparseFramePartialSums(C + row, entryColumns + row, entries, W, lane, kWarp, y);
#pragma unroll
  for (int o = 0; o < kPortableMaxOutputs; ++o)
    for (int offset = kWarp / 2; offset > 0; offset /= 2) y[o] += __shfl_down_sync(0xffffffffu, y[o], offset);
  if (lane == 0) finishFramePoint<Dim>(y, W.finish, W.origin, out + static_cast<size_t>(p) * Dim);
}

__global__ void somiglianaRowsKernel(const PortableFace* __restrict__ faces, int numFaces, int numVertices,
                                     const double* __restrict__ points, int numPoints, double* rows,
                                     double* winding) {
  const int p = blockIdx.x * blockDim.x + threadIdx.x;
  if (p >= numPoints) return;
  const double x[3] = {points[3 * p], points[3 * p + 1], points[3 * p + 2]};
  winding[p] = integrateSomiglianaRowPortable(faces, numFaces, numVertices, x, rows + p, numPoints);
}

// A device allocation freed on scope exit.
template <typename T>
struct DeviceArray {
  T* data = nullptr;
  explicit DeviceArray(size_t count) { check(cudaMalloc(&data, std::max<size_t>(1, count) * sizeof(T)), "cudaMalloc"); }
  ~DeviceArray() { cudaFree(data); }
  DeviceArray(const DeviceArray&) = delete;
  DeviceArray& operator=(const DeviceArray&) = delete;
};

}  // namespace

DeviceInfo queryDevice() {
  DeviceInfo info;
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount(&count);
  if (status == cudaErrorNoDevice || (status == cudaSuccess && count == 0)) {
    info.reason = "no CUDA device found";
    return info;
  }
  if (status == cudaErrorInsufficientDriver) {
    info.reason = "no NVIDIA driver, or one older than the CUDA runtime this was built with";
    return info;
  }
  if (status != cudaSuccess) {
    info.reason = std::string("CUDA unavailable: ") + cudaGetErrorString(status);
    return info;
  }
  cudaDeviceProp properties;
  check(cudaGetDeviceProperties(&properties, 0), "cudaGetDeviceProperties");
  info.name = properties.name;
  info.memoryBytes = properties.totalGlobalMem;
  info.computeCapability = properties.major * 10 + properties.minor;
  // A device older than every architecture this was built for has no code to run.
  cudaFuncAttributes attributes;
  if (cudaFuncGetAttributes(&attributes, frameKernel<float, 3>) != cudaSuccess) {
    cudaGetLastError();  // clear the error
    info.reason = info.name + " (compute capability " + std::to_string(properties.major) + "." +
                  std::to_string(properties.minor) +
                  ") has no kernel image in this build: rebuild with CMAKE_CUDA_ARCHITECTURES including it";
    return info;
  }
  info.available = true;
  return info;
}

struct DeviceFrame {
  void* coordinates = nullptr;
  double* out = nullptr;
  double* weights = nullptr;  // main weights then tail weights
  size_t weightCapacity = 0;
  bool isFloat = false;
  int rows = 0, columns = 0;
  int32_t* entryColumns = nullptr;  // sparse rows: `stored` columns per row; null: dense
  int stored = 0;
};

DeviceFrame* uploadCoordinates(const void* data, const int32_t* entryColumns, bool isFloat, int rows, int stored,
                               int columns) {
  auto* frame = new DeviceFrame{nullptr, nullptr, nullptr, 0, isFloat, rows, columns, nullptr, stored};
  try {
    const size_t entries = static_cast<size_t>(rows) * stored;
    const size_t bytes = entries * (isFloat ? sizeof(float) : sizeof(double));
    check(cudaMalloc(&frame->coordinates, std::max<size_t>(1, bytes)), "cudaMalloc (coordinates)");
    check(cudaMemcpy(frame->coordinates, data, bytes, cudaMemcpyHostToDevice), "cudaMemcpy (coordinates)");
    if (entryColumns) {
      check(cudaMalloc(&frame->entryColumns, std::max<size_t>(1, entries * sizeof(int32_t))),
            "cudaMalloc (entry columns)");
      check(cudaMemcpy(frame->entryColumns, entryColumns, entries * sizeof(int32_t), cudaMemcpyHostToDevice),
            "cudaMemcpy (entry columns)");
    }
    check(cudaMalloc(&frame->out, std::max<size_t>(1, static_cast<size_t>(rows) * 3 * sizeof(double))),
          "cudaMalloc (frame output)");
  } catch (...) {
    releaseCoordinates(frame);
    throw;
  }
  return frame;
}

void releaseCoordinates(DeviceFrame* frame) noexcept {
  if (!frame) return;
  cudaFree(frame->coordinates);
  cudaFree(frame->out);
  cudaFree(frame->weights);
  cudaFree(frame->entryColumns);
  delete frame;
}

void evaluateFrame(DeviceFrame* frame, const FrameLaunch& launch, double* out) {
  const size_t mainCount = static_cast<size_t>(launch.mainColumns) * (launch.outputs - launch.mainOffset);
  const size_t tailCount = static_cast<size_t>(frame->columns - launch.mainColumns) * launch.outputs;
  if (mainCount + tailCount > frame->weightCapacity) {
    cudaFree(frame->weights);
    frame->weights = nullptr;
    frame->weightCapacity = 0;
    check(cudaMalloc(&frame->weights, (mainCount + tailCount) * sizeof(double)), "cudaMalloc (weights)");
    frame->weightCapacity = mainCount + tailCount;
  }
  check(cudaMemcpy(frame->weights, launch.mainWeights, mainCount * sizeof(double), cudaMemcpyHostToDevice),
        "cudaMemcpy (weights)");
  check(cudaMemcpy(frame->weights + mainCount, launch.tailWeights, tailCount * sizeof(double),
                   cudaMemcpyHostToDevice),
        "cudaMemcpy (weights)");
  const int pointsPerBlock = kFrameBlock / kWarp;
  const int blocks = (frame->rows + pointsPerBlock - 1) / pointsPerBlock;
  if (blocks > 0) {
    const PortableFrameWeights W{frame->weights, frame->weights + mainCount, frame->columns, launch.mainColumns,
                                 launch.mainOffset, launch.outputs,
                                 {launch.origin[0], launch.origin[1], launch.origin[2]}, launch.finish};
    const auto* floats = static_cast<const float*>(frame->coordinates);
    const auto* doubles = static_cast<const double*>(frame->coordinates);
    const int32_t* sparse = frame->entryColumns;
    const int n = frame->stored;
    if (sparse && frame->isFloat && launch.dim == 3)
      sparseFrameKernel<float, 3><<<blocks, kFrameBlock>>>(floats, sparse, n, frame->rows, W, frame->out);
    else if (sparse && frame->isFloat)
      sparseFrameKernel<float, 2><<<blocks, kFrameBlock>>>(floats, sparse, n, frame->rows, W, frame->out);
    else if (sparse && launch.dim == 3)
      sparseFrameKernel<double, 3><<<blocks, kFrameBlock>>>(doubles, sparse, n, frame->rows, W, frame->out);
    else if (sparse)
      sparseFrameKernel<double, 2><<<blocks, kFrameBlock>>>(doubles, sparse, n, frame->rows, W, frame->out);
    else if (frame->isFloat && launch.dim == 3)
      frameKernel<float, 3><<<blocks, kFrameBlock>>>(floats, frame->rows, W, frame->out);
    else if (frame->isFloat)
      frameKernel<float, 2><<<blocks, kFrameBlock>>>(floats, frame->rows, W, frame->out);
    else if (launch.dim == 3)
      frameKernel<double, 3><<<blocks, kFrameBlock>>>(doubles, frame->rows, W, frame->out);
    else
      frameKernel<double, 2><<<blocks, kFrameBlock>>>(doubles, frame->rows, W, frame->out);
    check(cudaGetLastError(), "frame kernel launch");
  }
  check(cudaMemcpy(out, frame->out, static_cast<size_t>(frame->rows) * launch.dim * sizeof(double),
                   cudaMemcpyDeviceToHost),
        "cudaMemcpy (frame output)");
}

void integrateSomiglianaRows(const PortableFace* faces, int numFaces, int numVertices, const double* points,
                             int numPoints, double* rows, double* winding) {
  const size_t columns = static_cast<size_t>(numVertices) * kPortableVertexTerms +
                         static_cast<size_t>(numFaces) * kPortableFaceTerms + kPortableAffineTerms;
  DeviceArray<PortableFace> deviceFaces(numFaces);
  DeviceArray<double> devicePoints(static_cast<size_t>(numPoints) * 3), deviceRows(columns * numPoints),
      deviceWinding(numPoints);
  check(cudaMemcpy(deviceFaces.data, faces, numFaces * sizeof(PortableFace), cudaMemcpyHostToDevice),
        "cudaMemcpy (faces)");
  check(cudaMemcpy(devicePoints.data, points, numPoints * 3 * sizeof(double), cudaMemcpyHostToDevice),
        "cudaMemcpy (points)");
  const int blocks = (numPoints + kPrecomputeBlock - 1) / kPrecomputeBlock;
  if (blocks > 0) {
    somiglianaRowsKernel<<<blocks, kPrecomputeBlock>>>(deviceFaces.data, numFaces, numVertices, devicePoints.data,
                                                       numPoints, deviceRows.data, deviceWinding.data);
    check(cudaGetLastError(), "precompute kernel launch");
  }
  check(cudaMemcpy(rows, deviceRows.data, columns * numPoints * sizeof(double), cudaMemcpyDeviceToHost),
        "cudaMemcpy (rows)");
  check(cudaMemcpy(winding, deviceWinding.data, numPoints * sizeof(double), cudaMemcpyDeviceToHost),
        "cudaMemcpy (winding)");
}

}  // namespace cuda_device
}  // namespace somicage
