// The quantities of a pose (core/analysis/deformation_quantities.h, deformation_analysis.h, coordinate_fields.h)
// against closed forms: volumes of known solids, scales and similarities, an independent quadrature of the coordinates,
// and the nu sweep against single evaluations.
#include "analysis/deformation_quantities.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "analysis/coordinate_fields.h"
#include "analysis/deformation_analysis.h"
#include "base/errors.h"
#include "method_cases.h"
#include "methods/method_descriptors.h"
#include "test_shapes.h"

namespace somicage {
namespace {

std::vector<std::vector<int>> facesOf(const Cage& cage) {
  std::vector<std::vector<int>> faces;
  for (int j = 0; j < cage.numFaces(); ++j) faces.push_back({cage.faces(j, 0), cage.faces(j, 1), cage.faces(j, 2)});
  return faces;
}

TEST(DeformationQuantities, VolumesOfKnownSolids) {
  const Cage cube = test::makeCube();  // [-1, 1]^3
  const std::vector<std::vector<int>> faces = facesOf(cube);
  EXPECT_TRUE(isClosedMesh(faces));
  const Eigen::MatrixXd scaled = 1.5 * cube.vertices;
  const EnclosedMeasure m = enclosedMeasure(faces, cube.vertices, scaled);
  EXPECT_TRUE(m.closed);
  EXPECT_NEAR(m.rest, 8, 1e-12);
  EXPECT_NEAR(m.deformed, 8 * 1.5 * 1.5 * 1.5, 1e-12);
  EXPECT_NEAR(m.change(), 1.5 * 1.5 * 1.5 - 1, 1e-12);
  // Reversed faces: negative volume.
  std::vector<std::vector<int>> flipped = faces;
  for (auto& f : flipped) std::swap(f[1], f[2]);
  EXPECT_NEAR(enclosedMeasure(flipped, cube.vertices, cube.vertices).rest, -8, 1e-12);
}

// A cube with one face pair removed has a planar square hole: closed = false, and the capped volume is exact.
TEST(DeformationQuantities, OpenMeshIsSaidOpenAndItsPlanarHoleCappedExactly) {
  const Cage cube = test::makeCube();
  std::vector<std::vector<int>> faces = facesOf(cube);
  faces.erase(faces.begin(), faces.begin() + 2);  // the x = +1 side
  EXPECT_FALSE(isClosedMesh(faces));
  EXPECT_EQ(boundaryVertices(faces).size(), 4u);
  const EnclosedMeasure m = enclosedMeasure(faces, cube.vertices, 2 * cube.vertices);
  EXPECT_FALSE(m.closed);
  EXPECT_NEAR(m.rest, 8, 1e-12);
  EXPECT_NEAR(m.change(), 7, 1e-12);
}

TEST(DeformationQuantities, AreasIn2dAndFaceRatios) {
  Eigen::MatrixXd square(4, 2);
  square << 0, 0, 2, 0, 2, 1, 0, 1;
  const std::vector<std::vector<int>> faces = {{0, 1, 2, 3}};
  Eigen::MatrixXd stretched = square;
  stretched.col(0) *= 3;  // area x3, longest edge stretch 3
  const EnclosedMeasure m = enclosedMeasure(faces, square, stretched);
  EXPECT_NEAR(m.rest, 2, 1e-14);
  EXPECT_NEAR(m.change(), 2, 1e-14);
  const FaceQuantities q = faceQuantities(faces, square, stretched);
  EXPECT_NEAR(q.areaRatio(0), 3, 1e-14);
  EXPECT_NEAR(q.edgeStretch(0), 3, 1e-14);
  // A mirror flips the 2D face: negative area ratio.
  Eigen::MatrixXd mirrored = square;
  mirrored.col(0) *= -1;
  EXPECT_NEAR(faceQuantities(faces, square, mirrored).areaRatio(0), -1, 1e-14);
}

TEST(DeformationQuantities, DeterminantDistortionAndFoldovers) {
  Eigen::MatrixXd J(4, 9);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Matrix3d similarity = 2 * R, stretch = Eigen::Vector3d(1, 2, 4).asDiagonal();
  const Eigen::Matrix3d mirror = Eigen::Vector3d(-1, 1, 1).asDiagonal();
  const Eigen::Matrix3d rows[3] = {similarity, stretch, mirror * R};
  for (int p = 0; p < 3; ++p)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) J(p, a * 3 + b) = rows[p](a, b);
  J.row(3).setConstant(std::nan(""));
  const PointQuantities q = pointQuantities(J, 3);
  EXPECT_NEAR(q.detJ(0), 8, 1e-12);
  EXPECT_NEAR(q.distortion(0), 1, 1e-12);
  EXPECT_NEAR(q.detJ(1), 8, 1e-12);
  EXPECT_NEAR(q.distortion(1), 4, 1e-12);
  EXPECT_NEAR(q.detJ(2), -1, 1e-12);
  EXPECT_NEAR(q.distortion(2), 1, 1e-12);
  EXPECT_TRUE(std::isnan(q.detJ(3)));
  EXPECT_EQ(q.foldovers, 1);
  EXPECT_EQ(q.undefined, 1);
}

TEST(DeformationQuantities, QuantilesInterpolateOrderStatisticsAndSkipNaN) {
  Eigen::VectorXd v(6);
  v << 5, 1, std::nan(""), 3, 2, 4;
  EXPECT_EQ(quantile(v, 0), 1);
  EXPECT_EQ(quantile(v, 1), 5);
  EXPECT_EQ(quantile(v, 0.5), 3);
  EXPECT_DOUBLE_EQ(quantile(v, 0.95), 4.8);
}

// Two deformations of the same points, one translated by t: |t| / diameter at every point; the same one: 0.
TEST(DeformationQuantities, DifferenceOfTwoDeformationsInDiameters) {
  const Eigen::MatrixXd a = test::randomBallPoints(6, 1, 2);
  Eigen::MatrixXd b = a;
  b.col(0).array() += 0.3;
  b.col(2).array() -= 0.4;
  const Eigen::VectorXd d = pointDifference(a, b, 2.0);
  for (int p = 0; p < 6; ++p) EXPECT_NEAR(d(p), 0.5 / 2.0, 1e-15);
  EXPECT_EQ(pointDifference(a, a, 2.0).maxCoeff(), 0);
}

// A uniform scale s of the cage: J = s I for every method, so det J = s^3, distortion 1, volume change s^3 - 1.
TEST(DeformationAnalysis, UniformScaleGivesCubedVolumeForEveryMethod) {
  const Cage cage = test::makeBumpySphere(1);
  const Cage small = test::makeIcosphere(1);  // a closed mesh inside, radius 0.5
  const Eigen::MatrixXd mesh = 0.5 * small.vertices;
  const double s = 1.3;
  for (Method method : {methods::somigliana(), methods::green(), methods::mvc()}) {
    const auto deformer = makeDeformer(method, cage, mesh);
    const DeformationGradients gradients(*deformer, mesh);
    const DeformationAnalysis a =
        analyzeDeformation(gradients, mesh, facesOf(small), s * cage.vertices, {1.0, 0.4, 0.5, true});
    EXPECT_NEAR(quantile(a.points.detJ, 0), s * s * s, 1e-9) << methodName(method);
    EXPECT_NEAR(quantile(a.points.detJ, 1), s * s * s, 1e-9) << methodName(method);
    EXPECT_NEAR(quantile(a.points.distortion, 1), 1, 1e-9) << methodName(method);
    EXPECT_TRUE(a.volume.closed);
    EXPECT_NEAR(a.volume.change(), s * s * s - 1, 1e-9) << methodName(method);
    EXPECT_NEAR(quantile(a.faces.areaRatio, 0.5), s * s, 1e-9);
  }
}

// The sweep only changes nu: each entry equals a single analysis at that nu.
TEST(DeformationAnalysis, SweepEntriesEqualSingleAnalyses) {
  const Cage cage = test::makeBumpySphere(1);
  const Cage small = test::makeIcosphere(1);
  const Eigen::MatrixXd mesh = 0.5 * small.vertices;
  const Eigen::MatrixXd posed = test::bendPose(cage.vertices, 0.5, 7);
  const auto deformer = makeDeformer(methods::somigliana(), cage, mesh);
  const DeformationGradients gradients(*deformer, mesh);
  const std::vector<double> nus = nuSweepValues(-0.9, 0.49, 5);
  ASSERT_EQ(nus.size(), 5u);
  EXPECT_DOUBLE_EQ(nus.front(), -0.9);
  EXPECT_DOUBLE_EQ(nus.back(), 0.49);
  const DeformParams params{1.0, 0.0, 0.3, true};
  const std::vector<NuSweepEntry> sweep = sweepNu(gradients, mesh, facesOf(small), posed, params, nus);
  for (std::size_t k = 0; k < nus.size(); ++k) {
    DeformParams at = params;
    at.nu = nus[k];
    const DeformationAnalysis a = analyzeDeformation(gradients, mesh, facesOf(small), posed, at);
    EXPECT_EQ(sweep[k].nu, nus[k]);
    EXPECT_EQ(sweep[k].volumeChange, a.volume.change());
    EXPECT_EQ(sweep[k].foldovers, a.points.foldovers);
  }
  // nu changes the volume (the point of the sweep): more compressible, more volume change.
  EXPECT_NE(sweep.front().volumeChange, sweep.back().volumeChange);
  EXPECT_THROW(nuSweepValues(-1, 0.3, 5), InputError);
  EXPECT_THROW(nuSweepValues(0, 0.3, 1), InputError);
}

// T_i n_i and K_j n_j against the same coordinates integrated by the paper's quadrature (an independent rule),
// at points far from the cage where the rule is accurate.
TEST(CoordinateFields, EqualTheCoordinateColumnsOfAnIndependentQuadrature) {
  const Cage cage = test::makeIcosphere(1);
  const Eigen::MatrixXd points = test::randomBallPoints(5, 0.3, 4);
  IntegrationOptions gauss;
  gauss.rule = IntegrationOptions::Rule::Gauss;
  gauss.gaussPointsPerSide = 40;
  const SomiglianaCoordinates exact = computeSomiglianaCoordinates(cage, points);
  const SomiglianaCoordinates reference = computeSomiglianaCoordinates(cage, points, gauss);
  const int vertex = 7, face = 11;
  const double nu = 0.35;
  const Eigen::MatrixXd field = vertexCoordinateField(exact, cage, vertex, nu);
  const Eigen::MatrixXd faceField = faceCoordinateField(exact, face, nu);
  // The vertex normal: the area-weighted mean of the incident faces' normals.
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (int j = 0; j < cage.numFaces(); ++j)
    for (int k = 0; k < 3; ++k)
      if (cage.faces(j, k) == vertex) {
        const Eigen::Vector3d a = cage.vertices.row(cage.faces(j, 0)), b = cage.vertices.row(cage.faces(j, 1)),
                              c = cage.vertices.row(cage.faces(j, 2));
        n += (b - a).cross(c - a);
      }
  n.normalize();
  for (int p = 0; p < points.rows(); ++p) {
    const Eigen::VectorXd expected = reference.vertexCoordinate(p, vertex, nu) * n;
    EXPECT_LE((field.row(p).transpose() - expected).norm(), 1e-6 * expected.norm()) << "point " << p;
    const Eigen::VectorXd expectedFace = reference.faceCoordinateTimesNormal(p, face, nu);
    EXPECT_LE((faceField.row(p).transpose() - expectedFace).norm(), 1e-6 * expectedFace.norm()) << "point " << p;
  }
}

// One element's streamed terms (the editor's field view) give the field of the stored coordinate matrix, 2D and 3D.
TEST(CoordinateFields, OneElementsTermsGiveTheStoredMatrixsField) {
  for (int dim : {2, 3}) {
    const Cage cage = dim == 3 ? test::makeIcosphere(1) : test::makeStarPolygon(7);
    const Eigen::MatrixXd points = dim == 3 ? test::randomBallPoints(7, 0.3, 4) : test::randomDiscPoints(7, 0.3, 4);
    const SomiglianaCoordinates all = computeSomiglianaCoordinates(cage, points);
    const int vertex = 3, face = 5;
    for (double nu : {-0.5, 0.3, 0.45}) {
      const ElementTerms v = integrateElementTerms(cage, points, ElementTerms::Kind::Vertex, vertex);
      const ElementTerms f = integrateElementTerms(cage, points, ElementTerms::Kind::Face, face);
      const Eigen::MatrixXd expected = vertexCoordinateField(all, cage, vertex, nu);
      const Eigen::MatrixXd expectedFace = faceCoordinateField(all, face, nu);
      EXPECT_LE((elementCoordinateField(v, nu) - expected).cwiseAbs().maxCoeff(),
                1e-14 * expected.cwiseAbs().maxCoeff());
      EXPECT_LE((elementCoordinateField(f, nu) - expectedFace).cwiseAbs().maxCoeff(),
                1e-14 * expectedFace.cwiseAbs().maxCoeff());
      EXPECT_EQ(v.winding, all.winding);
    }
  }
  EXPECT_THROW(
      integrateElementTerms(test::makeIcosphere(1), Eigen::MatrixXd::Zero(1, 3), ElementTerms::Kind::Face, 999),
      InputError);
}

}  // namespace
}  // namespace somicage
