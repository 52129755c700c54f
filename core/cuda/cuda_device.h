// The CUDA side of core/cuda/cuda_backend.h behind plain pointers: no Eigen (nvcc never compiles Eigen here) and
// no CUDA types (the rest of the project never includes a CUDA header). cuda_device.cu implements it;
// cuda_device_stub.cpp stands in when the project is built without CUDA. Use cuda_backend.h instead.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "coordinates/somigliana_row_portable.h"
#include "deform/frame_finish.h"

namespace somicage {

// A CUDA call failed: the message names the call and the driver's explanation.
class CudaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

namespace cuda_device {

struct DeviceInfo {
  bool available = false;
  std::string reason;  // why not, when unavailable
  std::string name;
  std::size_t memoryBytes = 0;
  int computeCapability = 0;  // major * 10 + minor
};

DeviceInfo queryDevice();

// The coordinate matrix C on the device (row-major, float or double) and an output buffer. Sparse rows
// (coordinate_layout.h): data holds `stored` values per row and entryColumns (rows by stored) their columns of C's
// `columns`; dense: entryColumns is null and stored == columns.
struct DeviceFrame;
DeviceFrame* uploadCoordinates(const void* data, const int32_t* entryColumns, bool isFloat, int rows, int stored,
                               int columns);
void releaseCoordinates(DeviceFrame* frame) noexcept;

// The weights of one frame, one row of outputs per column of C: mainWeights is mainColumns by
// (outputs - mainOffset), tailWeights is (columns - mainColumns) by outputs, both row-major.
struct FrameLaunch {
  const double* mainWeights;
  const double* tailWeights;
  int mainColumns, mainOffset, outputs, dim;
  double origin[3];  // FrameWeights::origin, zeros when it is empty
  FrameFinish finish;
};
// out: rows by dim, row-major (frame_evaluation.h: y = C W, then o + T^-1 b for FrameFinish::SolveT).
void evaluateFrame(DeviceFrame* frame, const FrameLaunch& launch, double* out);

// Rows of nu-independent terms for numPoints points (row-major numPoints by 3), written column-major:
// term k of point p at rows[k * numPoints + p]; winding numbers in winding[p].
void integrateSomiglianaRows(const PortableFace* faces, int numFaces, int numVertices, const double* points,
                             int numPoints, double* rows, double* winding);

}  // namespace cuda_device
}  // namespace somicage
