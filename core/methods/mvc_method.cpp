// Mean value coordinates as a deformation method (method.h): C = the normalised weights (#P by #V), W = v~.
#include <algorithm>
#include <memory>
#include <vector>

#include "base/errors.h"
#include "coordinates/mean_value_coordinates.h"
#include "deform/deformer.h"
#include "methods/method_descriptors.h"

namespace somicage {

namespace {

CoordinateLayout meanValueLayout(int, int numVertices, int numFaces) { return {numVertices, numFaces, 1, 0, 0}; }

class MeanValueDeformer : public CageDeformer {
 public:
  MeanValueDeformer(const Cage& restCage, RowMatrixXd weights, const PrecomputeOptions& options)
      : CageDeformer(makeFrameCoordinates(std::move(weights), restCage.numVertices(), options.floatStorage),
                     options.threads),
        rest_(restCage),
        numVertices_(restCage.numVertices()),
        dim_(restCage.dim()) {}

  Method method() const override { return methods::mvc(); }
  int dim() const override { return dim_; }

  // C's rows are the coordinates themselves; they are defined everywhere, so every row has its gradient.
  std::vector<FrameCoordinates> coordinateGradients(const Eigen::MatrixXd& points,
                                                    const ProgressCallback& progress) const override {
    std::vector<RowMatrixXd> gradients(static_cast<std::size_t>(dim_));
    for (auto& g : gradients) g.resize(points.rows(), numVertices_);
    integrateMeanValueGradients(rest_, points, threads_, progress, [&](int p, const double* const* rows) {
      for (int a = 0; a < dim_; ++a)
        std::copy(rows[a], rows[a] + numVertices_, gradients[static_cast<std::size_t>(a)].row(p).data());
    });
    std::vector<FrameCoordinates> frames;
    for (auto& g : gradients)
      frames.push_back(makeFrameCoordinates(std::move(g), numVertices_, coordinates_.isFloat()));
    return frames;
  }

  FrameWeights frameWeights(const Eigen::MatrixXd& posedVertices, const DeformParams&) const override {
    SOMICAGE_ASSERT(posedVertices.rows() == numVertices_ && posedVertices.cols() == dim_,
                    "the posed cage has the rest cage's vertex count and dimension");
    FrameWeights W;
    W.outputs = dim_;
    W.main = posedVertices;
    W.tail.resize(0, dim_);
    return W;
  }

 private:
  Cage rest_;
  int numVertices_, dim_;
};

std::unique_ptr<CageDeformer> precomputeMeanValue(const Cage& restCage, const Eigen::MatrixXd& points,
                                                  const PrecomputeOptions& options, const ProgressCallback& progress) {
  RowMatrixXd weights = computeMeanValueCoordinates(restCage, points, options.threads, progress);
  return std::make_unique<MeanValueDeformer>(restCage, std::move(weights), options);
}

// The weights are computed in double; float storage converts them while they are still alive.
std::size_t meanValueWorkingBytes(const CoordinateLayout& layout, int, std::size_t points, bool floatStorage, int) {
  return floatStorage ? layout.bytes(points, false) : 0;
}

}  // namespace

namespace methods {

const MethodDescriptor& mvc() {
  static const MethodDescriptor descriptor{"mvc",
                                           "Mean value",
                                           "Mean value coordinates (Ju et al. 2005): smooth, interpolating, affine",
                                           2,
                                           0,
                                           true,
                                           false,
                                           {},
                                           validateDeformParams,
                                           meanValueLayout,
                                           meanValueWorkingBytes,
                                           precomputeMeanValue};
  return descriptor;
}

}  // namespace methods

}  // namespace somicage
