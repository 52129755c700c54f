// Somigliana coordinates (Eq. 8): partition of unity, the reproduction identity (Eq. 7), the nu-independent split,
// thread-count independence and cancellation. Tolerances are stated per test, with the reason.
#include "coordinates/somigliana_coordinates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "base/errors.h"
#include "geometry/kelvin_kernels.h"
#include "geometry/triangle_quadrature.h"
#include "test_shapes.h"

namespace somicage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double traction(double nu, int d) { return std::isinf(nu) ? 2.0 - d : 2 * (1 + d * nu / (1 - 2 * nu)); }  // c, Eq. 6

// Eq. 7: |sum_i T_i v_i + c sum_j K_j n_j - x|, the largest over the points.
double reproductionError(const SomiglianaCoordinates& coords, const Cage& cage, const Eigen::MatrixXd& points,
                         double nu) {
  double worst = 0;
  for (int p = 0; p < coords.numPoints(); ++p) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(cage.dim());
    for (int i = 0; i < cage.numVertices(); ++i)
      x += coords.vertexCoordinate(p, i, nu) * cage.vertices.row(i).transpose();
    for (int j = 0; j < cage.numFaces(); ++j)
      x += traction(nu, cage.dim()) * coords.faceCoordinateTimesNormal(p, j, nu);
    worst = std::max(worst, (x - points.row(p).transpose()).norm());
  }
  return worst;
}

TEST(SomiglianaCoordinates, PartitionOfUnity3D) {
  // Exact integrals: sum_i T_i = I to round-off (docs/closed-form.md table D: <= 1e-15); 1e-12 leaves margin.
  const Cage cage = test::makeBumpySphere(1);
  for (double offset : {0.3, 1e-2, 1e-4, 1e-6}) {
    const Eigen::MatrixXd points = test::pointsNearFaces(cage, 40, offset, 7);
    const SomiglianaCoordinates coords = computeSomiglianaCoordinates(cage, points);
    EXPECT_LT(partitionOfUnityResidual(coords).maxCoeff(), 1e-12) << "offset " << offset;
    EXPECT_NEAR(coords.winding.minCoeff(), 1.0, 1e-12);
  }
}

TEST(SomiglianaCoordinates, PartitionOfUnity2D) {
  const Cage cage = test::makeStarPolygon(5);
  for (double offset : {0.1, 1e-3, 1e-6}) {
    const Eigen::MatrixXd points = test::pointsNearFaces(cage, 40, offset, 3);
    const SomiglianaCoordinates coords = computeSomiglianaCoordinates(cage, points);
    EXPECT_LT(partitionOfUnityResidual(coords).maxCoeff(), 1e-12) << "offset " << offset;
    EXPECT_NEAR(coords.winding.minCoeff(), 1.0, 1e-12);
  }
}

TEST(SomiglianaCoordinates, PointsOutsideHaveZeroSumAndWinding) {
  // Outside a closed cage sum_i T_i -> 0 (docs/method.md); the winding number says which points those are.
  const Cage cage = test::makeIcosphere(1);
  Eigen::MatrixXd points(2, 3);
  points << 1.5, 0.2, 0.1, -3, 2, 1;
  const SomiglianaCoordinates coords = computeSomiglianaCoordinates(cage, points);
  for (int p = 0; p < 2; ++p) {
    EXPECT_NEAR(coords.winding(p), 0.0, 1e-12);
    EXPECT_LT(coords.vertexCoordinateSum(p, 0.3).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(SomiglianaCoordinates, ReproductionIdentityForEveryNu) {
  // Eq. 7 holds for every nu, including the limit nu = +-infinity (c = 2 - d there); round-off level, 1e-12.
  const Cage cage3 = test::makeBumpySphere(1);
  const Eigen::MatrixXd points3 = test::randomBallPoints(30, 0.6, 11);
  const SomiglianaCoordinates coords3 = computeSomiglianaCoordinates(cage3, points3);
  const Cage cage2 = test::makeStarPolygon(6);
  const Eigen::MatrixXd points2 = test::randomDiscPoints(30, 0.4, 5);
  const SomiglianaCoordinates coords2 = computeSomiglianaCoordinates(cage2, points2);
  for (double nu : {-0.9, -0.3, 0.0, 0.3, 0.49, kInf, -kInf}) {
    EXPECT_LT(reproductionError(coords3, cage3, points3, nu), 1e-12) << "3D nu " << nu;
    EXPECT_LT(reproductionError(coords2, cage2, points2, nu), 1e-12) << "2D nu " << nu;
  }
}

// T_i(x) and K_j(x) n_j integrated directly from the full kernels of Eqs. 3-4 at this nu, with a high-order Gauss
// rule: an independent route that never uses the nu-independent split.
void integrateDirectly(const Cage& cage, const Eigen::Vector3d& x, double nu, std::vector<Eigen::Matrix3d>& T,
                       std::vector<Eigen::Vector3d>& Kn) {
  const int order = 40;
  Eigen::VectorXd nodes, weights;
  gaussLegendre01(order, nodes, weights);
  T.assign(cage.numVertices(), Eigen::Matrix3d::Zero());
  Kn.assign(cage.numFaces(), Eigen::Vector3d::Zero());
  const Eigen::MatrixXd N = faceNormals(cage, cage.vertices);
  for (int j = 0; j < cage.numFaces(); ++j) {
    const Eigen::Vector3d p[3] = {cage.vertices.row(cage.faces(j, 0)), cage.vertices.row(cage.faces(j, 1)),
                                  cage.vertices.row(cage.faces(j, 2))};
    const Eigen::Vector3d n = N.row(j);
    const double twiceArea = (p[1] - p[0]).cross(p[2] - p[0]).norm();
    // Collapsed (Duffy) map of the unit square onto the triangle: b1 = u (1 - v), b2 = u v, Jacobian u.
    for (int a = 0; a < order; ++a)
      for (int b = 0; b < order; ++b) {
        const double u = nodes(a), v = nodes(b);
        const double phi1 = u * (1 - v), phi2 = u * v, phi0 = 1 - phi1 - phi2;
        const Eigen::Vector3d y = phi0 * p[0] + phi1 * p[1] + phi2 * p[2];
        const double w = weights(a) * weights(b) * u * twiceArea;
        const Eigen::Matrix3d kernelT = tractionKernel(Eigen::Vector3d(y - x), n, nu);
        T[cage.faces(j, 0)] += w * phi0 * kernelT;
        T[cage.faces(j, 1)] += w * phi1 * kernelT;
        T[cage.faces(j, 2)] += w * phi2 * kernelT;
        Kn[j] += w * kelvinlet(Eigen::Vector3d(y - x), nu) * n;
      }
  }
}

TEST(SomiglianaCoordinates, NuReassemblyEqualsIntegratingAgain) {
  // Points at least ~0.4 from the cage, where a 1600-point rule per face is accurate to ~1e-11.
  const Cage cage = test::makeIcosphere(1);
  const Eigen::MatrixXd points = test::randomBallPoints(4, 0.4, 21);
  const SomiglianaCoordinates coords = computeSomiglianaCoordinates(cage, points);
  for (double nu : {-0.5, 0.0, 0.3, 0.45, kInf}) {
    for (int p = 0; p < points.rows(); ++p) {
      std::vector<Eigen::Matrix3d> T;
      std::vector<Eigen::Vector3d> Kn;
      integrateDirectly(cage, points.row(p), nu, T, Kn);
      for (int i = 0; i < cage.numVertices(); ++i)
        EXPECT_LT((coords.vertexCoordinate(p, i, nu) - T[i]).cwiseAbs().maxCoeff(), 1e-10) << "nu " << nu;
      for (int j = 0; j < cage.numFaces(); ++j)
        EXPECT_LT((coords.faceCoordinateTimesNormal(p, j, nu) - Kn[j]).cwiseAbs().maxCoeff(), 1e-10) << "nu " << nu;
    }
  }
}

TEST(SomiglianaCoordinates, ResultDoesNotDependOnThreadCount) {
  const Cage cage = test::makeBumpySphere(1);
  const Eigen::MatrixXd points = test::randomBallPoints(700, 0.6, 2);
  IntegrationOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const SomiglianaCoordinates a = computeSomiglianaCoordinates(cage, points, one);
  const SomiglianaCoordinates b = computeSomiglianaCoordinates(cage, points, two);
  EXPECT_TRUE((a.values.array() == b.values.array()).all()) << "bitwise equal";
}

TEST(SomiglianaCoordinates, GaussBaselineIsSelectableAndLessAccurateNearTheCage) {
  // The paper's rule (section 5) converges far from the cage but not near it, which is why the closed form is the
  // default: at 1e-3 from a face its partition of unity residual is far above the closed form's 1e-12.
  const Cage cage = test::makeIcosphere(1);
  IntegrationOptions gauss;
  gauss.rule = IntegrationOptions::Rule::Gauss;
  gauss.gaussPointsPerSide = 12;
  const Eigen::MatrixXd far = test::randomBallPoints(10, 0.3, 4);
  EXPECT_LT(partitionOfUnityResidual(computeSomiglianaCoordinates(cage, far, gauss)).maxCoeff(), 1e-6);
  const Eigen::MatrixXd near = test::pointsNearFaces(cage, 10, 1e-3, 4);
  EXPECT_GT(partitionOfUnityResidual(computeSomiglianaCoordinates(cage, near, gauss)).maxCoeff(), 1e-4);
}

TEST(SomiglianaCoordinates, ProgressCanCancel) {
  const Cage cage = test::makeIcosphere(1);
  const Eigen::MatrixXd points = test::randomBallPoints(5000, 0.5, 1);  // several blocks of work
  int calls = 0;
  auto stopSoon = [&](double) { return ++calls < 3; };
  EXPECT_THROW(computeSomiglianaCoordinates(cage, points, {}, stopSoon), Cancelled);
  double last = -1;
  bool monotone = true;
  computeSomiglianaCoordinates(cage, points, {}, [&](double f) {
    monotone = monotone && f >= last;
    last = f;
    return true;
  });
  EXPECT_TRUE(monotone);
  EXPECT_EQ(last, 1.0);
}

}  // namespace
}  // namespace somicage
