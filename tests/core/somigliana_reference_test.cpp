// The Somigliana deformer against an independent evaluation of Eq. 11 (reference/somigliana_reference.h: adaptive
// Gauss-Legendre quadrature of the kernels of Eqs. 3-4, boundary conditions written from docs/method.md), on poses that
// are not similarities (a smooth random perturbation, a twist, a bend), in 2D and 3D, for the global, local and
// blended variants, several nu and gamma, with and without the traction correction. The similarity and rest-pose
// tests (somigliana_deformer_test.cpp) cannot see a rotation given to the wrong vertex, a mis-signed kernel term or
// a wrong stretch: all of them cancel when every R_i is the same; these cannot.
//
// Tolerance: 1e-10 cage diameters. The reference (order 10, pieces of diameter <= dist / 2) reproduces the identity
// of Eq. 7 to ~5e-15 at every test point, and its distance to the core falls with the order as fast as its own error
// does (QuadratureConverges*, DifferenceFallsWithTheGaussOrder: 4e-5, 4e-9, 7e-13, 5e-16 at orders 2, 4, 6, 8);
// measured |core - reference| <= 1.3e-14 diameters over every pose and parameter set here. 1e-10 leaves four
// orders of magnitude for other compilers and machines and still sees an error of a single float rounding.
#include "reference/somigliana_reference.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "deform/deformer.h"
#include "methods/method_descriptors.h"
#include "test_shapes.h"

namespace somicage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTolerance = 1e-10;  // cage diameters

// ---- Poses that are not similarities --------------------------------------------------------------------------

// Every vertex moved by a smooth random field: three sine waves of random direction, phase and amplitude.
Eigen::MatrixXd smoothPerturbation(const Eigen::MatrixXd& V, double amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  const int d = static_cast<int>(V.cols());
  const double frequency = 3 / cageDiameter(V);
  Eigen::MatrixXd P = V;
  for (int wave = 0; wave < 3; ++wave) {
    Eigen::VectorXd direction(d), displacement(d);
    for (int a = 0; a < d; ++a) direction(a) = uniform(rng), displacement(a) = amplitude * uniform(rng);
    const double phase = M_PI * uniform(rng);
    for (int i = 0; i < V.rows(); ++i)
      P.row(i) += std::sin(frequency * V.row(i).dot(direction.normalized()) + phase) * displacement.transpose();
  }
  return P;
}

// A twist about the z axis through (cx, cy): angle `rate` per unit of height.
Eigen::MatrixXd twist(const Eigen::MatrixXd& V, double cx, double cy, double rate) {
  Eigen::MatrixXd P = V;
  for (int i = 0; i < V.rows(); ++i) {
    const Eigen::Vector2d xy =
        Eigen::Rotation2Dd(rate * V(i, 2)) * Eigen::Vector2d(V(i, 0) - cx, V(i, 1) - cy) + Eigen::Vector2d(cx, cy);
    P(i, 0) = xy.x(), P(i, 1) = xy.y();
  }
  return P;
}

// A bend of the x axis into an arc of the given radius in the xy plane (lengths along x and across kept).
Eigen::MatrixXd bend(const Eigen::MatrixXd& V, double radius) {
  Eigen::MatrixXd P = V;
  for (int i = 0; i < V.rows(); ++i) {
    const double angle = V(i, 0) / radius, across = radius - V(i, 1);
    P(i, 0) = across * std::sin(angle);
    P(i, 1) = radius - across * std::cos(angle);
  }
  return P;
}

// ---- Scenes ---------------------------------------------------------------------------------------------------

// Points with winding number 1 at distance >= 1e-2 cage diameters from the cage: half uniform in the bounding box,
// half within 1e-2 ... 3e-2 diameters of a random face (where the integrands are nearly singular).
Eigen::MatrixXd interiorPoints(const Cage& cage, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::uniform_int_distribution<int> anyFace(0, cage.numFaces() - 1);
  const double diameter = cageDiameter(cage.vertices);
  const Eigen::RowVectorXd lo = cage.vertices.colwise().minCoeff(), hi = cage.vertices.colwise().maxCoeff();
  Eigen::MatrixXd points(count, cage.dim());
  for (int p = 0; p < count;) {
    Eigen::VectorXd x(cage.dim());
    if (p % 2 == 0) {
      for (int a = 0; a < cage.dim(); ++a) x(a) = lo(a) + (hi(a) - lo(a)) * uniform(rng);
    } else {
      const int j = anyFace(rng);
      Eigen::VectorXd n;
      double area;
      reference::faceGeometry(cage, cage.vertices, j, n, area);
      double u = uniform(rng), v = cage.dim() == 3 ? uniform(rng) : 0;
      if (u + v > 1) u = 1 - u, v = 1 - v;
      x = ((1 - u - v) * cage.vertices.row(cage.faces(j, 0)) + u * cage.vertices.row(cage.faces(j, 1))).transpose();
      if (cage.dim() == 3) x += v * cage.vertices.row(cage.faces(j, 2)).transpose();
      x -= (0.01 + 0.02 * uniform(rng)) * diameter * n;
    }
    if (reference::windingNumber(cage, x) < 0.5 || reference::distanceToCage(cage, x) < 0.01 * diameter) continue;
    points.row(p++) = x;
  }
  return points;
}

struct ReferenceScene {
  std::string name;
  Cage cage;
  Eigen::MatrixXd posed;
  int numPoints;
};

Cage stretchedIcosphere() {
  Cage cage = test::makeIcosphere(1);
  cage.vertices.col(0) *= 2;
  return cage;
}

Cage stripPolygon() {  // [-2, 2] x [-0.5, 0.5], 6 vertices along each long side, counter-clockwise
  Eigen::MatrixXd loop(12, 2);
  for (int i = 0; i < 6; ++i) {
    loop.row(i) << -2 + 0.8 * i, -0.5;
    loop.row(11 - i) << -2 + 0.8 * i, 0.5;
  }
  return makePolygonCage(loop);
}

#ifdef SOMICAGE_SANITIZE
constexpr int kPoints3 = 2, kPoints2 = 6, kCheckPoints = 2;  // instrumented code is ~20x slower
#else
constexpr int kPoints3 = 14, kPoints2 = 24, kCheckPoints = 5;  // per scene; per check of the reference
#endif

std::vector<ReferenceScene> referenceScenes() {
  const Cage bumpy = test::makeBumpySphere(1), el = test::makeExtrudedL(), bar = stretchedIcosphere();
  const Cage star = test::makeStarPolygon(6), strip = stripPolygon();
  return {
      {"3D_bumpy_sphere_perturbed", bumpy, smoothPerturbation(bumpy.vertices, 0.2, 3), kPoints3},
      {"3D_L_twisted", el, twist(el.vertices, 1, 1, 0.9), kPoints3},
      {"3D_stretched_sphere_bent", bar, bend(bar.vertices, 2.5), kPoints3},
      {"2D_star_perturbed", star, smoothPerturbation(star.vertices, 0.15, 4), kPoints2},
      {"2D_strip_bent", strip, bend(strip.vertices, 2.0), kPoints2},
  };
}

// The core deformer, through its narrowest entry point, on one thread (the frames here are tiny, and OpenMP's
// spinning workers only slow a busy machine down).
std::unique_ptr<CageDeformer> coreDeformer(const Cage& cage, const Eigen::MatrixXd& points) {
  PrecomputeOptions options;
  options.threads = 1;
  return makeDeformer(methods::somigliana(), cage, points, options);
}

DeformParams coreParams(const reference::PoseParameters& p) {
  return DeformParams{p.blend, p.nu, p.gamma, p.tractionCorrection};
}

std::string describe(const reference::PoseParameters& p) {
  return "blend " + std::to_string(p.blend) + " nu " + std::to_string(p.nu) + " gamma " + std::to_string(p.gamma) +
         (p.tractionCorrection ? " fix" : " nofix");
}

// ---- The reference itself -------------------------------------------------------------------------------------

// Eq. 7 at rest, x = sum_i T_i v_i + c sum_j K_j n_j, holds only with the right kernels, coefficients and signs
// (c = 2[1 + d nu/(1 - 2nu)]): the reference's error on it falls with the Gauss order, to <= 1e-12 diameters at
// order 10, which is the accuracy the deformer tests below rely on.
TEST(SomiglianaReference, QuadratureConvergesToTheIdentityOfEq7) {
  for (const Cage& cage : {test::makeBumpySphere(1), test::makeStarPolygon(6)}) {
    const int d = cage.dim();
    const Eigen::MatrixXd points = interiorPoints(cage, kCheckPoints, 11);
    const double diameter = cageDiameter(cage.vertices);
    const std::vector<double> nus = {0.0, 0.3, -0.5};
    std::vector<double> errors;
    for (int order : {2, 4, 6, 8, 10}) {
      double worst = 0;
      for (int p = 0; p < points.rows(); ++p) {
        const Eigen::VectorXd x = points.row(p).transpose();
        const auto coordinates = reference::integrateCoordinates(cage, x, nus, {order, 0.5, 40});
        for (size_t k = 0; k < nus.size(); ++k) {
          const double c = 2 * (1 + d * nus[k] / (1 - 2 * nus[k]));
          Eigen::VectorXd sum = Eigen::VectorXd::Zero(d);
          Eigen::MatrixXd unity = -Eigen::MatrixXd::Identity(d, d);
          for (int i = 0; i < cage.numVertices(); ++i)
            sum += coordinates[k].T[i] * cage.vertices.row(i).transpose(), unity += coordinates[k].T[i];
          for (int j = 0; j < cage.numFaces(); ++j) {
            Eigen::VectorXd n;
            double area;
            reference::faceGeometry(cage, cage.vertices, j, n, area);
            sum += c * coordinates[k].K[j] * n;
          }
          worst = std::max({worst, (sum - x).norm() / diameter, unity.cwiseAbs().maxCoeff()});  // Eqs. 7, 9
        }
      }
      errors.push_back(worst);
      std::printf("  %dD order %2d: largest Eq. 7/9 residual %.1e\n", d, order, worst);
    }
    for (size_t k = 1; k < errors.size(); ++k)
      EXPECT_LT(errors[k], 0.2 * errors[k - 1] + 1e-14) << d << "D, order " << 2 * k + 2 << ": " << errors[k];
    EXPECT_LE(errors.back(), 1e-12) << d << "D, order 10";
    EXPECT_GT(errors.front(), 1e-6) << d << "D: order 2 should be visibly inexact (else the test shows nothing)";
  }
}

// The reference's own boundary conditions keep a similarity pose a similarity (section 4.3): the check that its
// Umeyama, rotations, bulging and Eq. 15 agree with one another before the deformer is compared with them.
TEST(SomiglianaReference, ReproducesASimilarityPose) {
  for (const Cage& cage : {test::makeBumpySphere(1), test::makeStarPolygon(6)}) {
    const test::TestSimilarity similarity = test::randomSimilarity(cage.dim(), 5);
    const Eigen::MatrixXd moved = similarity.apply(cage.vertices), points = interiorPoints(cage, kCheckPoints, 2);
    for (const reference::PoseParameters& p :
         {reference::PoseParameters{0, 0.3, 1.5, true}, reference::PoseParameters{1, -0.5, 0, false},
          reference::PoseParameters{0.5, kInf, 2, true}}) {
      const reference::BoundaryConditions bc = reference::boundaryConditions(cage, moved, p);
      for (int q = 0; q < points.rows(); ++q) {
        const Eigen::VectorXd x = points.row(q).transpose();
        const auto coordinates = reference::integrateCoordinates(cage, x, {p.nu});
        const Eigen::VectorXd expected = similarity.apply(points.row(q)).transpose();
        EXPECT_LT((reference::deformPoint(cage, moved, coordinates[0], bc) - expected).norm(),
                  1e-10 * cageDiameter(moved))
            << cage.dim() << "D " << describe(p);
      }
    }
  }
}

// ---- The core deformer against it -----------------------------------------------------------------------------

class SomiglianaAgainstReference : public ::testing::TestWithParam<ReferenceScene> {};

TEST_P(SomiglianaAgainstReference, DeformedPointsMatchEq11) {
  const ReferenceScene& scene = GetParam();
  const Cage& cage = scene.cage;
  const Eigen::MatrixXd points = interiorPoints(cage, scene.numPoints, 17);
  const double diameter = cageDiameter(scene.posed);
  const std::vector<double> nus = {0.0, 0.3, 0.45, -0.5, kInf};
  std::vector<std::vector<reference::Coordinates>> coordinates;  // [point][nu]
  for (int p = 0; p < points.rows(); ++p)
    coordinates.push_back(reference::integrateCoordinates(cage, points.row(p).transpose(), nus));

  const auto deformer = coreDeformer(cage, points);
  double worst = 0, globalToLocal = 0;
  for (size_t k = 0; k < nus.size(); ++k)
    for (double gamma : {0.0, 1.5})
      for (bool fix : {true, false}) {
        Eigen::MatrixXd global;
        for (double blend : {0.0, 0.5, 1.0}) {
          const reference::PoseParameters p{blend, nus[k], gamma, fix};
          const reference::BoundaryConditions bc = reference::boundaryConditions(cage, scene.posed, p);
          Eigen::MatrixXd expected(points.rows(), cage.dim());
          for (int q = 0; q < points.rows(); ++q)
            expected.row(q) = reference::deformPoint(cage, scene.posed, coordinates[q][k], bc).transpose();
          const Eigen::MatrixXd actual = deformer->deform(scene.posed, coreParams(p));
          const double error = (actual - expected).rowwise().norm().maxCoeff() / diameter;
          worst = std::max(worst, error);
          EXPECT_LE(error, kTolerance) << describe(p) << ": largest difference " << error << " cage diameters";
          if (blend == 0) global = expected;
          if (blend == 1) globalToLocal = std::max(globalToLocal, (expected - global).rowwise().norm().maxCoeff());
        }
      }
  RecordProperty("largest_difference_in_diameters", std::to_string(worst));
  std::printf("  %s: largest |core - reference| %.1e cage diameters over %d parameter sets\n", scene.name.c_str(),
              worst, 60);
  // The test has power only if the pose is not a similarity: the local variant must move points away from the
  // global one (they coincide on similarities).
  EXPECT_GT(globalToLocal / diameter, 1e-3) << "the pose is too close to a similarity to test anything";
}

INSTANTIATE_TEST_SUITE_P(Poses, SomiglianaAgainstReference, ::testing::ValuesIn(referenceScenes()),
                         [](const auto& info) { return info.param.name; });

// The difference between core and reference falls with the reference's Gauss order until it reaches round-off:
// the agreement above is the quadrature converging onto the core, not a coincidence at one order.
TEST(SomiglianaAgainstReference, DifferenceFallsWithTheGaussOrder) {
  const Cage cage = test::makeBumpySphere(1);
  const Eigen::MatrixXd posed = smoothPerturbation(cage.vertices, 0.2, 3),
                        points = interiorPoints(cage, kCheckPoints, 23);
  const reference::PoseParameters p{0.5, 0.3, 1.5, true};
  const Eigen::MatrixXd actual = coreDeformer(cage, points)->deform(posed, coreParams(p));
  const reference::BoundaryConditions bc = reference::boundaryConditions(cage, posed, p);
  std::vector<double> errors;
  for (int order : {2, 4, 6, 8, 10}) {
    double worst = 0;
    for (int q = 0; q < points.rows(); ++q) {
      const auto coordinates = reference::integrateCoordinates(cage, points.row(q).transpose(), {p.nu}, {order});
      worst =
          std::max(worst, (reference::deformPoint(cage, posed, coordinates[0], bc) - actual.row(q).transpose()).norm());
    }
    errors.push_back(worst / cageDiameter(posed));
    std::printf("  order %2d: largest |core - reference| %.1e cage diameters\n", order, errors.back());
  }
  for (size_t k = 1; k < errors.size(); ++k)
    EXPECT_LT(errors[k], 0.2 * errors[k - 1] + 1e-13) << "order " << 2 * k + 2 << ": " << errors[k];
  EXPECT_LE(errors.back(), kTolerance);
}

}  // namespace
}  // namespace somicage
