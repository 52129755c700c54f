#include "somigliana_deformer.h"

#include <omp.h>

#include <Eigen/LU>
#include <array>
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

template <int Dim>
class SomiglianaDeformer final : public CageDeformer {
 public:
  using Matrix = Eigen::Matrix<double, Dim, Dim>;
  using Vector = Eigen::Matrix<double, Dim, 1>;
  static constexpr int kOutputs = Dim * Dim + Dim;  // T(x) row-major, then the right-hand side of Eq. 11

  SomiglianaDeformer(Cage rest, Eigen::MatrixXd restPoints, SomiglianaCoordinates coords, int threads)
      : rest_(std::move(rest)), restPoints_(std::move(restPoints)), coords_(std::move(coords)), threads_(threads) {}

  Method method() const override { return Method::Somigliana; }
  int dim() const override { return Dim; }
  int numPoints() const override { return coords_.numPoints(); }

  // Eq. 11: x~ = T(x)^-1 [sum_i R_i T_i R_i^T v~_i + sum_j R_j K_j R_j^T tau~_j], T(x) = sum_i R_i T_i R_i^T.
  // Both sums are linear in the stored nu-independent terms, so one frame is one product of the coordinate
  // matrix (#P by #terms) with a per-frame weight matrix (#terms by kOutputs), then a d by d solve per point.
  void deform(const Eigen::MatrixXd& posed, const DeformParams& params, Eigen::MatrixXd& out) const override {
    validateDeformParams(params);
    SOMICAGE_ASSERT(posed.rows() == rest_.numVertices() && posed.cols() == Dim, "posed cage matches the rest cage");
    const BoundaryConditions bc = computeBoundaryConditions(rest_, posed, params);
    const Eigen::MatrixXd weights = frameWeights(posed, params, bc);

    const int numPoints = coords_.numPoints();
    out.resize(numPoints, Dim);
    const Eigen::MatrixXd& G = bc.global.rotation;
    const int blockSize = 64;
    const int numBlocks = (numPoints + blockSize - 1) / blockSize;
    const int threads = threads_ > 0 ? threads_ : omp_get_max_threads();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int block = 0; block < numBlocks; ++block) {
      const int begin = block * blockSize, count = std::min(blockSize, numPoints - begin);
      const Eigen::Matrix<double, Eigen::Dynamic, kOutputs, Eigen::RowMajor> y =
          coords_.values.middleRows(begin, count) * weights;
      for (int r = 0; r < count; ++r) {
        const int p = begin + r;
        if (coords_.winding(p) < 0.5) {
          // Outside the cage sum_i T_i -> 0 and Eq. 11 is undefined; such points follow the global similarity.
          out.row(p) = (bc.global.scale * G * restPoint(p) + bc.global.translation).transpose();
          continue;
        }
        const Eigen::Map<const Eigen::Matrix<double, Dim, Dim, Eigen::RowMajor>> T(y.row(r).data());
        const Eigen::Map<const Vector> rhs(y.row(r).data() + Dim * Dim);
        out.row(p) = (Matrix(T).inverse() * rhs).transpose();
      }
    }
  }

 private:
  Eigen::VectorXd restPoint(int p) const { return restPoints_.row(p).transpose(); }

  Eigen::MatrixXd frameWeights(const Eigen::MatrixXd& posed, const DeformParams& params,
                               const BoundaryConditions& bc) const {
    const int vertexTerms = vertexTermCount(Dim);
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(coords_.values.cols(), kOutputs);
    const std::vector<Eigen::MatrixXd> basis = vertexTermBasis(Dim, params.nu);
    for (int i = 0; i < rest_.numVertices(); ++i) {
      const Matrix R = bc.vertexRotations[i];
      const Vector v = posed.row(i).transpose();
      for (int k = 0; k < vertexTerms; ++k) {
        const Matrix rotated = R * basis[k] * R.transpose();
        const int row = coords_.vertexOffset(i) + k;
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b) W(row, a * Dim + b) = rotated(a, b);
        W.row(row).tail<Dim>() = (rotated * v).transpose();
      }
    }
    // R_j K_j R_j^T tau~_j = s_j R_j K_j n_j = s_j R_j (k1 S_j n_j + k2 q_j) (Eq. 14 and docs/method.md).
    const NuCoefficients c = nuCoefficients(Dim, params.nu);
    for (int j = 0; j < rest_.numFaces(); ++j) {
      const Matrix R = bc.faceRotations[j];
      const double s = bc.tractionScales(j);
      const int row = coords_.faceOffset(j);
      W.row(row).tail<Dim>() = (s * c.k1 * R * coords_.restNormals.row(j).transpose()).transpose();
      for (int a = 0; a < Dim; ++a) W.row(row + 1 + a).tail<Dim>() = (s * c.k2 * R.col(a)).transpose();
    }
    return W;
  }

  Cage rest_;
  Eigen::MatrixXd restPoints_;
  SomiglianaCoordinates coords_;
  int threads_;
};

}  // namespace

std::unique_ptr<CageDeformer> makeSomiglianaDeformer(const Cage& restCage, const Eigen::MatrixXd& points,
                                                     const PrecomputeOptions& options,
                                                     const ProgressCallback& progress) {
  IntegrationOptions integration = options.integration;
  if (integration.threads == 0) integration.threads = options.threads;
  SomiglianaCoordinates coords = computeSomiglianaCoordinates(restCage, points, integration, progress);
  if (restCage.dim() == 3)
    return std::make_unique<SomiglianaDeformer<3>>(restCage, points, std::move(coords), options.threads);
  return std::make_unique<SomiglianaDeformer<2>>(restCage, points, std::move(coords), options.threads);
}

}  // namespace somicage
