// Points outside the cage and on it (core/deform/exterior_points.h): x~ = S(x) + w(d) [phi(x_in) - S(x_in)] for the
// Somigliana and Green deformers, 2D and 3D. Continuity across a face, an edge and at a vertex; finite results
// exactly on the cage; the pure similarity beyond the band; C2 in the distance; identity at rest and similarity
// invariance with exterior points present. Mean value coordinates need no rule: they stay finite on the cage.
#include "deform/exterior_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "coordinates/somigliana_coordinates.h"
#include "deform/boundary_conditions.h"
#include "deform/deformer.h"
#include "method_cases.h"
#include "methods/method_descriptors.h"
#include "test_shapes.h"

namespace somicage {
namespace {

using Case = test::MethodCase;

// Non-convex cages: a bumpy sphere and a star.
Cage testCage(int dim) { return dim == 3 ? test::makeBumpySphere(1) : test::makeStarPolygon(6); }

// A convex cage: the regular 12-gon of radius 1.
Cage regularPolygon() {
  Eigen::MatrixXd loop(12, 2);
  for (int k = 0; k < 12; ++k) loop.row(k) << std::cos(M_PI * k / 6), std::sin(M_PI * k / 6);
  return makePolygonCage(loop);
}

Eigen::MatrixXd bentPose(const Cage& cage) { return test::bendPose(cage.vertices, 0.3, 11); }

// A non-trivial parameter set for Somigliana (the others ignore it).
const DeformParams kParams{0.5, 0.3, 1.0, true};

// Points of the cage with their outward pseudo-normals: face centroids, edge midpoints (3D) and vertices.
struct CagePoint {
  std::string what;
  Eigen::VectorXd point, normal;
};

std::vector<CagePoint> cagePoints(const Cage& cage) {
  const CageProximity proximity(cage);
  std::vector<CagePoint> all;
  auto add = [&](const std::string& what, const Eigen::VectorXd& y) {
    all.push_back({what, y, proximity.closest(y).normal});
  };
  const int d = cage.dim();
  for (int j = 0; j < cage.numFaces(); j += cage.numFaces() / 5) {
    Eigen::VectorXd centroid = Eigen::VectorXd::Zero(d);
    for (int k = 0; k < d; ++k) centroid += cage.vertices.row(cage.faces(j, k)).transpose() / d;
    add((d == 3 ? "face " : "edge ") + std::to_string(j), centroid);
    if (d == 3)
      add("edge of face " + std::to_string(j),
          0.5 * (cage.vertices.row(cage.faces(j, 0)) + cage.vertices.row(cage.faces(j, 1))).transpose());
    add("vertex " + std::to_string(cage.faces(j, 0)), cage.vertices.row(cage.faces(j, 0)).transpose());
  }
  return all;
}

class ExteriorPointsTest : public ::testing::TestWithParam<Case> {};

TEST_P(ExteriorPointsTest, ContinuousAcrossFacesEdgesAndVertices) {
  // Points at +-eps along the pseudo-normal of a face, an edge or a vertex, and the point exactly there, map
  // within 4e-5 cage diameters of each other once eps <= 1e-7 diameters: the jump is O(h |grad phi - sR|) with
  // h = kProxyDepth = 1e-5 diameters (how deep inside the proxy lies), plus O(eps). Measured: ~1e-5.
  const Case& c = GetParam();
  const Cage cage = testCage(c.dim);
  const double diameter = cageDiameter(cage.vertices);
  const std::vector<CagePoint> onCage = cagePoints(cage);
  const std::vector<double> offsets = {1e-7, 1e-9, 1e-12};
  Eigen::MatrixXd points(static_cast<Eigen::Index>(onCage.size() * (1 + 2 * offsets.size())), c.dim);
  Eigen::Index row = 0;
  for (const CagePoint& y : onCage) {
    points.row(row++) = y.point.transpose();
    for (double eps : offsets)
      for (double side : {1.0, -1.0}) points.row(row++) = (y.point + side * eps * diameter * y.normal).transpose();
  }
  const auto deformer = makeDeformer(c.method, cage, points);
  const Eigen::MatrixXd out = deformer->deform(bentPose(cage), kParams);
  ASSERT_TRUE(out.allFinite());
  double worst = 0;
  std::string where;
  row = 0;
  for (const CagePoint& y : onCage) {
    const Eigen::RowVectorXd on = out.row(row++);
    for (double eps : offsets) {
      const Eigen::RowVectorXd outside = out.row(row++), inside = out.row(row++);
      const double jump = std::max((outside - inside).norm(), std::max((on - inside).norm(), (on - outside).norm()));
      if (jump > worst) worst = jump, where = y.what + " eps " + std::to_string(eps);
    }
  }
  EXPECT_LT(worst, 4e-5 * diameter) << "worst at " << where;
  std::ostringstream measured;
  measured << worst / diameter;
  RecordProperty("max_jump_over_diameter", measured.str());
}

TEST_P(ExteriorPointsTest, FarPointsFollowTheSimilarity) {
  // Beyond the band (0.25 diameters) w = 0: x~ = s R x + t, the Umeyama fit of the posed cage, to round-off
  // (1e-12 of the posed diameter).
  const Case& c = GetParam();
  const Cage cage = testCage(c.dim);
  const double diameter = cageDiameter(cage.vertices);
  Eigen::MatrixXd points = test::randomBoxPoints(40, c.dim, -1, 1, 3);
  points.rowwise().normalize();
  points *= 1.25 + kExteriorBand * diameter + 0.01;  // the cages lie within radius 1.25
  const Eigen::MatrixXd posed = bentPose(cage);
  const auto deformer = makeDeformer(c.method, cage, points);
  EXPECT_EQ(deformer->diagnostics().exteriorCount(), points.rows());
  const Similarity fit = fitSimilarity(cage.vertices, posed);
  const Eigen::MatrixXd expected =
      ((fit.scale * points * fit.rotation.transpose()).rowwise() + fit.translation.transpose());
  const Eigen::MatrixXd out = deformer->deform(posed, kParams);
  EXPECT_LT((out - expected).rowwise().norm().maxCoeff(), 1e-12 * cageDiameter(posed));
}

TEST_P(ExteriorPointsTest, SmoothInTheDistance) {
  // Along a ray from a face centroid along its normal, on a convex cage (the closest point stays the centroid),
  // x~(d) = S(c + d n) + w(d) K with K = phi(x_in) - S(x_in) constant: C2 in d. The second differences
  // (step band / 50, across d = 0 and d = band) stay within |K| max|w''| = |K| 10 / (sqrt(3) band^2) (+1%) and the
  // first ones within s + |K| max|w'| = s + 1.875 |K| / band (+1%).
  const Case& c = GetParam();
  const Cage cage = c.dim == 3 ? test::makeIcosphere(1) : regularPolygon();
  const double diameter = cageDiameter(cage.vertices), band = kExteriorBand * diameter, step = band / 50;
  const Eigen::VectorXd normal = faceNormals(cage, cage.vertices).row(0).transpose();
  Eigen::VectorXd centroid = Eigen::VectorXd::Zero(c.dim);
  for (int k = 0; k < c.dim; ++k) centroid += cage.vertices.row(cage.faces(0, k)).transpose() / c.dim;
  const int samples = 61;  // d from 0 to 1.2 band
  Eigen::MatrixXd points(samples, c.dim);
  for (int i = 0; i < samples; ++i) points.row(i) = (centroid + (i * step) * normal).transpose();
  const Eigen::MatrixXd posed = bentPose(cage);
  const auto deformer = makeDeformer(c.method, cage, points);
  const Eigen::MatrixXd out = deformer->deform(posed, kParams);
  ASSERT_TRUE(out.allFinite());

  const Similarity fit = fitSimilarity(cage.vertices, posed);
  const Eigen::VectorXd atCage = fit.scale * fit.rotation * centroid + fit.translation;
  const double K = (out.row(0).transpose() - atCage).norm();  // w(0) = 1: out(0) = S(c) + K
  double firstWorst = 0, secondWorst = 0;
  for (int i = 1; i + 1 < samples; ++i) {
    firstWorst = std::max(firstWorst, (out.row(i + 1) - out.row(i)).norm() / step);
    secondWorst = std::max(secondWorst, (out.row(i + 1) - 2 * out.row(i) + out.row(i - 1)).norm() / (step * step));
  }
  EXPECT_LE(secondWorst, 1.01 * K * 10 / (std::sqrt(3.0) * band * band) + 1e-6);
  EXPECT_LE(firstWorst, 1.01 * (fit.scale + 1.875 * K / band));
  EXPECT_GT(K, 1e-3 * diameter) << "the pose should move the proxy off the similarity";
}

TEST_P(ExteriorPointsTest, RestPoseIsTheIdentity) {
  // At rest S = I and phi(x_in) = x_in to the integrals' round-off, so every point stays put: outside, on the
  // cage, near it; 1e-9 of the diameter. (Some points exactly on the cage -- at some vertices -- integrate
  // reliably, to winding number 1: they keep their own coordinates.)
  const Case& c = GetParam();
  const Cage cage = testCage(c.dim);
  const double diameter = cageDiameter(cage.vertices);
  std::vector<Eigen::VectorXd> all;
  for (const CagePoint& y : cagePoints(cage))
    for (double offset : {0.0, 1e-8, 0.01, 0.1, 0.3}) all.push_back(y.point + offset * diameter * y.normal);
  Eigen::MatrixXd points(static_cast<Eigen::Index>(all.size()), c.dim);
  for (std::size_t p = 0; p < all.size(); ++p) points.row(static_cast<Eigen::Index>(p)) = all[p].transpose();
  const auto deformer = makeDeformer(c.method, cage, points);
  const int exterior = deformer->diagnostics().exteriorCount();
  EXPECT_GE(exterior, 4 * points.rows() / 5);  // at least every point off the cage
  EXPECT_EQ(deformer->numPoints(), points.rows());
  EXPECT_EQ(deformer->frameCoordinates().rows(), points.rows() + 2 * exterior);
  const Eigen::MatrixXd out = deformer->deform(cage.vertices, kParams);
  EXPECT_LT((out - points).rowwise().norm().maxCoeff(), 1e-9 * diameter);
}

TEST_P(ExteriorPointsTest, SimilarityInvarianceWithExteriorPoints) {
  // A similarity Q of the cage moves every point, inside or not, by Q: S = Q and phi(x_in) = Q(x_in).
  // 1e-9 of the posed diameter.
  const Case& c = GetParam();
  const Cage cage = testCage(c.dim);
  const double diameter = cageDiameter(cage.vertices);
  Eigen::MatrixXd points = test::randomBoxPoints(200, c.dim, -1.5, 1.5, 5);
  const std::vector<CagePoint> onCage = cagePoints(cage);
  points.conservativeResize(points.rows() + static_cast<Eigen::Index>(onCage.size()), Eigen::NoChange);
  for (std::size_t k = 0; k < onCage.size(); ++k)
    points.row(200 + static_cast<Eigen::Index>(k)) = (onCage[k].point + 1e-3 * diameter * onCage[k].normal).transpose();
  const auto deformer = makeDeformer(c.method, cage, points);
  const int exterior = deformer->diagnostics().exteriorCount();
  EXPECT_GT(exterior, 20);
  EXPECT_LT(exterior, points.rows());
  const test::TestSimilarity Q = test::randomSimilarity(c.dim, 17);
  const Eigen::MatrixXd out = deformer->deform(Q.apply(cage.vertices), kParams);
  EXPECT_LT((out - Q.apply(points)).rowwise().norm().maxCoeff(), 1e-9 * cageDiameter(Q.apply(cage.vertices)));
}

TEST_P(ExteriorPointsTest, FloatStorageMatchesDouble) {
  // The exterior rows are stored like any other: float storage within 1e-5 diameters of double (engine.md).
  const Case& c = GetParam();
  const Cage cage = testCage(c.dim);
  const Eigen::MatrixXd points = test::randomBoxPoints(100, c.dim, -1.5, 1.5, 7);
  PrecomputeOptions floats;
  floats.floatStorage = true;
  const Eigen::MatrixXd posed = bentPose(cage);
  const Eigen::MatrixXd exact = makeDeformer(c.method, cage, points)->deform(posed, kParams);
  const Eigen::MatrixXd rounded = makeDeformer(c.method, cage, points, floats)->deform(posed, kParams);
  EXPECT_LT((exact - rounded).rowwise().norm().maxCoeff(), 1e-5 * cageDiameter(posed));
}

// Float storage of a 3D cage's Somigliana rows is streamed in whole packs of points (somigliana_method.cpp:
// streamFrameGroup) and the rest written point by point; double storage is written point by point (writeFrameRow).
// The float C is the double C rounded, entry by entry, exterior rows and proxies included, with the same diagnostics:
// 101 points, a third of them outside, so exterior lanes inside whole packs and a part pack at the end.
TEST(ExteriorPoints, SomiglianaFloatRowsAreTheDoubleRowsRounded) {
  const Cage cage = testCage(3);
  const Eigen::MatrixXd points = test::randomBoxPoints(101, 3, -1.2, 1.2, 11);
  PrecomputeOptions floats;
  floats.floatStorage = true;
  const auto exact = makeDeformer(methods::somigliana(), cage, points);
  const auto rounded = makeDeformer(methods::somigliana(), cage, points, floats);
  const FrameCoordinates &C = exact->frameCoordinates(), &F = rounded->frameCoordinates();
  ASSERT_EQ(F.floats.rows(), C.doubles.rows());
  ASSERT_EQ(F.floats.cols(), C.doubles.cols());
  EXPECT_EQ((F.floats.array() != C.doubles.cast<float>().array()).count(), 0);
  EXPECT_GT(exact->diagnostics().exteriorCount(), 10);
  EXPECT_EQ(rounded->diagnostics().regions, exact->diagnostics().regions);
  EXPECT_EQ(rounded->diagnostics().winding, exact->diagnostics().winding);
  EXPECT_EQ(rounded->diagnostics().unityResidual, exact->diagnostics().unityResidual);
}

INSTANTIATE_TEST_SUITE_P(Methods, ExteriorPointsTest,
                         ::testing::Values(Case{"somigliana3d", 3, methods::somigliana()},
                                           Case{"somigliana2d", 2, methods::somigliana()},
                                           Case{"green3d", 3, methods::green()}, Case{"green2d", 2, methods::green()},
                                           Case{"bem3d", 3, methods::bem()}, Case{"bem2d", 2, methods::bem()}),
                         test::methodCaseName);

TEST(ExteriorPoints, ProxiesAreInsideWithAccurateIntegrals) {
  // h = 1e-5 diameters puts the proxies of face, edge and vertex points inside (winding number 1) with their
  // closed-form integrals at round-off: max |sum T_i - I| <= 1e-11 (kUnreliableResidual is 1e-8).
  for (int dim : {3, 2}) {
    const Cage cage = testCage(dim);
    const std::vector<CagePoint> onCage = cagePoints(cage);
    Eigen::MatrixXd points(static_cast<Eigen::Index>(onCage.size()), dim);
    for (std::size_t k = 0; k < onCage.size(); ++k) points.row(static_cast<Eigen::Index>(k)) = onCage[k].point;
    const ExteriorPlan plan =
        planExteriorPoints(cage, points, std::vector<PointRegion>(onCage.size(), PointRegion::OnCage));
    const SomiglianaCoordinates coords = computeSomiglianaCoordinates(cage, plan.proxies);
    EXPECT_GT(coords.winding.minCoeff(), 1 - 1e-12) << dim << "D";
    const double worst = partitionOfUnityResidual(coords).maxCoeff();
    EXPECT_LE(worst, 1e-11) << dim << "D";
    std::printf("[ %dD ] proxies: max |sum T_i - I| = %.2g\n", dim, worst);
  }
}

TEST(ExteriorPoints, MeanValueCoordinatesStayFiniteOnAndNearTheCage) {
  // MVC need no rule (they interpolate the cage): finite on faces, edges and vertices and at +-eps, and continuous
  // across the cage to 1e-6 diameters at eps = 1e-9 diameters.
  for (int dim : {3, 2}) {
    const Cage cage = testCage(dim);
    const double diameter = cageDiameter(cage.vertices);
    const std::vector<CagePoint> onCage = cagePoints(cage);
    Eigen::MatrixXd points(3 * static_cast<Eigen::Index>(onCage.size()), dim);
    for (std::size_t k = 0; k < onCage.size(); ++k)
      for (int side = -1; side <= 1; ++side)
        points.row(3 * static_cast<Eigen::Index>(k) + side + 1) =
            (onCage[k].point + side * 1e-9 * diameter * onCage[k].normal).transpose();
    const auto deformer = makeDeformer(methods::mvc(), cage, points);
    const Eigen::MatrixXd out = deformer->deform(bentPose(cage), kParams);
    ASSERT_TRUE(out.allFinite()) << dim << "D";
    for (std::size_t k = 0; k < onCage.size(); ++k) {
      const Eigen::Index at = 3 * static_cast<Eigen::Index>(k);
      EXPECT_LT((out.row(at) - out.row(at + 2)).norm(), 1e-6 * diameter) << dim << "D " << onCage[k].what;
      EXPECT_LT((out.row(at + 1) - out.row(at)).norm(), 1e-6 * diameter) << dim << "D " << onCage[k].what;
    }
  }
}

TEST(ExteriorPoints, ClosestPointsAndPseudoNormalsOnACube) {
  // The cube [-1, 1]^3: a face, an edge and a corner region, each with its pseudo-normal; exact to 1e-15.
  const CageProximity cube(test::makeCube());
  struct Expected {
    Eigen::Vector3d x, point, normal;
  };
  const double r2 = 1 / std::sqrt(2.0), r3 = 1 / std::sqrt(3.0);
  const std::vector<Expected> cases = {
      {{2, 0.3, -0.2}, {1, 0.3, -0.2}, {1, 0, 0}},  // face x = 1
      {{2, 2, 0.3}, {1, 1, 0.3}, {r2, r2, 0}},      // edge x = y = 1
      {{-3, -2, 4}, {-1, -1, 1}, {-r3, -r3, r3}},   // corner (-1, -1, 1): all angles equal
      {{0.5, 0.2, 0.9}, {0.5, 0.2, 1}, {0, 0, 1}},  // inside, closest to the face z = 1
      {{1, 1, -0.5}, {1, 1, -0.5}, {r2, r2, 0}},    // on an edge
  };
  for (const Expected& e : cases) {
    const CageProximity::Closest c = cube.closest(e.x);
    EXPECT_LT((c.point - e.point).norm(), 1e-15) << e.x.transpose();
    EXPECT_LT((c.normal - e.normal).norm(), 1e-15) << e.x.transpose();
    EXPECT_NEAR(c.distance, (e.x - e.point).norm(), 1e-15) << e.x.transpose();
  }
  // 2D: the unit square's corner normal is the normalised sum of its two edge normals.
  Eigen::MatrixXd square(4, 2);
  square << 0, 0, 1, 0, 1, 1, 0, 1;
  const CageProximity::Closest corner = CageProximity(makePolygonCage(square)).closest(Eigen::Vector2d(2, 3));
  EXPECT_LT((corner.normal - Eigen::Vector2d(r2, r2)).norm(), 1e-15);
  EXPECT_LT((corner.point - Eigen::Vector2d(1, 1)).norm(), 1e-15);
}

TEST(ExteriorPoints, WeightIsC2WithTheStatedEnds) {
  // w(0) = 1, w(band) = 0, w(d) = 0 beyond; w' and w'' vanish at both ends (central differences, step 1e-4:
  // truncation ~1e-7 for w', ~1e-3 for w'' against max|w''| = 5.77).
  const double band = 2.0, h = 1e-4 * band;
  EXPECT_EQ(exteriorWeight(0, band), 1.0);
  EXPECT_EQ(exteriorWeight(band, band), 0.0);
  EXPECT_EQ(exteriorWeight(3 * band, band), 0.0);
  EXPECT_NEAR(exteriorWeight(0.5 * band, band), 0.5, 1e-15);
  for (double d : {0.0, band}) {
    const double first = (exteriorWeight(d + h, band) - exteriorWeight(d - h, band)) / (2 * h);
    const double second =
        (exteriorWeight(d + h, band) - 2 * exteriorWeight(d, band) + exteriorWeight(d - h, band)) / (h * h);
    EXPECT_NEAR(first, 0, 1e-6) << d;
    EXPECT_NEAR(second * band * band, 0, 1e-2) << d;
  }
}

}  // namespace
}  // namespace somicage
