#include "somigliana_deformer.h"

#include <vector>

#include "boundary_conditions.h"
#include "errors.h"

namespace somicage {

namespace {

// The d by d matrices E_k with T_i = sum_k t_k E_k(nu), t_k the stored terms of vertex i (somigliana_coordinates.h).
std::vector<Eigen::MatrixXd> vertexTermBasis(int d, double nu) {
  const NuCoefficients c = nuCoefficients(d, nu);
  std::vector<Eigen::MatrixXd> basis;
  auto unit = [d](int r, int s) {
    Eigen::MatrixXd E = Eigen::MatrixXd::Zero(d, d);
    E(r, s) = 1;
    return E;
  };
  basis.push_back(c.alpha * Eigen::MatrixXd::Identity(d, d));  // D
  if (d == 3) {
    basis.push_back(c.alpha * (unit(2, 1) - unit(1, 2)));  // omega_x: w -> e_x x w
    basis.push_back(c.alpha * (unit(0, 2) - unit(2, 0)));  // omega_y
    basis.push_back(c.alpha * (unit(1, 0) - unit(0, 1)));  // omega_z
    for (int a = 0; a < 3; ++a) basis.push_back(c.beta * unit(a, a));
    const int offDiagonal[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    for (const auto& rs : offDiagonal) basis.push_back(c.beta * (unit(rs[0], rs[1]) + unit(rs[1], rs[0])));
  } else {
    basis.push_back(c.alpha * (unit(0, 1) - unit(1, 0)));  // A01
    basis.push_back(c.beta * unit(0, 0));
    basis.push_back(c.beta * unit(1, 1));
    basis.push_back(c.beta * (unit(0, 1) + unit(1, 0)));
  }
  return basis;
}

// A d by d matrix, row-major, into columns [0, d^2) of row `row` of W.
void setMatrixColumns(const Eigen::MatrixXd& M, Eigen::MatrixXd& W, int row) {
  const int d = static_cast<int>(M.rows());
  for (int a = 0; a < d; ++a)
    for (int b = 0; b < d; ++b) W(row, a * d + b) = M(a, b);
}

// The coordinate matrix C of frame_evaluation.h for the Somigliana deformer:
//   main = the stored integrals (vertex terms, then face terms; somigliana_coordinates.h),
//   tail = [ sum_i of the vertex terms | x | 1 ].
// The sums give T(x) = R (sum_i T_i) R^T in one small product for the global variant. Points outside the cage
// (winding < 1/2) have no Somigliana coordinates (sum_i T_i -> 0, Eq. 11 is undefined): their row is zero except
// [x | 1], which the weights turn into T = I, b = s R x + t, the global similarity of the cage.
template <typename Scalar>
CoordinateMatrix<Scalar> frameMatrix(const SomiglianaCoordinates& coords, const Eigen::MatrixXd& points) {
  const int d = coords.dim, terms = vertexTermCount(d), main = static_cast<int>(coords.values.cols());
  const int columns = main + terms + d + 1;
  CoordinateMatrix<Scalar> C = CoordinateMatrix<Scalar>::Zero(coords.numPoints(), columns);
  for (int p = 0; p < coords.numPoints(); ++p) {
    if (coords.winding(p) < 0.5) {
      C.row(p).segment(main + terms, d) = points.row(p).cast<Scalar>();
      C(p, columns - 1) = 1;
      continue;
    }
    C.row(p).head(main) = coords.values.row(p).cast<Scalar>();
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(terms);
    for (int i = 0; i < coords.numVertices; ++i)
      sum += coords.values.row(p).segment(coords.vertexOffset(i), terms).transpose();
    C.row(p).segment(main, terms) = sum.cast<Scalar>().transpose();
  }
  return C;
}

FrameCoordinates buildFrameCoordinates(const SomiglianaCoordinates& coords, const Eigen::MatrixXd& points,
                                       bool floatStorage) {
  FrameCoordinates frame;
  frame.mainColumns = static_cast<int>(coords.values.cols());
  if (floatStorage)
    frame.floats = frameMatrix<float>(coords, points);
  else
    frame.doubles = frameMatrix<double>(coords, points);
  return frame;
}

class SomiglianaDeformer final : public CageDeformer {
 public:
  SomiglianaDeformer(Cage rest, const SomiglianaCoordinates& coords, const Eigen::MatrixXd& points,
                     const PrecomputeOptions& options)
      : CageDeformer(buildFrameCoordinates(coords, points, options.floatStorage), options.threads),
        rest_(std::move(rest)),
        restNormals_(coords.restNormals),
        vertexOffsets_(coords.numVertices),
        faceOffsets_(coords.numFaces) {
    for (int i = 0; i < coords.numVertices; ++i) vertexOffsets_[i] = coords.vertexOffset(i);
    for (int j = 0; j < coords.numFaces; ++j) faceOffsets_[j] = coords.faceOffset(j);
  }

  Method method() const override { return Method::Somigliana; }
  int dim() const override { return rest_.dim(); }

  // Eq. 11: x~ = T(x)^-1 [sum_i R_i T_i R_i^T v~_i + sum_j R_j K_j R_j^T tau~_j], T(x) = sum_i R_i T_i R_i^T.
  // Both sums are linear in the stored nu-independent terms t_k (T_i = sum_k t_k E_k), so their weights are
  // R_i E_k R_i^T (for T) and R_i E_k R_i^T v~_i (for the right-hand side); the face terms give
  // R_j K_j R_j^T tau~_j = s_j R_j K_j n_j = s_j R_j (k1 S_j n_j + k2 q_j) (Eq. 14, docs/method.md).
  FrameWeights frameWeights(const Eigen::MatrixXd& posed, const DeformParams& params) const override {
    validateDeformParams(params);
    const int d = dim(), terms = vertexTermCount(d);
    SOMICAGE_ASSERT(posed.rows() == rest_.numVertices() && posed.cols() == d, "posed cage matches the rest cage");
    const BoundaryConditions bc = computeBoundaryConditions(rest_, posed, params);
    const std::vector<Eigen::MatrixXd> basis = vertexTermBasis(d, params.nu);
    const bool global = params.blend == 0;  // every R_i = R: T(x) comes from the per-point sums in the tail

    FrameWeights W;
    W.outputs = d * d + d;
    W.mainOffset = global ? d * d : 0;
    const int rhs = W.outputs - W.mainOffset - d;  // where the right-hand side starts in W.main
    W.main = Eigen::MatrixXd::Zero(coordinates_.mainColumns, W.outputs - W.mainOffset);
    W.tail = Eigen::MatrixXd::Zero(terms + d + 1, W.outputs);
    for (int i = 0; i < rest_.numVertices(); ++i) {
      const Eigen::MatrixXd& R = global ? bc.global.rotation : bc.vertexRotations[i];
      const Eigen::VectorXd v = posed.row(i).transpose();
      for (int k = 0; k < terms; ++k) {
        const Eigen::MatrixXd rotated = R * basis[k] * R.transpose();
        const int row = vertexOffsets_[i] + k;
        if (!global) setMatrixColumns(rotated, W.main, row);
        W.main.row(row).segment(rhs, d) = (rotated * v).transpose();
      }
    }
    const NuCoefficients c = nuCoefficients(d, params.nu);
    for (int j = 0; j < rest_.numFaces(); ++j) {
      const Eigen::MatrixXd& R = bc.faceRotations[j];
      const double s = bc.tractionScales(j);
      const int row = faceOffsets_[j];
      W.main.row(row).segment(rhs, d) = (s * c.k1 * R * restNormals_.row(j).transpose()).transpose();
      for (int a = 0; a < d; ++a) W.main.row(row + 1 + a).segment(rhs, d) = (s * c.k2 * R.col(a)).transpose();
    }
    if (global)
      for (int k = 0; k < terms; ++k)
        setMatrixColumns(bc.global.rotation * basis[k] * bc.global.rotation.transpose(), W.tail, k);
    // Outside points: T = I and b = s R x + t.
    const Eigen::MatrixXd sR = bc.global.scale * bc.global.rotation;
    for (int a = 0; a < d; ++a) W.tail.row(terms + a).tail(d) = sR.col(a).transpose();
    setMatrixColumns(Eigen::MatrixXd::Identity(d, d), W.tail, terms + d);
    W.tail.row(terms + d).tail(d) = bc.global.translation.transpose();
    return W;
  }

 private:
  Cage rest_;
  Eigen::MatrixXd restNormals_;
  std::vector<int> vertexOffsets_, faceOffsets_;
};

}  // namespace

std::unique_ptr<CageDeformer> makeSomiglianaDeformer(const Cage& restCage, const Eigen::MatrixXd& points,
                                                     const PrecomputeOptions& options,
                                                     const ProgressCallback& progress) {
  IntegrationOptions integration = options.integration;
  if (integration.threads == 0) integration.threads = options.threads;
  const SomiglianaCoordinates coords = computeSomiglianaCoordinates(restCage, points, integration, progress);
  return makeSomiglianaDeformer(restCage, coords, points, options);
}

std::unique_ptr<CageDeformer> makeSomiglianaDeformer(const Cage& restCage, const SomiglianaCoordinates& coords,
                                                     const Eigen::MatrixXd& points, const PrecomputeOptions& options) {
  SOMICAGE_ASSERT(coords.numPoints() == points.rows() && coords.numVertices == restCage.numVertices(),
                  "coordinates belong to these points and this cage");
  return std::make_unique<SomiglianaDeformer>(restCage, coords, points, options);
}

}  // namespace somicage
