// The Eigen-facing half of the CUDA backend (compiled by the host compiler in every build); the device half is
// cuda_device.cu, or cuda_device_stub.cpp in a build without CUDA.
#include "cuda/cuda_backend.h"

#include <omp.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "base/errors.h"
#include "base/parallel_failure.h"
#include "geometry/triangle_integrals.h"

namespace somicage {

const CudaStatus& cudaStatus() {
  static const CudaStatus status = [] {
    CudaStatus s;
    try {
      const cuda_device::DeviceInfo info = cuda_device::queryDevice();
      s.available = info.available;
      s.reason = info.reason;
      s.deviceName = info.name;
      s.memoryBytes = info.memoryBytes;
      s.computeCapability = info.computeCapability;
    } catch (const CudaError& e) {
      s.reason = e.what();
    }
    return s;
  }();
  return status;
}

namespace {

void requireDevice() {
  if (!cudaStatus().available) throw CudaError("no usable CUDA device: " + cudaStatus().reason);
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------------
// Frame evaluation
// ---------------------------------------------------------------------------------------------------------------

CudaFrameEvaluator::CudaFrameEvaluator(const FrameCoordinates& C, int dim)
    : rows_(C.rows()), columns_(C.columns()), mainColumns_(C.mainColumns), dim_(dim), blends_(C.exteriorBlends) {
  SOMICAGE_ASSERT(dim == 2 || dim == 3, "a frame is 2D or 3D");
  requireDevice();
  const void* data = C.isFloat() ? static_cast<const void*>(C.floats.data()) : C.doubles.data();
  frame_ = cuda_device::uploadCoordinates(data, C.isSparse() ? C.entryColumns.data() : nullptr, C.isFloat(), rows_,
                                          C.storedColumns(), columns_);
}

CudaFrameEvaluator::~CudaFrameEvaluator() { cuda_device::releaseCoordinates(frame_); }

CudaFrameEvaluator::CudaFrameEvaluator(CudaFrameEvaluator&& other) noexcept
    : frame_(std::exchange(other.frame_, nullptr)),
      rows_(other.rows_),
      columns_(other.columns_),
      mainColumns_(other.mainColumns_),
      dim_(other.dim_),
      blends_(std::move(other.blends_)) {}

CudaFrameEvaluator& CudaFrameEvaluator::operator=(CudaFrameEvaluator&& other) noexcept {
  if (this != &other) {
    cuda_device::releaseCoordinates(frame_);
    frame_ = std::exchange(other.frame_, nullptr);
    rows_ = other.rows_, columns_ = other.columns_, mainColumns_ = other.mainColumns_, dim_ = other.dim_;
    blends_ = std::move(other.blends_);
  }
  return *this;
}

void CudaFrameEvaluator::evaluate(const FrameWeights& W, Eigen::MatrixXd& out) {
  SOMICAGE_ASSERT(frame_ != nullptr, "evaluate() on a moved-from CudaFrameEvaluator");
  SOMICAGE_ASSERT(W.outputs == frameOutputs(W.finish, dim_), "a frame has the outputs of its finish");
  SOMICAGE_ASSERT(W.main.rows() == mainColumns_ && W.main.cols() == W.outputs - W.mainOffset, "W_main shape");
  SOMICAGE_ASSERT(W.tail.rows() == columns_ - mainColumns_ && W.tail.cols() == W.outputs, "W_tail shape");
  // The kernel reads the weights of one column of C contiguously.
  const RowMatrixXd mainWeights = W.main, tailWeights = W.tail;
  RowMatrixXd result(rows_, dim_);
  cuda_device::FrameLaunch launch{mainWeights.data(), tailWeights.data(), mainColumns_, W.mainOffset, W.outputs, dim_,
                                  {0, 0, 0}, W.finish};
  for (int a = 0; a < dim_ && a < W.origin.size(); ++a) launch.origin[a] = W.origin(a);
  cuda_device::evaluateFrame(frame_, launch, result.data());
  out = result;
  blendExteriorPoints(blends_, out);  // on the host: a few rows
}

// ---------------------------------------------------------------------------------------------------------------
// Precompute
// ---------------------------------------------------------------------------------------------------------------

void integrateSomiglianaCoordinatesCuda(const Cage& cage, const Eigen::MatrixXd& points,
                                        const ProgressCallback& progress, const CoordinateRowSink& sink) {
  assertCageAndPoints(cage, points);
  SOMICAGE_ASSERT(cage.dim() == 3, "the CUDA precompute integrates 3D cages; 2D cages use the CPU");
  requireDevice();
  std::vector<PortableFace> faces(cage.numFaces());
  for (int j = 0; j < cage.numFaces(); ++j) {
    const TriangleFrame frame = makeTriangleFrame(
        cage.vertices.row(cage.faces(j, 0)), cage.vertices.row(cage.faces(j, 1)), cage.vertices.row(cage.faces(j, 2)));
    faces[j].frame = frame.kernel;
    for (int k = 0; k < 3; ++k) faces[j].corners[k] = cage.faces(j, k);
  }
  const int numPoints = static_cast<int>(points.rows());
  const int columns = somiglianaLayout(3, cage.numVertices(), cage.numFaces()).integralColumns();
  const int chunk = static_cast<int>(
      std::clamp<long>((256L << 20) / (static_cast<long>(columns) * sizeof(double)), 1, std::max(1, numPoints)));
  const RowMatrixXd rowPoints = points;
  std::vector<double> rows(static_cast<size_t>(chunk) * columns), winding(chunk);
  for (int start = 0; start < numPoints; start += chunk) {
    if (!progress(static_cast<double>(start) / numPoints)) throw Cancelled();
    const int count = std::min(chunk, numPoints - start);
    cuda_device::integrateSomiglianaRows(faces.data(), cage.numFaces(), cage.numVertices(), rowPoints.row(start).data(),
                                         count, rows.data(), winding.data());
    // The device wrote the rows column-major (coalesced); hand each one to the sink contiguous.
    ParallelFailure failure;  // the row buffer allocates and the sink is the caller's: rethrown after the region
#pragma omp parallel
    {
      std::vector<double> row;
      failure.run([&] { row.resize(columns); });
#pragma omp for schedule(static)
      for (int p = 0; p < count; ++p) {
        if (failure.failed() || row.empty()) continue;
        failure.run([&] {
          for (int k = 0; k < columns; ++k) row[k] = rows[static_cast<size_t>(k) * count + p];
          sink(start + p, row.data(), winding[p]);
        });
      }
    }
    failure.rethrow();
  }
  progress(1.0);
}

RowIntegrator cudaRowIntegrator() {
  return [](const Cage& cage, const Eigen::MatrixXd& points, const IntegrationOptions& options,
            const ProgressCallback& progress, const CoordinateRowSink& sink) {
    if (cage.dim() == 3 && options.rule == IntegrationOptions::Rule::ClosedForm)
      integrateSomiglianaCoordinatesCuda(cage, points, progress, sink);
    else
      integrateSomiglianaCoordinates(cage, points, options, progress, sink);
  };
}

FrameDevice cudaFrameDevice() {
  return {"cuda", "cuda",
          [](const CageDeformer& deformer) -> std::unique_ptr<FrameEvaluator> {
            if (!cudaStatus().available) throw FrameDeviceUnavailable(cudaStatus().reason);
            try {
              return std::make_unique<CudaFrameEvaluator>(deformer.frameCoordinates(), deformer.dim());
            } catch (const CudaError& e) {
              throw FrameDeviceUnavailable(e.what());
            }
          },
          [] { return cudaStatus().available ? std::string() : cudaStatus().reason; }, cudaRowIntegrator()};
}

}  // namespace somicage
