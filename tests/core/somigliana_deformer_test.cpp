// The corotational Somigliana deformer (Eqs. 10-15): identity at rest and similarity invariance for every variant,
// nu, gamma and traction setting, in 2D and 3D.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "base/errors.h"
#include "deform/deformer.h"
#include "methods/method_descriptors.h"
#include "recorded_number.h"
#include "reference/somigliana_reference.h"
#include "test_shapes.h"

namespace somicage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Scene {
  Cage cage;
  Eigen::MatrixXd points;
};

Scene scene3() { return {test::makeBumpySphere(1), test::randomBallPoints(60, 0.6, 9)}; }
Scene scene2() { return {test::makeStarPolygon(6), test::randomDiscPoints(60, 0.4, 9)}; }

std::vector<DeformParams> parameterGrid() {
  std::vector<DeformParams> grid;
  for (double blend : {0.0, 0.5, 1.0})
    for (double nu : {-0.5, 0.0, 0.3, 0.45, kInf})
      for (double gamma : {0.0, 2.0})
        for (bool fix : {true, false}) grid.push_back({blend, nu, gamma, fix});
  // Every bulging convention and normal weighting (deform_choices.h), with bulging on, in both variants.
  for (double blend : {0.0, 1.0})
    for (Bulging bulging : {Bulging::SolidAngle, Bulging::Reference, Bulging::SweptVolume, Bulging::Polygon})
      for (NormalWeights normals : {NormalWeights::Area, NormalWeights::Angle})
        grid.push_back({blend, 0.3, 1.5, true, false, bulging, normals});
  // The variants beyond the paper (deformer.h: VariantKind), and with the other choices.
  for (VariantKind kind : {VariantKind::Affine, VariantKind::Stable}) {
    for (double nu : {0.0, 0.45})
      for (double gamma : {0.0, 1.5}) {
        DeformParams p{kind == VariantKind::Stable ? 1.0 : 0.0, nu, gamma, true};
        p.kind = kind;
        grid.push_back(p);
      }
    for (Bulging bulging : {Bulging::Reference, Bulging::SweptVolume, Bulging::Polygon}) {
      DeformParams p{0, 0.3, 1.5, true, false, bulging, NormalWeights::Angle};
      p.kind = kind;
      grid.push_back(p);
    }
  }
  return grid;
}

std::string describe(const DeformParams& p) {
  std::string text = "blend " + std::to_string(p.blend) + " nu " + std::to_string(p.nu) + " gamma " +
                     std::to_string(p.gamma) + (p.tractionCorrection ? " fix" : " nofix");
  for (const ChoiceParameter& choice : choiceParameters())
    text += std::string(" ") + choice.name + " " + choice.values[static_cast<std::size_t>(choice.get(p))].name;
  return text + " variant " + variantName(p);
}

class SomiglianaDeformerTest : public ::testing::TestWithParam<int> {
 protected:
  Scene scene() const { return GetParam() == 3 ? scene3() : scene2(); }
};

TEST_P(SomiglianaDeformerTest, RestPoseIsTheIdentity) {
  // At rest every rotation is I and s_j = c, so Eq. 11 reduces to Eq. 7: round-off, asserted at 1e-8 diameters.
  const Scene s = scene();
  const auto deformer = makeDeformer(methods::somigliana(), s.cage, s.points, {}, noProgress);
  const double diameter = cageDiameter(s.cage.vertices);
  for (const DeformParams& params : parameterGrid()) {
    const Eigen::MatrixXd out = deformer->deform(s.cage.vertices, params);
    EXPECT_LT((out - s.points).rowwise().norm().maxCoeff(), 1e-8 * diameter) << describe(params);
  }
}

TEST_P(SomiglianaDeformerTest, SimilarityInvariance) {
  // Deforming by (similarity o pose) equals the similarity applied to the deformed pose (section 4.3); 1e-9 of
  // the posed cage's diameter (the operations are exact up to round-off in the SVDs and the 3 by 3 solves).
  const Scene s = scene();
  const int d = s.cage.dim();
  const auto deformer = makeDeformer(methods::somigliana(), s.cage, s.points, {}, noProgress);
  const Eigen::MatrixXd pose = test::bendPose(s.cage.vertices, 0.3, 5);
  for (unsigned seed : {1u, 2u}) {
    const test::TestSimilarity similarity = test::randomSimilarity(d, seed);
    const Eigen::MatrixXd moved = similarity.apply(pose);
    const double diameter = cageDiameter(moved);
    for (const DeformParams& params : parameterGrid()) {
      const Eigen::MatrixXd expected = similarity.apply(deformer->deform(pose, params));
      const Eigen::MatrixXd actual = deformer->deform(moved, params);
      EXPECT_LT((actual - expected).rowwise().norm().maxCoeff(), 1e-9 * diameter) << describe(params);
    }
  }
}

TEST_P(SomiglianaDeformerTest, SimilarityPoseMovesPointsBySimilarity) {
  // A pose that is itself a similarity of the rest cage moves every interior point by that similarity.
  const Scene s = scene();
  const auto deformer = makeDeformer(methods::somigliana(), s.cage, s.points, {}, noProgress);
  const test::TestSimilarity similarity = test::randomSimilarity(s.cage.dim(), 8);
  const Eigen::MatrixXd moved = similarity.apply(s.cage.vertices);
  for (const DeformParams& params : parameterGrid()) {
    const Eigen::MatrixXd out = deformer->deform(moved, params);
    EXPECT_LT((out - similarity.apply(s.points)).rowwise().norm().maxCoeff(), 1e-8 * cageDiameter(moved))
        << describe(params);
  }
}

TEST_P(SomiglianaDeformerTest, EachParameterMovesPointsAsEq11Does) {
  // Guards the tests above against a deformer that ignores or mishandles a parameter: on a real pose, what nu,
  // gamma, the variant and the traction fix each change (the deformation minus the one with the defaults) equals
  // what the independent evaluation of Eq. 11 changes (tests/core/reference, its own quadrature and boundary
  // conditions) to 1e-8 diameters, and is more than 1e-4 diameters (the pose makes every parameter matter).
  const Scene s = scene();
  const Eigen::MatrixXd points = s.points.topRows(6);
  const auto deformer = makeDeformer(methods::somigliana(), s.cage, points, {}, noProgress);
  const Eigen::MatrixXd pose = test::bendPose(s.cage.vertices, 0.3, 5);
  const double diameter = cageDiameter(pose);
  std::vector<std::vector<reference::Coordinates>> coordinates;  // [point][nu 0, nu 0.4]
  for (Eigen::Index q = 0; q < points.rows(); ++q)
    coordinates.push_back(reference::integrateCoordinates(s.cage, points.row(q).transpose(), {0.0, 0.4}));
  const auto referenceDeform = [&](const reference::PoseParameters& p) {
    const reference::BoundaryConditions bc = reference::boundaryConditions(s.cage, pose, p);
    Eigen::MatrixXd out(points.rows(), s.cage.dim());
    for (Eigen::Index q = 0; q < points.rows(); ++q)
      out.row(q) =
          reference::deformPoint(s.cage, pose, coordinates[static_cast<size_t>(q)][p.nu == 0 ? 0 : 1], bc).transpose();
    return out;
  };
  // Each parameter changed alone, from the defaults; the traction fix from the local variant with bulging (with
  // gamma = 0, s_j w_j is a multiple of the posed face's area-weighted normal, whose sum over a closed cage is 0 in
  // 2D and in the global variant: Eq. 15 then has nothing to correct).
  const reference::PoseParameters defaults{0.0, 0.0, 0.0, true}, local{1.0, 0.0, 0.0, true},
      bulgingLocal{1.0, 0.0, 3.0, true};
  const struct {
    const char* name;
    reference::PoseParameters from, to;
  } changes[] = {{"nu", defaults, {0.0, 0.4, 0.0, true}},
                 {"gamma", defaults, {0.0, 0.0, 3.0, true}},
                 {"local variant", defaults, local},
                 {"no traction fix", bulgingLocal, {1.0, 0.0, 3.0, false}}};
  const auto core = [&](const reference::PoseParameters& p) {
    return deformer->deform(pose, {p.blend, p.nu, p.gamma, p.tractionCorrection});
  };
  for (const auto& change : changes) {
    const Eigen::MatrixXd coreChange = core(change.to) - core(change.from);
    const Eigen::MatrixXd referenceChange = referenceDeform(change.to) - referenceDeform(change.from);
    EXPECT_GT(referenceChange.rowwise().norm().maxCoeff(), 1e-4 * diameter) << change.name;
    EXPECT_LE((coreChange - referenceChange).rowwise().norm().maxCoeff(), 1e-8 * diameter) << change.name;
  }
  // The choices (bulging, normals: deform_choices.h) each change the result too, but for polygon bulging: it merges
  // coplanar neighbouring faces only, and this cage has none, so it must equal the paper's measure bit for bit.
  const DeformParams bulged{0.0, 0.0, 3.0, true};
  for (const ChoiceParameter& choice : choiceParameters())
    for (int value = 1; value < static_cast<int>(choice.values.size()); ++value) {
      DeformParams p = bulged;
      choice.set(p, value);
      const std::string name = choice.values[static_cast<std::size_t>(value)].name;
      const double moved = (deformer->deform(pose, p) - deformer->deform(pose, bulged)).rowwise().norm().maxCoeff();
      if (name == "polygon")
        EXPECT_EQ(moved, 0.0) << choice.name << " " << name;
      else
        EXPECT_GT(moved, 1e-4 * diameter) << choice.name << " " << name;
    }
}

TEST_P(SomiglianaDeformerTest, ResultDoesNotDependOnThreadCount) {
  const Scene s = scene();
  PrecomputeOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const Eigen::MatrixXd pose = test::bendPose(s.cage.vertices, 0.3, 5);
  const DeformParams params{0.5, 0.3, 1.0, true};
  const Eigen::MatrixXd a =
      makeDeformer(methods::somigliana(), s.cage, s.points, one, noProgress)->deform(pose, params);
  const Eigen::MatrixXd b =
      makeDeformer(methods::somigliana(), s.cage, s.points, two, noProgress)->deform(pose, params);
  EXPECT_TRUE((a.array() == b.array()).all()) << "bitwise equal";
}

TEST_P(SomiglianaDeformerTest, FloatStorageStaysWithinItsErrorBudget) {
  // Float storage (the editor's choice) rounds each coordinate to ~6e-8 relative; over a frame's sums that stays
  // below 1e-5 of the cage diameter, the tolerance the GPU path is held to as well.
  const Scene s = scene();
  PrecomputeOptions single;
  single.floatStorage = true;
  const auto exact = makeDeformer(methods::somigliana(), s.cage, s.points, {}, noProgress);
  const auto rounded = makeDeformer(methods::somigliana(), s.cage, s.points, single, noProgress);
  EXPECT_LT(rounded->frameCoordinates().bytes(), exact->frameCoordinates().bytes());
  const Eigen::MatrixXd pose = test::bendPose(s.cage.vertices, 0.3, 5);
  for (const DeformParams& params : parameterGrid()) {
    const Eigen::MatrixXd a = exact->deform(pose, params), b = rounded->deform(pose, params);
    EXPECT_LT((a - b).rowwise().norm().maxCoeff(), 1e-5 * cageDiameter(pose)) << describe(params);
  }
}

// The gradient matrices (CageDeformer::coordinateGradients, written group by group from the kernels' packs) are
// the derivatives of C's rows, every column: the main block, the per-vertex sums and affine terms in the tail, and
// [x | 1] (zero inside; the per-vertex sums' gradients vanish there too, to the differences' accuracy); rows of
// points outside the cage are zero. The reference is central differences of whole precomputes, which share none of
// the gradients' code. 62 points: full groups, a partial last one, and two exterior points inside groups. Measured
// 5.6e-9 (2D) and 9.8e-10 (3D) of max(1, |entry|) with h = 1e-5 (the differences' h^2 error: 5.6e-7 and 9.6e-8
// with h = 1e-4).
TEST_P(SomiglianaDeformerTest, CoordinateGradientsAreTheDerivativesOfTheRows) {
  const Scene s = scene();
  const int dim = GetParam(), numPoints = static_cast<int>(s.points.rows()) + 2;
  Eigen::MatrixXd points(numPoints, dim);
  points << s.points.topRows(5), Eigen::RowVectorXd::Constant(dim, 3.0), s.points.middleRows(5, 8),
      Eigen::RowVectorXd::Constant(dim, -4.0), s.points.bottomRows(s.points.rows() - 13);
  const int exterior[2] = {5, 14};
  const auto deformer = makeDeformer(methods::somigliana(), s.cage, points, {}, noProgress);
  const std::vector<FrameCoordinates> gradients = deformer->coordinateGradients(points, noProgress);
  ASSERT_EQ(static_cast<int>(gradients.size()), dim);
  const auto rowsOfC = [&](const Eigen::MatrixXd& at) -> Eigen::MatrixXd {
    return makeDeformer(methods::somigliana(), s.cage, at, {}, noProgress)
        ->frameCoordinates()
        .doubles.topRows(numPoints);
  };
  const double h = 1e-5;
  double worst = 0;
  for (int a = 0; a < dim; ++a) {
    Eigen::MatrixXd plus = points, minus = points;
    plus.col(a).array() += h;
    minus.col(a).array() -= h;
    const Eigen::MatrixXd difference = (rowsOfC(plus) - rowsOfC(minus)) / (2 * h);
    const Eigen::MatrixXd& g = gradients[static_cast<std::size_t>(a)].doubles;
    ASSERT_EQ(g.rows(), numPoints);
    ASSERT_EQ(g.cols(), difference.cols());
    for (int p = 0; p < numPoints; ++p) {
      if (p == exterior[0] || p == exterior[1]) {
        EXPECT_TRUE((g.row(p).array() == 0).all()) << "exterior point " << p;
        continue;
      }
      const Eigen::ArrayXd scale = difference.row(p).transpose().array().abs().max(1.0);
      worst = std::max(worst, ((g.row(p) - difference.row(p)).transpose().array().abs() / scale).maxCoeff());
    }
  }
  EXPECT_LT(worst, 1e-7);
  RecordProperty("worst_relative_difference", test::scientific(worst));
}

INSTANTIATE_TEST_SUITE_P(Dimensions, SomiglianaDeformerTest, ::testing::Values(2, 3),
                         [](const auto& info) { return info.param == 3 ? "3D" : "2D"; });

// Found by fuzz_precompute_deform: a cage collapsed to one point, with blended rotations, made T(x) singular and
// every point NaN. The regularised solve (core/deform/frame_point_kernel.h) keeps the points finite; with every cage
// vertex at c the right-hand side is T c, so they all land on c (to round-off of the cage's offset).
TEST_P(SomiglianaDeformerTest, ACageCollapsedToAPointTakesEveryPointThere) {
  const Scene s = scene();
  const int d = s.cage.dim();
  const Eigen::RowVectorXd c = Eigen::RowVectorXd::Constant(d, -1000.0);
  Eigen::MatrixXd collapsed = s.cage.vertices;
  collapsed.rowwise() = c;
  const auto deformer = makeDeformer(methods::somigliana(), s.cage, s.points, {}, noProgress);
  for (const DeformParams& params :
       {DeformParams{0.352951, -0.999, 0, false}, DeformParams{1, 0.3, 2, true}, DeformParams{0, 0, 0, true}}) {
    const FrameWeights W = deformer->frameWeights(collapsed, params);
    ASSERT_TRUE(W.main.allFinite() && W.tail.allFinite()) << describe(params);
    const Eigen::MatrixXd out = deformer->deform(collapsed, params);
    ASSERT_TRUE(out.allFinite()) << describe(params);
    EXPECT_LE((out.rowwise() - c).rowwise().norm().maxCoeff(), 1e-9 * 1000) << describe(params);
  }
}

// The frame is solved about the posed centroid (frame_evaluation.h): moving cage and points far from the origin
// changes nothing but the offset, in float storage too.
TEST_P(SomiglianaDeformerTest, FarFromTheOriginFloatStorageKeepsItsAccuracy) {
  const Scene s = scene();
  const Eigen::RowVectorXd offset = Eigen::RowVectorXd::Constant(s.cage.dim(), 1e4);
  Cage far = s.cage;
  far.vertices.rowwise() += offset;
  const Eigen::MatrixXd farPoints = s.points.rowwise() + offset;
  PrecomputeOptions single;
  single.floatStorage = true;
  const Eigen::MatrixXd pose = test::bendPose(s.cage.vertices, 0.2, 5);
  const DeformParams params{0.5, 0.3, 1, true};
  const Eigen::MatrixXd near =
      makeDeformer(methods::somigliana(), s.cage, s.points, single, noProgress)->deform(pose, params);
  const Eigen::MatrixXd moved =
      makeDeformer(methods::somigliana(), far, farPoints, single, noProgress)->deform(pose.rowwise() + offset, params);
  const double diameter = cageDiameter(s.cage.vertices);
  EXPECT_LE(((moved.rowwise() - offset) - near).rowwise().norm().maxCoeff(), 1e-5 * diameter);
}

TEST(SomiglianaDeformer, RejectsInvalidParameters) {
  const Scene s = scene2();
  const auto deformer = makeDeformer(methods::somigliana(), s.cage, s.points, {}, noProgress);
  for (const DeformParams& bad :
       {DeformParams{0, 0.5, 0, true}, DeformParams{0, -1, 0, true}, DeformParams{0, kNaN, 0, true},
        DeformParams{0, 0, -1, true}, DeformParams{1.5, 0, 0, true}, DeformParams{kNaN, 0, 0, true},
        DeformParams{0, 0, 0, true, false, static_cast<Bulging>(4)},
        DeformParams{0, 0, 0, true, false, Bulging::SolidAngle, static_cast<NormalWeights>(-1)}})
    EXPECT_THROW(deformer->deform(s.cage.vertices, bad), InputError) << describe(bad);
}

}  // namespace
}  // namespace somicage
