#include "deform/jacobian.h"

#include <limits>

#include "base/dual_number.h"
#include "base/errors.h"
#include "deform/frame_point_kernel.h"

namespace somicage {

DeformationGradients::DeformationGradients(const CageDeformer& deformer, const Eigen::MatrixXd& points,
                                           const ProgressCallback& progress)
    : deformer_(deformer), gradients_(deformer.coordinateGradients(points, progress)) {
  SOMICAGE_ASSERT(points.rows() == deformer.numPoints(), "the deformer's points");
  const std::vector<PointRegion>& regions = deformer.diagnostics().regions;
  defined_.assign(static_cast<std::size_t>(points.rows()), 1);
  for (std::size_t p = 0; p < regions.size(); ++p) defined_[p] = regions[p] == PointRegion::Inside;
}

int DeformationGradients::undefinedCount() const {
  int count = 0;
  for (char d : defined_) count += d == 0;
  return count;
}

std::size_t DeformationGradients::bytes() const {
  std::size_t total = defined_.size();
  for (const FrameCoordinates& g : gradients_) total += g.bytes();
  return total;
}

namespace {

// Up to one block of rows (the stable variant's fold check: a few hundred samples, every frame) runs on one thread:
// waking the others costs more than it saves, and the outputs do not depend on the thread count.
constexpr int kSerialRows = 256;

template <int Dim>
void finishPoints(const FrameWeights& W, const CoordinateMatrix<double>& y,
                  const std::vector<CoordinateMatrix<double>>& dy, const std::vector<char>& defined,
                  Eigen::MatrixXd& positions, Eigen::MatrixXd& jacobians) {
  using Dual = dual::Dual<Dim>;
  const int numRows = static_cast<int>(y.rows()), numPoints = static_cast<int>(defined.size());
  double origin[3] = {0, 0, 0};
  for (int a = 0; a < W.origin.size(); ++a) origin[a] = W.origin(a);
  positions.resize(numRows, Dim);
  jacobians.setConstant(numPoints, Dim * Dim, std::numeric_limits<double>::quiet_NaN());
#pragma omp parallel for schedule(static, kSerialRows) if (numRows > kSerialRows)
  for (int p = 0; p < numRows; ++p) {
    Dual yd[kPortableMaxOutputs], f[Dim];
    const bool withGradient = p < numPoints && defined[static_cast<std::size_t>(p)];
    for (int o = 0; o < W.outputs; ++o) {
      yd[o] = Dual(y(p, o));
      if (withGradient)
        for (int b = 0; b < Dim; ++b) yd[o].g[b] = dy[static_cast<std::size_t>(b)](p, o);
    }
    finishFramePoint<Dim>(yd, W.finish, origin, f);
    for (int a = 0; a < Dim; ++a) {
      positions(p, a) = f[a].v;
      if (withGradient)
        for (int b = 0; b < Dim; ++b) jacobians(p, a * Dim + b) = f[a].g[b];
    }
  }
}

}  // namespace

void DeformationGradients::evaluate(const Eigen::MatrixXd& posedVertices, const DeformParams& params,
                                    Eigen::MatrixXd& positions, Eigen::MatrixXd& jacobians) const {
  evaluate(deformer_.frameWeights(posedVertices, params), positions, jacobians);
}

void DeformationGradients::evaluate(const FrameWeights& W, Eigen::MatrixXd& positions,
                                    Eigen::MatrixXd& jacobians) const {
  const FrameCoordinates& C = deformer_.frameCoordinates();
  const int threads = C.rows() > kSerialRows ? 0 : 1;
  CoordinateMatrix<double> y;
  evaluateFrameOutputs(C, W, threads, y);
  std::vector<CoordinateMatrix<double>> dy(gradients_.size());
  for (std::size_t a = 0; a < gradients_.size(); ++a) evaluateFrameOutputs(gradients_[a], W, threads, dy[a]);
  if (dim() == 3)
    finishPoints<3>(W, y, dy, defined_, positions, jacobians);
  else
    finishPoints<2>(W, y, dy, defined_, positions, jacobians);
  blendExteriorPoints(C.exteriorBlends, positions);
}

}  // namespace somicage
