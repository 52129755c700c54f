// The seams of a volume mesh (core/analysis/seam_jumps.h): where mesh edges cross faces between simplices, and the jump
// of J there: Phong's against a closed form worked out by hand, the smooth methods' 0 to round-off on a shared model.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <map>
#include <set>

#include "analysis/deformation_quantities.h"
#include "analysis/seam_jumps.h"
#include "core/test_models.h"
#include "engine/engine.h"
#include "geometry/simplex_locator.h"
#include "methods/method_descriptors.h"
#include "test_shapes.h"

namespace somicage {
namespace {

// The unit square split by its diagonal from (0, 0) to (1, 1): triangle 0 below it, triangle 1 above.
std::shared_ptr<VolumeMesh> splitSquare() {
  auto mesh = std::make_shared<VolumeMesh>();
  mesh->vertices = test::makeUnitSquare().vertices;
  mesh->simplices.resize(2, 3);
  mesh->simplices << 0, 1, 2, 0, 2, 3;
  return mesh;
}

// A triangle with p0, p2 below the diagonal and p1 above it: edges 0-1 and 1-2 cross it, 0-2 does not.
Eigen::MatrixXd trianglePoints() {
  Eigen::MatrixXd points(3, 2);
  points << 0.8, 0.2, 0.3, 0.6, 0.9, 0.5;
  return points;
}

TEST(SeamJumps, FindsWhereEdgesCrossTheFaceBetweenTwoTriangles) {
  const SeamCrossings c = findSeamCrossings(*splitSquare(), {{0, 1, 2}}, trianglePoints());
  EXPECT_EQ(c.holders, (std::vector<int>{0, 1, 0}));
  ASSERT_EQ(c.edges.size(), 2u);
  EXPECT_EQ(c.edges[0], (std::array<int, 2>{0, 1}));
  EXPECT_EQ(c.edges[1], (std::array<int, 2>{1, 2}));
  ASSERT_EQ(c.points.rows(), 2);
  // On the diagonal x = y: p0 + t (p1 - p0) at t = 2/3, p1 + t (p2 - p1) at t = 3/7.
  EXPECT_NEAR(c.points(0, 0), 0.8 - 0.5 * 2.0 / 3, 1e-15);
  EXPECT_NEAR(c.points(0, 1), 0.8 - 0.5 * 2.0 / 3, 1e-15);
  EXPECT_NEAR(c.points(1, 0), 0.3 + 0.6 * 3.0 / 7, 1e-15);
  EXPECT_NEAR(c.points(1, 1), 0.3 + 0.6 * 3.0 / 7, 1e-15);
  EXPECT_EQ(c.sides[0], (std::array<int, 2>{0, 1}));  // from p0's triangle into p1's
  EXPECT_EQ(c.sides[1], (std::array<int, 2>{1, 0}));
}

// Moving corner 1 by (delta, 0) shears the lower triangle, F_0 = [[1 + delta, -delta], [0, 1]], and leaves the upper
// one, F_1 = I; the diagonal stays put. By the square's mirror symmetry the Phong weights of the diagonal's ends are
// equal, so F_v = (F_0 + I) / 2 there, and on the diagonal every x_i + F_i (X - X_i) is X itself. Phong's
// J = F_t + 1/2 sum_i F_i (X - X_i) g_i^T + 1/2 sum_i l_i F_i then is 3/4 F_0 + 1/4 I below the diagonal and
// 1/4 F_0 + 3/4 I above it: the jump is 1/2 (F_0 - I), of norm delta / sqrt 2, at every point of the diagonal.
TEST(SeamJumps, PhongJumpMatchesItsClosedFormAcrossTheDiagonal) {
  const Cage square = test::makeUnitSquare();
  const double delta = 0.3;
  PrecomputeOptions options;
  options.volumeMesh = splitSquare();
  const Eigen::MatrixXd points = trianglePoints();
  const std::vector<std::vector<int>> faces{{0, 1, 2}};
  const auto deformer = makeDeformer(methods::phong(), square, points, options);
  const auto seams = prepareSeamJumps(*deformer, square, points, faces, options, "faces");
  Eigen::MatrixXd posed = square.vertices;
  posed(1, 0) += delta;
  const SeamJumps jumps = seams->evaluate(posed, {});
  const double below = std::sqrt(std::pow(1 + 0.75 * delta, 2) + std::pow(0.75 * delta, 2) + 1),
               above = std::sqrt(std::pow(1 + 0.25 * delta, 2) + std::pow(0.25 * delta, 2) + 1);
  const double expected = (delta / std::sqrt(2.0)) / (0.5 * (below + above));
  ASSERT_EQ(jumps.edges.size(), 2);
  EXPECT_NEAR(jumps.edges(0), expected, 1e-12);
  EXPECT_NEAR(jumps.edges(1), expected, 1e-12);
  for (int v = 0; v < 3; ++v) EXPECT_NEAR(jumps.vertices(v), expected, 1e-12) << "vertex " << v;
  // The rest pose and an affine one have one F everywhere: no seam.
  EXPECT_LE(seams->evaluate(square.vertices, {}).edges.maxCoeff(), 1e-12);
  Eigen::Matrix2d A;
  A << 1.3, 0.4, -0.2, 0.8;
  EXPECT_LE(seams->evaluate(square.vertices * A.transpose(), {}).edges.maxCoeff(), 1e-12);
}

TEST(SeamJumps, GradientJumpIsTheRelativeFrobeniusDifference) {
  Eigen::RowVectorXd a(4), b(4);
  a << 2, 0, 0, 2;  // |a| = 2 sqrt 2
  b << 1, 0, 0, 1;  // |b| = sqrt 2, |a - b| = sqrt 2
  EXPECT_NEAR(gradientJump(a, b), std::sqrt(2.0) / (1.5 * std::sqrt(2.0)), 1e-15);
  EXPECT_EQ(gradientJump(a, a), 0.0);
  EXPECT_TRUE(std::isnan(gradientJump(a, Eigen::RowVectorXd::Constant(4, NAN))));
  EXPECT_TRUE(std::isnan(gradientJump(Eigen::RowVectorXd::Zero(4), Eigen::RowVectorXd::Zero(4))));
}

// On the shared sphere model (its cage's star: the mesh Phong uses for it): every crossing lies on the face its two
// simplices share, every edge between two simplices is found, the smooth methods' J does not jump (one function of
// the point) and Phong's does.
TEST(SeamJumps, SmoothMethodsDoNotJumpAndPhongDoesOnASharedModel) {
  const test::ModelCase model{"sphere", "sphere.obj", "sphere_cages_triangulated.obj",
                              "sphere_cages_triangulated_deformed.obj", 1.0};
  if (test::skipIfModelAbsent(model)) return;
  const Cage cage = loadCage(test::modelPath(model, model.cage));
  const Cage posedCage = loadCage(test::modelPath(model, model.pose));
  const PolygonMesh mesh = loadMesh(test::modelPath(model, model.mesh));
  const Eigen::MatrixXd points = mesh.vertices;
  const std::shared_ptr<const VolumeMesh> volume = volumeMeshFor(cage, {});
  ASSERT_EQ(volume->numVertices(), cage.numVertices() + 1) << "the sphere's cage is star-shaped: its star";

  const SeamCrossings c = findSeamCrossings(*volume, mesh.faces, points);
  const SimplexLocator locator(*volume);
  for (Eigen::Index k = 0; k < c.points.rows(); ++k) {
    const std::array<int, 2>& sides = c.sides[static_cast<std::size_t>(k)];
    std::set<int> a, b, shared;
    for (int j = 0; j < 4; ++j) a.insert(volume->simplices(sides[0], j)), b.insert(volume->simplices(sides[1], j));
    for (int v : a)
      if (b.count(v)) shared.insert(v);
    ASSERT_EQ(shared.size(), 3u) << "crossing " << k << ": the two sides share a face";
    for (int side : sides) {
      const Eigen::VectorXd l = locator.barycentric(side, c.points.row(k).transpose());
      EXPECT_GE(l.minCoeff(), -1e-12) << "crossing " << k;
      EXPECT_LE(l.minCoeff(), 1e-12) << "crossing " << k << " is on a face";
    }
  }
  std::set<std::array<int, 2>> between;  // edges whose ends lie in different simplices
  for (const std::vector<int>& f : mesh.faces)
    for (std::size_t j = 0; j < f.size(); ++j) {
      const int u = f[j], v = f[(j + 1) % f.size()];
      if (c.holders[static_cast<std::size_t>(u)] != c.holders[static_cast<std::size_t>(v)])
        between.insert({std::min(u, v), std::max(u, v)});
    }
  ASSERT_GT(between.size(), 50u);
  const std::set<std::array<int, 2>> found(c.edges.begin(), c.edges.end());
  EXPECT_EQ(found, between);

  DeformParams params;
  params.nu = 0.3;
  for (Method method : allMethods()) {
    const auto deformer = makeDeformer(method, cage, points);
    const auto seams = prepareSeamJumps(*deformer, cage, points, mesh.faces, {}, "faces");
    ASSERT_EQ(seams->crossings().edges.size(), between.size()) << methodName(method);
    const SeamJumps jumps = seams->evaluate(posedCage.vertices, params);
    const double largest = quantile(jumps.edges, 1.0);
    if (method->needsVolumeMesh)
      EXPECT_GT(largest, 1e-2) << methodName(method) << " is C0 across the tetrahedra";
    else
      EXPECT_LE(largest, 1e-12) << methodName(method) << "'s J is one function";
  }
}

}  // namespace
}  // namespace somicage
