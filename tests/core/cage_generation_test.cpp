// core/generation/cage_generation.h on meshes made here: a knotted tube (genus 1, knotted), two separate spheres (two
// components), an open hemisphere (a boundary), a thin plate, and one shape at 1e-3 and 1e3 scale. Each generated
// cage is checked by generated_cage_checks.h, independently of the CGAL predicates the generator uses.
#include "generation/cage_generation.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "base/errors.h"
#include "generated_cage_checks.h"
#include "test_shapes.h"

namespace somicage {
namespace {

struct TriangleMesh {
  Eigen::MatrixXd vertices;
  Eigen::MatrixXi triangles;
};

TriangleMesh fromCage(const Cage& cage) { return {cage.vertices, cage.faces}; }

// A tube of radius 0.3 around the (2, 3) torus knot, `along` rings of `around` vertices.
TriangleMesh torusKnot(int along = 96, int around = 8) {
  const auto curve = [](double t) {
    return Eigen::Vector3d((2 + std::cos(3 * t)) * std::cos(2 * t), (2 + std::cos(3 * t)) * std::sin(2 * t),
                           std::sin(3 * t));
  };
  TriangleMesh mesh;
  mesh.vertices.resize(along * around, 3);
  mesh.triangles.resize(2 * along * around, 3);
  for (int i = 0; i < along; ++i) {
    const double t = 2 * M_PI * i / along;
    const Eigen::Vector3d tangent = (curve(t + 1e-4) - curve(t - 1e-4)).normalized();
    const Eigen::Vector3d u = tangent.cross(Eigen::Vector3d::UnitZ()).normalized(), v = tangent.cross(u);
    for (int k = 0; k < around; ++k) {
      const double a = 2 * M_PI * k / around;
      mesh.vertices.row(i * around + k) = curve(t) + 0.3 * (std::cos(a) * u + std::sin(a) * v);
    }
  }
  for (int i = 0; i < along; ++i)
    for (int k = 0; k < around; ++k) {
      const int a = i * around + k, b = i * around + (k + 1) % around;
      const int c = ((i + 1) % along) * around + k, d = ((i + 1) % along) * around + (k + 1) % around;
      mesh.triangles.row(2 * a) << a, c, b;
      mesh.triangles.row(2 * a + 1) << b, c, d;
    }
  return mesh;
}

TriangleMesh twoSpheres() {
  const Cage sphere = test::makeIcosphere(2);
  TriangleMesh mesh;
  const int n = sphere.numVertices(), f = sphere.numFaces();
  mesh.vertices.resize(2 * n, 3);
  mesh.triangles.resize(2 * f, 3);
  mesh.vertices.topRows(n) = sphere.vertices.rowwise() - Eigen::RowVector3d(2, 0, 0);
  mesh.vertices.bottomRows(n) = sphere.vertices.rowwise() + Eigen::RowVector3d(2, 0, 0);
  mesh.triangles.topRows(f) = sphere.faces;
  mesh.triangles.bottomRows(f) = sphere.faces.array() + n;
  return mesh;
}

// The faces of a unit icosphere above the equator (an open surface with one boundary loop).
TriangleMesh hemisphere() {
  const Cage sphere = test::makeIcosphere(3);
  std::vector<int> kept;
  for (int j = 0; j < sphere.numFaces(); ++j) {
    double z = 0;
    for (int k = 0; k < 3; ++k) z += sphere.vertices(sphere.faces(j, k), 2);
    if (z > 0) kept.push_back(j);
  }
  std::vector<int> index(sphere.numVertices(), -1);  // only the vertices of the kept faces
  TriangleMesh mesh{Eigen::MatrixXd(0, 3), Eigen::MatrixXi(kept.size(), 3)};
  std::vector<int> used;
  for (size_t j = 0; j < kept.size(); ++j)
    for (int k = 0; k < 3; ++k) {
      int& i = index[sphere.faces(kept[j], k)];
      if (i < 0) i = static_cast<int>(used.size()), used.push_back(sphere.faces(kept[j], k));
      mesh.triangles(j, k) = i;
    }
  mesh.vertices.resize(used.size(), 3);
  for (size_t i = 0; i < used.size(); ++i) mesh.vertices.row(i) = sphere.vertices.row(used[i]);
  return mesh;
}

// A 2 x 2 x 0.01 box: thinner than any voxel of the offset surface.
TriangleMesh thinPlate() {
  TriangleMesh mesh = fromCage(test::makeCube());
  mesh.vertices.col(2) *= 0.005;
  return mesh;
}

GeneratedCage generate(const TriangleMesh& mesh, int maxFaces) {
  CageGenerationOptions options;
  options.maxFaces = maxFaces;
  return generateCage(mesh.vertices, mesh.triangles, options, "test mesh");
}

void expectValidCage(const TriangleMesh& mesh, int maxFaces) {
  const GeneratedCage generated = generate(mesh, maxFaces);
  test::expectGeneratedCageValid(generated.cage, mesh.vertices, mesh.triangles, maxFaces, 200);
  EXPECT_GE(generated.minAngleDegrees, 1.0);
}

TEST(CageGeneration, TorusKnot) { expectValidCage(torusKnot(), 150); }

TEST(CageGeneration, TwoSeparateSpheresGetTwoShells) {
  const TriangleMesh mesh = twoSpheres();
  const GeneratedCage generated = generate(mesh, 100);
  test::expectGeneratedCageValid(generated.cage, mesh.vertices, mesh.triangles, 100, 200);
  EXPECT_EQ(validateCage(generated.cage).components, 2);  // the gap (2) is far wider than the closing
}

TEST(CageGeneration, OpenHemisphere) { expectValidCage(hemisphere(), 60); }

TEST(CageGeneration, ThinPlate) { expectValidCage(thinPlate(), 40); }

// The pipeline works in diagonals: the same shape at 1e-3 and 1e3 gets a valid cage with the same relative margin.
TEST(CageGeneration, ScaleInvariant) {
  const TriangleMesh shape = fromCage(test::makeBumpySphere(3));
  std::vector<double> margins;
  for (double scale : {1e-3, 1e3}) {
    TriangleMesh scaled = shape;
    scaled.vertices *= scale;
    const GeneratedCage generated = generate(scaled, 80);
    test::expectGeneratedCageValid(generated.cage, scaled.vertices, scaled.triangles, 80, 200);
    margins.push_back(generated.margin);
  }
  EXPECT_DOUBLE_EQ(margins[0], margins[1]);
}

TEST(CageGeneration, ReportsProgressAndCancels) {
  const TriangleMesh mesh = fromCage(test::makeBumpySphere(2));
  CageGenerationOptions options;
  options.maxFaces = 60;
  std::vector<double> fractions;
  generateCage(mesh.vertices, mesh.triangles, options, "test mesh", [&](double f) {
    fractions.push_back(f);
    return true;
  });
  ASSERT_FALSE(fractions.empty());
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  EXPECT_THROW(generateCage(mesh.vertices, mesh.triangles, options, "test mesh", [](double f) { return f < 0.3; }),
               Cancelled);
}

TEST(CageGeneration, RejectsUnusableInput) {
  const TriangleMesh mesh = fromCage(test::makeCube());
  CageGenerationOptions options;
  options.maxFaces = 4;
  EXPECT_THROW(generateCage(mesh.vertices, mesh.triangles, options, "m"), InputError);
  options.maxFaces = 100;
  EXPECT_THROW(generateCage(mesh.vertices, Eigen::MatrixXi(0, 3), options, "m"), InputError);
  EXPECT_THROW(generateCage(Eigen::MatrixXd::Zero(3, 3), Eigen::MatrixXi::Zero(1, 3), options, "m"), InputError);
  options.margin = 2;
  EXPECT_THROW(generateCage(mesh.vertices, mesh.triangles, options, "m"), InputError);
}

}  // namespace
}  // namespace somicage
