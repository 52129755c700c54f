#include "frame_evaluation.h"

#include <omp.h>

#include <Eigen/LU>
#include <algorithm>

#include "errors.h"

namespace somicage {

namespace {

template <int Dim>
void finishRows(const Eigen::MatrixXd& y, int begin, bool solve, Eigen::MatrixXd& out) {
  for (int r = 0; r < y.rows(); ++r) {
    if (!solve) {
      out.row(begin + r) = y.row(r).head<Dim>();
      continue;
    }
    Eigen::Matrix<double, Dim, Dim> T;
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) T(a, b) = y(r, a * Dim + b);
    const Eigen::Matrix<double, Dim, 1> rhs = y.row(r).segment<Dim>(Dim * Dim).transpose();
    out.row(begin + r) = (T.inverse() * rhs).transpose();
  }
}

template <typename Scalar>
void evaluate(const CoordinateMatrix<Scalar>& C, int mainColumns, const FrameWeights& W, int dim, int threads,
              Eigen::MatrixXd& out) {
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  const Matrix main = W.main.cast<Scalar>(), tail = W.tail.cast<Scalar>();
  const int numPoints = static_cast<int>(C.rows()), tailColumns = static_cast<int>(C.cols()) - mainColumns;
  const bool solve = W.outputs == dim * dim + dim;
  out.resize(numPoints, dim);

  // Blocks of 128 points: big enough to amortise the product's packing of W, small enough for the cache.
  const int blockSize = 128, numBlocks = (numPoints + blockSize - 1) / blockSize;
#pragma omp parallel num_threads(threads > 0 ? threads : omp_get_max_threads())
  {
    Matrix partial;
    Eigen::MatrixXd y;
#pragma omp for schedule(static)
    for (int block = 0; block < numBlocks; ++block) {
      const int begin = block * blockSize, count = std::min(blockSize, numPoints - begin);
      y.setZero(count, W.outputs);
      partial.noalias() = C.block(begin, 0, count, mainColumns) * main;
      y.rightCols(W.outputs - W.mainOffset) = partial.template cast<double>();
      if (tailColumns > 0) {
        partial.noalias() = C.block(begin, mainColumns, count, tailColumns) * tail;
        y += partial.template cast<double>();
      }
      if (dim == 3)
        finishRows<3>(y, begin, solve, out);
      else
        finishRows<2>(y, begin, solve, out);
    }
  }
}

}  // namespace

FrameCoordinates makeFrameCoordinates(CoordinateMatrix<double> C, int mainColumns, bool floatStorage) {
  FrameCoordinates frame;
  frame.mainColumns = mainColumns;
  if (floatStorage)
    frame.floats = C.cast<float>();
  else
    frame.doubles = std::move(C);
  return frame;
}

void evaluateFrame(const FrameCoordinates& C, const FrameWeights& W, int dim, int threads, Eigen::MatrixXd& out) {
  SOMICAGE_ASSERT(W.outputs == dim || W.outputs == dim * dim + dim, "a frame has d or d^2 + d outputs");
  SOMICAGE_ASSERT(W.main.rows() == C.mainColumns && W.main.cols() == W.outputs - W.mainOffset, "W_main shape");
  SOMICAGE_ASSERT(W.tail.rows() == C.columns() - C.mainColumns, "W_tail shape");
  if (C.isFloat())
    evaluate(C.floats, C.mainColumns, W, dim, threads, out);
  else
    evaluate(C.doubles, C.mainColumns, W, dim, threads, out);
}

}  // namespace somicage
