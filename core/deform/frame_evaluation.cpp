#include "deform/frame_evaluation.h"

#include <omp.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "base/cpu_dispatch.h"
#include "base/errors.h"
#include "deform/frame_point_kernel.h"

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
  std::vector<int> tailRows;     // the tail columns whose W row is not zero (the affine terms only in that variant)
  std::vector<Group> groups;
  int steps = 0;                 // SIMD steps of all the groups' passes over one block
  double origin[3] = {0, 0, 0};  // FrameWeights::origin
  FrameFinish finish;

  PreparedWeights(const FrameWeights& W, int mainColumns_)
      : mainColumns(mainColumns_),
        tailColumns(static_cast<int>(W.tail.rows())),
        outputs(W.outputs),
        tail(W.tail),
        finish(W.finish) {
    for (int a = 0; a < 3 && a < W.origin.size(); ++a) origin[a] = W.origin(a);
    for (int k = 0; k < tailColumns; ++k)
      if (!W.tail.row(k).isZero(0)) tailRows.push_back(k);
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
    // The widest group first: its pass brings each row of C in from memory front to back, a pattern the hardware
    // prefetcher follows; the narrower passes after it find the row in L1. Each output's sums are unchanged.
    std::stable_sort(groups.begin(), groups.end(),
                     [](const Group& a, const Group& b) { return a.end - a.begin > b.end - b.begin; });
    constexpr int lanes = 32 / sizeof(Scalar);
    for (const Group& g : groups) steps += (g.end - g.begin) / lanes;
    steps = std::max(steps, 1);
  }
  const Scalar* row(int output) const { return mainRows.data() + static_cast<size_t>(output) * mainColumns; }
};

// A 32-byte SIMD vector of Scalar (GCC/Clang vector extensions: one AVX2 register in the x86-64-v3 copy,
// two SSE halves otherwise). This file is compiled with -ffp-contract=fast, so `sum += c * w` is one FMA.
template <typename Scalar>
struct Simd {
  typedef Scalar Vector __attribute__((vector_size(32)));
  static constexpr int lanes = 32 / sizeof(Scalar);
};

// Points evaluated together: their rows share every load of W.
constexpr int kBlockRows = 4;

// The next block's rows (contiguous bytes [next, end)) asked into L2 a few cache lines per SIMD step of the current
// block's passes (one more than an even spread, which measured best: done within about the first pass).
// FIREHYDRANT, local variant, same machine state: 10.3-10.5 ms prefetching in the first pass only, 7.9-8.5 ms so.
struct BlockPrefetch {
  const char* next = nullptr;
  const char* end = nullptr;
  int linesPerStep = 0;

  void step() {
    for (int l = 0; l < linesPerStep && next < end; ++l, next += 64) __builtin_prefetch(next, 0, 2);
  }
};

// The dot products of Rows rows of C with three rows of W over columns [begin, end), added to sums[r][0..2].
// Every W load serves all rows and every C load three outputs; four rows make 12 accumulators, which with the
// three W vectors and one C vector fill AVX2's 16 registers, so the loop runs at the rate of the FMA units
// rather than of the loads. A row's summation order does not depend on the rows beside it: the result is the
// same whichever block (and so whichever thread) evaluates it.
// Each step also asks for a share of the next block (prefetch.step()), so that memory keeps streaming while the
// passes compute and the next block's first pass does not wait on it.
template <typename Scalar, int Rows>
void dotBlock(const Scalar* const* c, const Scalar* const* w, int begin, int end, double (*sums)[3],
              BlockPrefetch& prefetch) {
  using Vector = typename Simd<Scalar>::Vector;
  constexpr int lanes = Simd<Scalar>::lanes;
  Vector acc[Rows][3] = {};
  int k = begin;
  for (; k + lanes <= end; k += lanes) {
    prefetch.step();
    Vector w0, w1, w2;  // memcpy: unaligned loads without aliasing concerns
    std::memcpy(&w0, w[0] + k, sizeof w0);
    std::memcpy(&w1, w[1] + k, sizeof w1);
    std::memcpy(&w2, w[2] + k, sizeof w2);
    for (int r = 0; r < Rows; ++r) {
      Vector x;
      std::memcpy(&x, c[r] + k, sizeof x);
      acc[r][0] += x * w0;
      acc[r][1] += x * w1;
      acc[r][2] += x * w2;
    }
  }
  for (int r = 0; r < Rows; ++r) {
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int lane = 0; lane < lanes; ++lane) s += acc[r][j][lane];
      for (int kk = k; kk < end; ++kk) s += static_cast<double>(c[r][kk] * w[j][kk]);
      sums[r][j] += s;
    }
  }
}

// The outputs y (kMaxOutputs per row) of Rows consecutive points from `first` on: y = C_main . W_main + C_tail .
// W_tail.
template <typename Scalar, int Rows>
void outputsOfRows(const CoordinateMatrix<Scalar>& C, const PreparedWeights<Scalar>& W, int first,
                   double (*y)[kMaxOutputs]) {
  const Scalar* rows[Rows];
  for (int r = 0; r < Rows; ++r) rows[r] = C.row(first + r).data();
  BlockPrefetch prefetch;
  if (first + 2 * Rows <= C.rows()) {  // a next block exists
    prefetch.next = reinterpret_cast<const char*>(C.row(first + Rows).data());
    prefetch.end = prefetch.next + sizeof(Scalar) * Rows * C.cols();
    prefetch.linesPerStep = static_cast<int>((prefetch.end - prefetch.next + 63) / 64 / W.steps + 1);
  }
  for (const auto& g : W.groups) {
    const int o = g.firstOutput;
    // A group of fewer than three outputs repeats its last W row; the extra sums are dropped.
    const Scalar* w[3] = {W.row(o), W.row(std::min(o + 1, W.outputs - 1)), W.row(std::min(o + 2, W.outputs - 1))};
    double sums[Rows][3] = {};
    dotBlock<Scalar, Rows>(rows, w, g.begin, g.end, sums, prefetch);
    for (int r = 0; r < Rows; ++r)
      for (int j = 0; j < g.count; ++j) y[r][o + j] += sums[r][j];
  }
  for (int r = 0; r < Rows; ++r) {
    for (int k : W.tailRows) {
      const double ck = static_cast<double>(rows[r][W.mainColumns + k]);
      if (ck != 0)
        for (int o = 0; o < W.outputs; ++o) y[r][o] += ck * W.tail(k, o);
    }
  }
}

// A block of `rows` points from `first` on (kBlockRows, or 1 for the last few): the frame's hot loop, dispatched
// (cpu_dispatch.h), for float and for double storage.
template <typename Scalar>
void outputsOfBlock(const CoordinateMatrix<Scalar>& C, const PreparedWeights<Scalar>& W, int first, int rows,
                    double (*y)[kMaxOutputs]) {
  if (rows == kBlockRows)
    outputsOfRows<Scalar, kBlockRows>(C, W, first, y);
  else
    outputsOfRows<Scalar, 1>(C, W, first, y);
}
SOMICAGE_DISPATCH void dispatchedOutputsOfBlock(const CoordinateMatrix<float>& C, const PreparedWeights<float>& W,
                                                int first, int rows, double (*y)[kMaxOutputs]) {
  outputsOfBlock(C, W, first, rows, y);
}
SOMICAGE_DISPATCH void dispatchedOutputsOfBlock(const CoordinateMatrix<double>& C, const PreparedWeights<double>& W,
                                                int first, int rows, double (*y)[kMaxOutputs]) {
  outputsOfBlock(C, W, first, rows, y);
}

template <typename Scalar, int Dim>
void evaluate(const CoordinateMatrix<Scalar>& C, const PreparedWeights<Scalar>& W, int threads,
              Eigen::Matrix<double, Eigen::Dynamic, Dim, Eigen::RowMajor>& out) {
  const int numPoints = static_cast<int>(C.rows()), numBlocks = numPoints / kBlockRows;
#pragma omp parallel for schedule(static, 64) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (int b = 0; b < numBlocks; ++b) {
    double y[kBlockRows][kMaxOutputs] = {};
    dispatchedOutputsOfBlock(C, W, b * kBlockRows, kBlockRows, y);
    for (int r = 0; r < kBlockRows; ++r)
      finishFramePoint<Dim>(y[r], W.finish, W.origin, out.row(b * kBlockRows + r).data());
  }
  for (int p = numBlocks * kBlockRows; p < numPoints; ++p) {
    double y[1][kMaxOutputs] = {};
    dispatchedOutputsOfBlock(C, W, p, 1, y);
    finishFramePoint<Dim>(y[0], W.finish, W.origin, out.row(p).data());
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

template <typename Scalar>
void evaluateOutputs(const CoordinateMatrix<Scalar>& C, int mainColumns, const FrameWeights& W, int threads,
                     CoordinateMatrix<double>& rows) {
  const PreparedWeights<Scalar> prepared(W, mainColumns);
  const int numPoints = static_cast<int>(C.rows()), numBlocks = numPoints / kBlockRows;
  rows.resize(numPoints, W.outputs);
#pragma omp parallel for schedule(static, 64) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (int b = 0; b < numBlocks; ++b) {
    double y[kBlockRows][kMaxOutputs] = {};
    dispatchedOutputsOfBlock(C, prepared, b * kBlockRows, kBlockRows, y);
    for (int r = 0; r < kBlockRows; ++r) std::copy(y[r], y[r] + W.outputs, rows.row(b * kBlockRows + r).data());
  }
  for (int p = numBlocks * kBlockRows; p < numPoints; ++p) {
    double y[1][kMaxOutputs] = {};
    dispatchedOutputsOfBlock(C, prepared, p, 1, y);
    std::copy(y[0], y[0] + W.outputs, rows.row(p).data());
  }
}

// W as frame_point_kernel.h's kernels read it (row-major copies of W_main and W_tail): what a sparse row's entries
// index, with the CUDA kernel's per-row sums (addSparseFramePartialSums, one lane).
struct SparseWeights {
  CoordinateMatrix<double> main, tail;
  PortableFrameWeights portable;

  SparseWeights(const FrameWeights& W, int columns, int mainColumns) : main(W.main), tail(W.tail) {
    portable = {main.data(), tail.data(), columns, mainColumns, W.mainOffset, W.outputs, {0, 0, 0}, W.finish};
    for (int a = 0; a < 3 && a < W.origin.size(); ++a) portable.origin[a] = W.origin(a);
  }
};

// The outputs y (kMaxOutputs, added to) of sparse row r.
template <typename Scalar>
void sparseRowOutputs(const CoordinateMatrix<Scalar>& values, const CoordinateMatrix<std::int32_t>& columns,
                      const SparseWeights& W, int r, double* y) {
  addSparseFramePartialSums(values.row(r).data(), columns.row(r).data(), static_cast<int>(values.cols()), W.portable,
                            0, 1, y);
}

template <typename Scalar, int Dim>
void evaluateSparse(const FrameCoordinates& C, const CoordinateMatrix<Scalar>& values, const FrameWeights& W,
                    int threads, Eigen::MatrixXd& out) {
  const SparseWeights weights(W, C.columns(), C.mainColumns);
  const int numRows = static_cast<int>(values.rows());
  Eigen::Matrix<double, Eigen::Dynamic, Dim, Eigen::RowMajor> rows(numRows, Dim);
#pragma omp parallel for schedule(static, 256) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (int r = 0; r < numRows; ++r) {
    double y[kMaxOutputs] = {};
    sparseRowOutputs(values, C.entryColumns, weights, r, y);
    finishFramePoint<Dim>(y, W.finish, weights.portable.origin, rows.row(r).data());
  }
  out = rows;
}

template <typename Scalar>
void evaluateSparseOutputs(const FrameCoordinates& C, const CoordinateMatrix<Scalar>& values, const FrameWeights& W,
                           int threads, CoordinateMatrix<double>& rows) {
  const SparseWeights weights(W, C.columns(), C.mainColumns);
  const int numRows = static_cast<int>(values.rows());
  rows.resize(numRows, W.outputs);
#pragma omp parallel for schedule(static, 256) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (int r = 0; r < numRows; ++r) {
    double y[kMaxOutputs] = {};
    sparseRowOutputs(values, C.entryColumns, weights, r, y);
    std::copy(y, y + W.outputs, rows.row(r).data());
  }
}

template <typename Scalar>
CoordinateMatrix<Scalar> denseRows(const CoordinateMatrix<Scalar>& values, const CoordinateMatrix<std::int32_t>& columns,
                                   int numColumns) {
  CoordinateMatrix<Scalar> dense = CoordinateMatrix<Scalar>::Zero(values.rows(), numColumns);
  for (Eigen::Index r = 0; r < values.rows(); ++r)
    for (Eigen::Index k = 0; k < values.cols(); ++k) dense(r, columns(r, k)) += values(r, k);
  return dense;
}

}  // namespace

FrameCoordinates denseFrameCoordinates(const FrameCoordinates& C) {
  FrameCoordinates dense;
  dense.mainColumns = C.mainColumns;
  dense.exteriorBlends = C.exteriorBlends;
  if (!C.isSparse()) {
    dense.doubles = C.doubles;
    dense.floats = C.floats;
  } else if (C.isFloat()) {
    dense.floats = denseRows(C.floats, C.entryColumns, C.sparseColumns);
  } else {
    dense.doubles = denseRows(C.doubles, C.entryColumns, C.sparseColumns);
  }
  return dense;
}

void evaluateFrameOutputs(const FrameCoordinates& C, const FrameWeights& W, int threads, CoordinateMatrix<double>& y) {
  SOMICAGE_ASSERT(W.main.rows() == C.mainColumns && W.main.cols() == W.outputs - W.mainOffset, "W_main shape");
  SOMICAGE_ASSERT(W.tail.rows() == C.columns() - C.mainColumns, "W_tail shape");
  if (C.isSparse() && C.isFloat())
    evaluateSparseOutputs(C, C.floats, W, threads, y);
  else if (C.isSparse())
    evaluateSparseOutputs(C, C.doubles, W, threads, y);
  else if (C.isFloat())
    evaluateOutputs(C.floats, C.mainColumns, W, threads, y);
  else
    evaluateOutputs(C.doubles, C.mainColumns, W, threads, y);
}

void evaluateFrame(const FrameCoordinates& C, const FrameWeights& W, int dim, int threads, Eigen::MatrixXd& out) {
  SOMICAGE_ASSERT(W.outputs == frameOutputs(W.finish, dim), "a frame has the outputs of its finish");
  SOMICAGE_ASSERT(W.main.rows() == C.mainColumns && W.main.cols() == W.outputs - W.mainOffset, "W_main shape");
  SOMICAGE_ASSERT(W.tail.rows() == C.columns() - C.mainColumns, "W_tail shape");
  if (C.isSparse()) {
    if (C.isFloat())
      dim == 3 ? evaluateSparse<float, 3>(C, C.floats, W, threads, out)
               : evaluateSparse<float, 2>(C, C.floats, W, threads, out);
    else
      dim == 3 ? evaluateSparse<double, 3>(C, C.doubles, W, threads, out)
               : evaluateSparse<double, 2>(C, C.doubles, W, threads, out);
  } else if (C.isFloat())
    evaluateScalar(C.floats, C.mainColumns, W, dim, threads, out);
  else
    evaluateScalar(C.doubles, C.mainColumns, W, dim, threads, out);
  blendExteriorPoints(C.exteriorBlends, out);
}

void blendExteriorPoints(const std::vector<ExteriorBlend>& blends, Eigen::MatrixXd& out) {
  if (blends.empty()) return;
  const Eigen::Index numPoints = out.rows() - 2 * static_cast<Eigen::Index>(blends.size());
  SOMICAGE_ASSERT(numPoints >= 0, "two extra rows per exterior point");
  for (std::size_t e = 0; e < blends.size(); ++e) {
    const Eigen::Index proxy = numPoints + 2 * static_cast<Eigen::Index>(e);
    out.row(blends[e].point) += blends[e].weight * (out.row(proxy) - out.row(proxy + 1));  // S(x) + w (phi - S)(x_in)
  }
  out.conservativeResize(numPoints, Eigen::NoChange);
}

}  // namespace somicage
