// The exact coordinate gradients (core/coordinates/coordinate_gradients.h) of the Somigliana terms: the pack kernel
// (closed-form derivatives, four points at once) against the one-point dual-number kernel, the independent
// reference, to 1e-12 of each term's size (at least 1) on small cages with points from 1e-5 to 0.1 inside their
// faces, on the extensions of edges, far away, and on a subsample of every shared model; both against central
// differences of the closed-form coordinates; and the partition of unity's zero gradient.
#include "coordinates/coordinate_gradients.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "coordinates/bem_layer_integrals.h"
#include "coordinates/somigliana_coordinates.h"
#include "recorded_number.h"
#include "test_models.h"
#include "test_shapes.h"

namespace somicage {
namespace {

using GradientRows = std::array<Eigen::MatrixXd, 3>;  // [a](p, k) = d row_p[k] / dx_a
using Integrator = void (*)(const Cage&, const Eigen::MatrixXd&, int, const ProgressCallback&,
                            const GradientRowSink&, bool);

// The rows' first `columns` entries (each method's rows have at least that many).
GradientRows gradientRows(Integrator integrate, const Cage& cage, const Eigen::MatrixXd& points, int columns,
                          bool scalarKernel) {
  GradientRows rows;
  for (Eigen::MatrixXd& g : rows) g.setConstant(points.rows(), columns, std::nan(""));
  integrate(
      cage, points, 2, noProgress,
      [&](int p, const double* const* r) {
        for (int a = 0; a < 3; ++a) rows[a].row(p) = Eigen::Map<const Eigen::RowVectorXd>(r[a], columns);
      },
      scalarKernel);
  return rows;
}

GradientRows somiglianaGradientRows(const Cage& cage, const Eigen::MatrixXd& points, bool scalarKernel) {
  return gradientRows(integrateSomiglianaGradients, cage, points,
                      somiglianaLayout(3, cage.numVertices(), cage.numFaces()).integralColumns(), scalarKernel);
}

// The largest |packs - scalar| / max(1, |scalar|) over every gradient entry (NaN if a row was never written).
double worstDifference(const Cage& cage, const Eigen::MatrixXd& points, Integrator integrate = integrateSomiglianaGradients,
                       int columns = 0) {
  if (columns == 0) columns = somiglianaLayout(3, cage.numVertices(), cage.numFaces()).integralColumns();
  const GradientRows reference = gradientRows(integrate, cage, points, columns, true);
  const GradientRows packs = gradientRows(integrate, cage, points, columns, false);
  double worst = 0;
  for (int a = 0; a < 3; ++a) {
    const Eigen::ArrayXXd scale = reference[a].array().abs().max(1.0);
    const double w = ((packs[a] - reference[a]).array().abs() / scale).maxCoeff();
    worst = std::isnan(w) ? w : std::max(worst, w);
  }
  return worst;
}

using test::scientific;

// The closed form and the dual numbers are two derivations: at 0.1 from the faces they agree to 1e-12 of each entry
// (measured 3.6e-14), but an entry that is a small sum of the near face's large terms (which grow like delta^-2 for
// the gradients at a distance delta) takes their rounding: measured 1.2e-10 at 1e-3 (cube) and 1.7e-8 at 1e-5
// (320-face sphere), where the partition of unity's gradient still holds to 2e-14 of the vertices' terms in both
// (PartitionOfUnityHasAZeroGradient). Bound 1e-12 (0.1 / delta)^1.5: 1e-9 at 1e-3, 1e-6 at 1e-5.
TEST(CoordinateGradients, PacksAgreeWithTheScalarDualNumbersNearAndFarFromFaces) {
  for (const Cage& cage : {test::makeCube(), test::makeIcosphere(2), test::makeExtrudedL()})
    for (double offset : {1e-1, 1e-3, 1e-5}) {
      const Eigen::MatrixXd points = test::pointsNearFaces(cage, 4 * 10 + 3, offset, 1);  // the last pack padded
      const double worst = worstDifference(cage, points);
      EXPECT_LE(worst, 1e-12 * std::pow(0.1 / offset, 1.5)) << cage.numFaces() << " faces, " << offset << " inside";
      RecordProperty("worst_difference_" + std::to_string(cage.numFaces()) + "_faces_" + scientific(offset),
                     scientific(worst));
    }
}

// The rows away from the cage as well (the integrals hold anywhere off the faces): points on the extensions of the
// cube's edges (t and h of the edge line zero to rounding, closed-form.md 5.5) and far away.
TEST(CoordinateGradients, PacksAgreeWithTheScalarDualNumbersOnEdgeLinesAndFarAway) {
  const Cage cage = test::makeCube();
  Eigen::MatrixXd points(4 * 6 + 1, 3);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int p = 0; p < 12; ++p) {  // beyond a corner of the cube [-1, 1]^3 along one of its edges, 1e-9 off it
    Eigen::Vector3d x(p % 2 ? 1 : -1, (p / 2) % 2 ? 1 : -1, 1 + 0.1 + std::abs(u(rng)));
    x[(p / 4) % 3] += 1e-9;
    std::swap(x[2], x[p % 3]);
    points.row(p) = x.transpose();
  }
  for (int p = 12; p < points.rows(); ++p)
    points.row(p) = (Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized() * (p % 2 ? 10.0 : 30.0)).transpose();
  const double worst = worstDifference(cage, points);
  EXPECT_LE(worst, 1e-12);
  RecordProperty("worst_difference", scientific(worst));
}

// Sum_i T_i = I at every point inside the cage (Eq. 9), for every nu: so the gradient rows' vertex terms, summed
// over the vertices and assembled, vanish. Independent of any reference kernel; against the size of the single
// vertices' assembled gradients (at least 1). Points 0.1 to 1e-4 inside the faces of a non-convex cage.
TEST(CoordinateGradients, PartitionOfUnityHasAZeroGradient) {
  const Cage cage = test::makeBumpySphere(1);
  Eigen::MatrixXd points(4 * 5, 3);
  points << test::randomBallPoints(8, 0.55, 11), test::pointsNearFaces(cage, 6, 1e-2, 12),
      test::pointsNearFaces(cage, 6, 1e-4, 13);
  const CoordinateLayout layout = somiglianaLayout(3, cage.numVertices(), cage.numFaces());
  for (bool scalarKernel : {false, true}) {
    const GradientRows gradients = somiglianaGradientRows(cage, points, scalarKernel);
    double worst = 0;
    for (int a = 0; a < 3; ++a)
      for (int p = 0; p < points.rows(); ++p)
        for (double nu : {0.0, 0.3, 0.45}) {
          const Eigen::RowVectorXd row = gradients[a].row(p);
          double sums[vertexTermCount(3)] = {0}, terms[vertexTermCount(3)];
          double scale = 1;
          for (int i = 0; i < cage.numVertices(); ++i) {
            gatherVertexTerms(layout, row.data(), i, terms);
            for (int m = 0; m < vertexTermCount(3); ++m) sums[m] += terms[m];
            scale = std::max(scale, assembleVertexCoordinate(terms, 3, nu).cwiseAbs().maxCoeff());
          }
          worst = std::max(worst, assembleVertexCoordinate(sums, 3, nu).cwiseAbs().maxCoeff() / scale);
        }
    EXPECT_LE(worst, 1e-12) << (scalarKernel ? "scalar dual numbers" : "closed form in packs");
    RecordProperty(std::string(scalarKernel ? "scalar" : "packs") + "_worst", scientific(worst));
  }
}

// Green's [phi | psi] and the boundary element's layer integrals run the per-face kernel on duals of packs too.
// Bound 1e-11: a vertex term's gradient 1e-4 from a face of the 320-face sphere is a sum of per-face terms that grow
// like the inverse square of the distance and mostly cancel, so the packs' 1-ulp logarithms and angles (and the two
// kernels' different fused multiply-adds) show at up to 2.3e-12 of it (measured: BEM's omega terms); on the cube at
// most 2.1e-14.
TEST(CoordinateGradients, GreenAndBemPacksAgreeWithTheScalarDualNumbers) {
  for (const Cage& cage : {test::makeCube(), test::makeIcosphere(2)}) {
    Eigen::MatrixXd points(4 * 10 + 1, 3);
    points << test::pointsNearFaces(cage, 20, 1e-1, 4), test::pointsNearFaces(cage, 21, 1e-4, 5);
    const double green = worstDifference(cage, points, integrateGreenGradients, cage.numVertices() + cage.numFaces());
    const double bem = worstDifference(cage, points, integrateBemLayerGradients,
                                       bemLayerLayout(3, cage.numVertices(), cage.numFaces()).mainColumns());
    EXPECT_LE(green, 1e-11) << cage.numFaces() << " faces";
    EXPECT_LE(bem, 1e-11) << cage.numFaces() << " faces";
    RecordProperty("green_worst_" + std::to_string(cage.numFaces()) + "_faces", scientific(green));
    RecordProperty("bem_worst_" + std::to_string(cage.numFaces()) + "_faces", scientific(bem));
  }
}

// Central differences of the scalar closed form with step 1e-5 at points at least 0.1 inside a cage of size 1:
// truncation about 1e-10 and rounding about eps / 1e-5 = 2e-11 of the coordinates' third derivatives and sizes,
// so 1e-7 of each gradient's size (at least 1) leaves a wide margin and still catches any wrong term.
TEST(CoordinateGradients, MatchCentralDifferencesOfTheCoordinates) {
  const Cage cage = test::makeBumpySphere(1);
  const Eigen::MatrixXd points = test::randomBallPoints(9, 0.55, 7);
  IntegrationOptions scalar;
  scalar.scalarKernel = true;
  const double step = 1e-5;
  for (bool scalarKernel : {false, true}) {
    const GradientRows gradients = somiglianaGradientRows(cage, points, scalarKernel);
    for (int a = 0; a < 3; ++a) {
      Eigen::MatrixXd plus = points, minus = points;
      plus.col(a).array() += step;
      minus.col(a).array() -= step;
      const Eigen::MatrixXd difference = (computeSomiglianaCoordinates(cage, plus, scalar).values -
                                          computeSomiglianaCoordinates(cage, minus, scalar).values) /
                                         (2 * step);
      const Eigen::MatrixXd exact = gradients[a].leftCols(difference.cols());
      const double worst =
          ((exact - difference).array().abs() / exact.array().abs().max(1.0)).maxCoeff();
      EXPECT_LE(worst, 1e-7) << "d/dx_" << a << (scalarKernel ? " (scalar)" : " (packs)");
      RecordProperty(std::string(scalarKernel ? "scalar" : "packs") + "_worst_x" + std::to_string(a), scientific(worst));
    }
  }
}

class CoordinateGradientModels : public ::testing::TestWithParam<test::ModelCase> {};

TEST_P(CoordinateGradientModels, PacksAgreeWithTheScalarDualNumbers) {
  Cage cage;
  Eigen::MatrixXd sample;
  if (!test::loadModel(GetParam(), cage, sample)) return;
  Eigen::MatrixXd points(std::min<Eigen::Index>(sample.rows(), 21), 3);  // a quick subsample, 4k + 1 points
  for (Eigen::Index p = 0; p < points.rows(); ++p) points.row(p) = sample.row(p * (sample.rows() / points.rows()));
  const double worst = worstDifference(cage, points);
  EXPECT_LE(worst, 1e-12);
  RecordProperty("worst_difference", scientific(worst));
}

INSTANTIATE_TEST_SUITE_P(SharedModels, CoordinateGradientModels, ::testing::ValuesIn(test::modelCases()),
                         test::modelCaseName);

}  // namespace
}  // namespace somicage
