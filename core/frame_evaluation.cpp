#include "frame_evaluation.h"

#include <omp.h>

#include <Eigen/LU>
#include <algorithm>
#include <vector>

#include "errors.h"

namespace somicage {

FrameCoordinates makeFrameCoordinates(CoordinateMatrix<double> C, int mainColumns, bool floatStorage) {
  FrameCoordinates frame;
  frame.mainColumns = mainColumns;
  if (floatStorage)
    frame.floats = C.cast<float>();
  else
    frame.doubles = std::move(C);
  return frame;
}

Eigen::VectorXd tOutputsFromMatrix(const Eigen::MatrixXd& M) {
  const Eigen::MatrixXd S = 0.5 * (M + M.transpose()), A = 0.5 * (M - M.transpose());
  Eigen::VectorXd y(M.rows() * M.rows());
  if (M.rows() == 3)
    y << S(0, 0), S(1, 1), S(2, 2), S(0, 1), S(0, 2), S(1, 2), A(2, 1), A(0, 2), A(1, 0);
  else
    y << S(0, 0), S(1, 1), S(0, 1), A(0, 1);
  return y;
}

namespace {

constexpr int kMaxOutputs = 12;  // d * d + d for d = 3

// W transposed into contiguous rows of C's scalar type, one per output, so that every output is a dot product of
// two contiguous arrays; and, per group of up to three outputs, the range of C's columns where W is not zero.
// The local variant's T(x) outputs, for instance, only involve the vertex columns (about 60% of C).
template <typename Scalar>
struct PreparedWeights {
  struct Group {
    int firstOutput, count, begin, end;  // outputs [firstOutput, firstOutput + count), columns [begin, end)
  };
  int mainColumns, tailColumns, outputs;
  std::vector<Scalar> mainRows;  // (outputs) rows of mainColumns, zero for outputs before mainOffset
  Eigen::MatrixXd tail;          // tailColumns by outputs, in double: the tail is a handful of columns
  std::vector<Group> groups;

  PreparedWeights(const FrameWeights& W, int mainColumns_)
      : mainColumns(mainColumns_), tailColumns(static_cast<int>(W.tail.rows())), outputs(W.outputs), tail(W.tail) {
    mainRows.assign(static_cast<size_t>(outputs) * mainColumns, Scalar(0));
    for (int o = W.mainOffset; o < outputs; ++o)
      for (int k = 0; k < mainColumns; ++k)
        mainRows[static_cast<size_t>(o) * mainColumns + k] = static_cast<Scalar>(W.main(k, o - W.mainOffset));
    for (int first = W.mainOffset; first < outputs; first += 3) {
      Group g{first, std::min(3, outputs - first), mainColumns, 0};
      for (int o = first; o < first + g.count; ++o)
        for (int k = 0; k < mainColumns; ++k)
          if (W.main(k, o - W.mainOffset) != 0) g.begin = std::min(g.begin, k), g.end = std::max(g.end, k + 1);
      if (g.begin < g.end) groups.push_back(g);
    }
  }
  const Scalar* row(int output) const { return mainRows.data() + static_cast<size_t>(output) * mainColumns; }
};

// Up to three dot products of c with w0, w1, w2 over [0, n), sharing the loads of c. The reduction is vectorised
// (omp simd), in a fixed order for a given build: the result does not depend on the thread count.
template <typename Scalar>
void dot3(const Scalar* c, const Scalar* w0, const Scalar* w1, const Scalar* w2, int n, int count, double* out) {
  Scalar s0 = 0, s1 = 0, s2 = 0;
  if (count == 3) {
#pragma omp simd reduction(+ : s0, s1, s2)
    for (int k = 0; k < n; ++k) s0 += c[k] * w0[k], s1 += c[k] * w1[k], s2 += c[k] * w2[k];
  } else if (count == 2) {
#pragma omp simd reduction(+ : s0, s1)
    for (int k = 0; k < n; ++k) s0 += c[k] * w0[k], s1 += c[k] * w1[k];
  } else {
#pragma omp simd reduction(+ : s0)
    for (int k = 0; k < n; ++k) s0 += c[k] * w0[k];
  }
  out[0] += s0;
  if (count > 1) out[1] += s1;
  if (count > 2) out[2] += s2;
}

template <int Dim>
void finish(const double* y, bool solve, double* out) {
  if (!solve) {
    for (int a = 0; a < Dim; ++a) out[a] = y[a];
    return;
  }
  Eigen::Matrix<double, Dim, Dim> T;  // S + A (frame_evaluation.h)
  if constexpr (Dim == 3)
    T << y[0], y[3] - y[8], y[4] + y[7], y[3] + y[8], y[1], y[5] - y[6], y[4] - y[7], y[5] + y[6], y[2];
  else
    T << y[0], y[2] + y[3], y[2] - y[3], y[1];
  const Eigen::Map<const Eigen::Matrix<double, Dim, 1>> rhs(y + Dim * Dim);
  Eigen::Map<Eigen::Matrix<double, Dim, 1>> result(out);
  result = T.inverse() * rhs;
}

template <typename Scalar, int Dim>
void evaluate(const CoordinateMatrix<Scalar>& C, const PreparedWeights<Scalar>& W, int threads,
              Eigen::Matrix<double, Eigen::Dynamic, Dim, Eigen::RowMajor>& out) {
  const int numPoints = static_cast<int>(C.rows());
  const bool solve = W.outputs == Dim * Dim + Dim;
#pragma omp parallel for schedule(static, 256) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (int p = 0; p < numPoints; ++p) {
    const Scalar* c = C.row(p).data();
    double y[kMaxOutputs] = {0};
    for (const auto& g : W.groups) {
      const int o = g.firstOutput;
      dot3(c + g.begin, W.row(o) + g.begin, W.row(std::min(o + 1, W.outputs - 1)) + g.begin,
           W.row(std::min(o + 2, W.outputs - 1)) + g.begin, g.end - g.begin, g.count, y + o);
    }
    for (int k = 0; k < W.tailColumns; ++k) {
      const double ck = static_cast<double>(c[W.mainColumns + k]);
      if (ck != 0)
        for (int o = 0; o < W.outputs; ++o) y[o] += ck * W.tail(k, o);
    }
    finish<Dim>(y, solve, out.row(p).data());
  }
}

template <typename Scalar>
void evaluateScalar(const CoordinateMatrix<Scalar>& C, int mainColumns, const FrameWeights& W, int dim, int threads,
                    Eigen::MatrixXd& out) {
  const PreparedWeights<Scalar> prepared(W, mainColumns);
  if (dim == 3) {
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> rows(C.rows(), 3);
    evaluate<Scalar, 3>(C, prepared, threads, rows);
    out = rows;
  } else {
    Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> rows(C.rows(), 2);
    evaluate<Scalar, 2>(C, prepared, threads, rows);
    out = rows;
  }
}

}  // namespace

void evaluateFrame(const FrameCoordinates& C, const FrameWeights& W, int dim, int threads, Eigen::MatrixXd& out) {
  SOMICAGE_ASSERT(W.outputs == dim || W.outputs == dim * dim + dim, "a frame has d or d^2 + d outputs");
  SOMICAGE_ASSERT(W.main.rows() == C.mainColumns && W.main.cols() == W.outputs - W.mainOffset, "W_main shape");
  SOMICAGE_ASSERT(W.tail.rows() == C.columns() - C.mainColumns, "W_tail shape");
  if (C.isFloat())
    evaluateScalar(C.floats, C.mainColumns, W, dim, threads, out);
  else
    evaluateScalar(C.doubles, C.mainColumns, W, dim, threads, out);
}

}  // namespace somicage
