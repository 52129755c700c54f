// The optional CUDA backend: the per-frame evaluation (frame_evaluation.h) and the 3D Somigliana precompute
// (somigliana_coordinates.h) on an NVIDIA GPU. A plain C++ header: no CUDA types, and the same API whether or not
// the project was built with CUDA (SOMICAGE_HAVE_CUDA is defined when it was). Without CUDA, or without a usable
// device, cudaStatus() says why and every other call throws CudaError, so callers check cudaStatus() first.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "base/progress.h"
#include "coordinates/somigliana_coordinates.h"
#include "cuda/cuda_device.h"  // CudaError
#include "deform/frame_evaluation.h"
#include "deform/frame_evaluator.h"
#include "geometry/cage.h"

namespace somicage {

struct CudaStatus {
  bool available = false;
  std::string reason;      // why there is no usable device (empty when available)
  std::string deviceName;  // device 0, the one the backend uses
  std::size_t memoryBytes = 0;
  int computeCapability = 0;  // major * 10 + minor, e.g. 90 for an H100
};

// Whether a usable CUDA device exists. Queried once (the first call initialises the driver) and cached.
const CudaStatus& cudaStatus();

// The coordinate matrix C of a deformer, uploaded once; evaluate() then computes a frame on the device from that
// frame's weights, with the same result as evaluateFrame on the CPU: y_p = C_p W accumulated in double (C may be
// float), then T_p^-1 b_p for d^2 + d outputs (Eq. 11), for every row of C; the exterior points are then blended on
// the host (blendExteriorPoints). Each call uploads W (K by at most 12) and downloads the rows' points,
// synchronously. Not thread-safe: one evaluator per thread.
class CudaFrameEvaluator final : public FrameEvaluator {
 public:
  CudaFrameEvaluator(const FrameCoordinates& C, int dim);
  ~CudaFrameEvaluator() override;
  CudaFrameEvaluator(CudaFrameEvaluator&& other) noexcept;
  CudaFrameEvaluator& operator=(CudaFrameEvaluator&& other) noexcept;
  CudaFrameEvaluator(const CudaFrameEvaluator&) = delete;
  CudaFrameEvaluator& operator=(const CudaFrameEvaluator&) = delete;

  // out: #P by d (resized).
  void evaluate(const FrameWeights& W, Eigen::MatrixXd& out) override;

  int dim() const { return dim_; }

 private:
  cuda_device::DeviceFrame* frame_ = nullptr;
  int rows_ = 0, columns_ = 0, mainColumns_ = 0, dim_ = 3;  // rows: #P + 2 #E
  std::vector<ExteriorBlend> blends_;
};

// The CUDA frame device ("cuda", bench key "cuda"): a CudaFrameEvaluator, or FrameDeviceUnavailable with
// cudaStatus().reason when there is no usable device (or the upload fails).
FrameDevice cudaFrameDevice();

// integrateSomiglianaCoordinates with the closed-form rule on the device, for 3D cages: the same rows (the layout of
// C, coordinate_layout.h; double precision, one thread per point summing the faces in the CPU's order) and
// winding numbers, handed to the same kind of sink (called on the host from OpenMP threads, once per point).
// Points go to the device in chunks of at most ~256 MB of rows; progress is reported between chunks and may
// cancel (throws Cancelled).
void integrateSomiglianaCoordinatesCuda(const Cage& cage, const Eigen::MatrixXd& points,
                                        const ProgressCallback& progress, const CoordinateRowSink& sink);

// The row integrator to inject into PrecomputeOptions::rowIntegrator: the device's for 3D closed-form rows, the
// CPU's for 2D cages and the Gauss rule. Needs a usable device (cudaStatus()) for 3D cages.
RowIntegrator cudaRowIntegrator();

}  // namespace somicage
