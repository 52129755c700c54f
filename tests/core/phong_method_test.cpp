// The Phong deformer (core/methods/phong_method.cpp) against closed forms and against an implementation of
// James 2020's formulas written here (no call into core's Phong, elasticity or locator code), on a held-out mesh.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <fstream>
#include <random>
#include <vector>

#include "base/errors.h"
#include "coordinates/elastic_steiner_solve.h"
#include "coordinates/phong_interpolation.h"
#include "core/scratch_folder.h"
#include "core/test_shapes.h"
#include "deform/deformer.h"
#include "deform/jacobian.h"
#include "deform/memory_estimate.h"
#include "engine/engine.h"
#include "geometry/medit_io.h"
#include "methods/method_descriptors.h"
#include "tetrahedralization/cage_tetrahedralization.h"

namespace somicage {
namespace {

// The cube [-1, 1]^3 coned from an off-centre point c (vertex 8), then the tetrahedron on the cube's first face
// split 1-to-4 at an inner point p (vertex 9): 15 tetrahedra, two interior Steiner vertices, no symmetry.
VolumeMesh heldOutCubeMesh() {
  const Cage cube = test::makeCube();
  VolumeMesh mesh;
  mesh.vertices.resize(10, 3);
  mesh.vertices.topRows(8) = cube.vertices;
  mesh.vertices.row(8) << 0.1, -0.05, 0.07;
  std::vector<Eigen::Vector4i> tets;
  for (int j = 0; j < cube.numFaces(); ++j) tets.emplace_back(8, cube.faces(j, 0), cube.faces(j, 1), cube.faces(j, 2));
  const Eigen::Vector4i split = tets.front();
  mesh.vertices.row(9) = 0.4 * mesh.vertices.row(split(0)) + 0.3 * mesh.vertices.row(split(1)) +
                         0.2 * mesh.vertices.row(split(2)) + 0.1 * mesh.vertices.row(split(3));
  tets.erase(tets.begin());
  for (int k = 0; k < 4; ++k) {
    Eigen::Vector4i t = split;
    t(k) = 9;
    tets.push_back(t);
  }
  mesh.simplices.resize(static_cast<int>(tets.size()), 4);
  for (std::size_t s = 0; s < tets.size(); ++s) mesh.simplices.row(static_cast<int>(s)) = tets[s].transpose();
  return mesh;
}

// ---- The reference: James 2020 written out, dense and brute force. ----

Eigen::Matrix3d refEdges(const VolumeMesh& mesh, const Eigen::MatrixXd& x, int s) {
  Eigen::Matrix3d D;
  for (int k = 0; k < 3; ++k) D.col(k) = (x.row(mesh.simplices(s, k + 1)) - x.row(mesh.simplices(s, 0))).transpose();
  return D;
}

Eigen::Matrix3d refF(const VolumeMesh& mesh, const Eigen::MatrixXd& x, int s) {
  return refEdges(mesh, x, s) * refEdges(mesh, mesh.vertices, s).inverse();
}

// sum_t V_t (mu |eps|^2 + lambda/2 tr(eps)^2), eps = sym(F) - I, mu = 1, lambda = 2 nu / (1 - 2 nu).
double refEnergy(const VolumeMesh& mesh, const Eigen::MatrixXd& x, double nu) {
  const double lambda = 2 * nu / (1 - 2 * nu);
  double energy = 0;
  for (int s = 0; s < mesh.numSimplices(); ++s) {
    const Eigen::Matrix3d F = refF(mesh, x, s);
    const Eigen::Matrix3d eps = 0.5 * (F + F.transpose()) - Eigen::Matrix3d::Identity();
    energy += std::abs(refEdges(mesh, mesh.vertices, s).determinant()) / 6 *
              (eps.squaredNorm() + lambda / 2 * eps.trace() * eps.trace());
  }
  return energy;
}

// The free vertices' positions minimising refEnergy, the others as in x: E is quadratic in the displacement u
// with E(0) = 0 and no linear term, so its Hessian is read off by polarisation, K_ij = E(e_i + e_j) - E(e_i) - E(e_j),
// and the minimiser solves K_ff u_f = -K_fk u_k densely.
Eigen::MatrixXd refSteiner(const VolumeMesh& mesh, Eigen::MatrixXd x, const std::vector<int>& freeVertices, double nu) {
  const int n = mesh.numVertices(), dofs = 3 * n;
  const auto energyOf = [&](const Eigen::VectorXd& u) {
    Eigen::MatrixXd y = mesh.vertices;
    for (int i = 0; i < dofs; ++i) y(i / 3, i % 3) += u(i);
    return refEnergy(mesh, y, nu);
  };
  std::vector<int> free;
  std::vector<bool> isFree(static_cast<std::size_t>(dofs), false);
  for (int v : freeVertices)
    for (int a = 0; a < 3; ++a) free.push_back(3 * v + a), isFree[static_cast<std::size_t>(3 * v + a)] = true;
  Eigen::MatrixXd K(free.size(), dofs);
  for (std::size_t r = 0; r < free.size(); ++r) {
    const Eigen::VectorXd ei = Eigen::VectorXd::Unit(dofs, free[r]);
    for (int c = 0; c < dofs; ++c) {
      const Eigen::VectorXd ej = Eigen::VectorXd::Unit(dofs, c);
      K(static_cast<Eigen::Index>(r), c) = energyOf(ei + ej) - energyOf(ei) - energyOf(ej);
    }
  }
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(free.size()));
  Eigen::MatrixXd Kff(free.size(), free.size());
  for (std::size_t r = 0; r < free.size(); ++r) {
    for (int c = 0; c < dofs; ++c)
      if (!isFree[static_cast<std::size_t>(c)])
        rhs(static_cast<Eigen::Index>(r)) -=
            K(static_cast<Eigen::Index>(r), c) * (x(c / 3, c % 3) - mesh.vertices(c / 3, c % 3));
    for (std::size_t k = 0; k < free.size(); ++k)
      Kff(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(k)) = K(static_cast<Eigen::Index>(r), free[k]);
  }
  const Eigen::VectorXd u = Kff.fullPivLu().solve(rhs);
  for (std::size_t r = 0; r < free.size(); ++r)
    x(free[r] / 3, free[r] % 3) = mesh.vertices(free[r] / 3, free[r] % 3) + u(static_cast<Eigen::Index>(r));
  return x;
}

// F_v with the authors' weights: r_t = c_t - X_v, (I + sum r^ r^T) a = -sum r^, w = (1 + a.r^) / |r|.
Eigen::Matrix3d refVertexF(const VolumeMesh& mesh, const Eigen::MatrixXd& x, int v) {
  std::vector<int> star;
  for (int s = 0; s < mesh.numSimplices(); ++s)
    for (int k = 0; k < 4; ++k)
      if (mesh.simplices(s, k) == v) star.push_back(s);
  Eigen::Matrix3d M = Eigen::Matrix3d::Identity();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> r;
  for (int s : star) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) c += mesh.vertices.row(mesh.simplices(s, k)).transpose() / 4;
    r.push_back(c - mesh.vertices.row(v).transpose());
    const Eigen::Vector3d h = r.back().normalized();
    M += h * h.transpose();
    b -= h;
  }
  const Eigen::Vector3d a = M.inverse() * b;
  Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
  double sum = 0;
  for (std::size_t t = 0; t < star.size(); ++t) {
    const double w = (1 + a.dot(r[t].normalized())) / r[t].norm();
    F += w * refF(mesh, x, star[t]);
    sum += w;
  }
  return F / sum;
}

// phi(X) = 1/2 sum l_i x_i + 1/2 sum l_i (x_i + F_i (X - X_i)) in the tetrahedron holding X (a scan).
Eigen::Vector3d refPhong(const VolumeMesh& mesh, const Eigen::MatrixXd& x, const Eigen::Vector3d& X) {
  for (int s = 0; s < mesh.numSimplices(); ++s) {
    const Eigen::Vector3d l123 =
        refEdges(mesh, mesh.vertices, s).inverse() * (X - mesh.vertices.row(mesh.simplices(s, 0)).transpose());
    const Eigen::Vector4d l(1 - l123.sum(), l123(0), l123(1), l123(2));
    if (l.minCoeff() < -1e-12) continue;
    Eigen::Vector3d out = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) {
      const int v = mesh.simplices(s, k);
      const Eigen::Vector3d xi = x.row(v).transpose(), Xi = mesh.vertices.row(v).transpose();
      out += 0.5 * l(k) * xi + 0.5 * l(k) * (xi + refVertexF(mesh, x, v) * (X - Xi));
    }
    return out;
  }
  ADD_FAILURE() << "no tetrahedron holds the point";
  return Eigen::Vector3d::Constant(NAN);
}

// A smooth, clearly non-affine pose of the cube's vertices.
Eigen::MatrixXd bentCube(const Eigen::MatrixXd& V) {
  Eigen::MatrixXd P = V;
  for (int i = 0; i < V.rows(); ++i) {
    const double angle = 0.4 * V(i, 2);
    P(i, 0) = std::cos(angle) * V(i, 0) - std::sin(angle) * V(i, 1) + 0.1 * V(i, 2) * V(i, 2);
    P(i, 1) = std::sin(angle) * V(i, 0) + std::cos(angle) * V(i, 1);
    P(i, 2) = 1.2 * V(i, 2) + 0.05 * V(i, 0) * V(i, 1);
  }
  return P;
}

PrecomputeOptions withMesh(const VolumeMesh& mesh) {
  PrecomputeOptions options;
  options.volumeMesh = std::make_shared<VolumeMesh>(mesh);
  return options;
}

DeformParams atNu(double nu) {
  DeformParams params;
  params.nu = nu;
  return params;
}

TEST(PhongMethod, MatchesTheFormulasWrittenOutOnAHeldOutMesh) {
  const Cage cube = test::makeCube();
  const VolumeMesh mesh = heldOutCubeMesh();
  const Eigen::MatrixXd points = test::randomBoxPoints(40, 3, -0.95, 0.95, 5);
  const Eigen::MatrixXd posed = bentCube(cube.vertices);
  for (double nu : {0.0, 0.3, -0.5}) {
    SCOPED_TRACE("nu " + std::to_string(nu));
    const auto deformer = makeDeformer(methods::phong(), cube, points, withMesh(mesh));
    const Eigen::MatrixXd out = deformer->deform(posed, atNu(nu));
    Eigen::MatrixXd x = mesh.vertices;
    x.topRows(8) = posed;
    x = refSteiner(mesh, x, {8, 9}, nu);
    double worst = 0;
    for (int p = 0; p < points.rows(); ++p)
      worst = std::max(worst, (out.row(p).transpose() - refPhong(mesh, x, points.row(p).transpose())).norm());
    EXPECT_LE(worst / cageDiameter(cube.vertices), 1e-9);
  }
}

// The held-out mesh's interior Steiner vertices (8, 9), and the mesh with its cage vertices bent.
std::vector<bool> heldOutInteriorVertices() {
  std::vector<bool> free(10, false);
  free[8] = free[9] = true;
  return free;
}
Eigen::MatrixXd bentHeldOutCubeMesh(const VolumeMesh& mesh) {
  Eigen::MatrixXd x = mesh.vertices;
  x.topRows(8) = bentCube(mesh.vertices.topRows(8));
  return x;
}

TEST(PhongMethod, SteinerSolveMatchesADenseSolve) {
  const VolumeMesh mesh = heldOutCubeMesh();
  ElasticSteinerSolver solver(mesh, heldOutInteriorVertices());
  Eigen::MatrixXd x = bentHeldOutCubeMesh(mesh);
  for (double nu : {0.0, 0.45, -0.9}) {
    solver.factor(nu);
    Eigen::MatrixXd solved = x;
    solver.solve(solved);
    EXPECT_LE((solved - refSteiner(mesh, x, {8, 9}, nu)).cwiseAbs().maxCoeff(), 1e-12) << "nu " << nu;
  }
}

// The editor asks for the same frame's Steiner vertices twice (the points' weights, the tetrahedra's wireframe):
// the second is answered from the first, which is the same solve; a new pose or nu is solved again.
TEST(PhongMethod, SteinerSolveIsNotRepeatedForTheSamePose) {
  const VolumeMesh mesh = heldOutCubeMesh();
  ElasticSteinerSolver solver(mesh, heldOutInteriorVertices());
  Eigen::MatrixXd x = bentHeldOutCubeMesh(mesh);
  solver.factor(0.2);
  Eigen::MatrixXd first = x, second = x;
  solver.solve(first);
  solver.solve(second);
  EXPECT_EQ(solver.solveCount(), 1);
  EXPECT_EQ(first, second);
  EXPECT_LE((first - refSteiner(mesh, x, {8, 9}, 0.2)).cwiseAbs().maxCoeff(), 1e-12);
  x(0, 0) += 0.1;
  Eigen::MatrixXd moved = x;
  solver.solve(moved);
  EXPECT_EQ(solver.solveCount(), 2);
  EXPECT_LE((moved - refSteiner(mesh, x, {8, 9}, 0.2)).cwiseAbs().maxCoeff(), 1e-12);
  solver.factor(0.4);
  solver.solve(moved);
  EXPECT_EQ(solver.solveCount(), 3);
  EXPECT_LE((moved - refSteiner(mesh, x, {8, 9}, 0.4)).cwiseAbs().maxCoeff(), 1e-12);
}

// The cube coned from its centre is symmetric under X -> -X; under an odd pose (x(-X) = -x(X)) the energy is
// even in the centre's displacement, so its unique minimiser keeps the centre at the origin. Under an affine pose
// x = A X + t every tetrahedron can have F = A, which is stationary, so the centre goes to t.
TEST(PhongMethod, SteinerSolveMatchesClosedFormsOnASymmetricStar) {
  const Cage cube = test::makeCube();
  const std::unique_ptr<VolumeMesh> star = starVolumeMesh(cube);
  ASSERT_TRUE(star);
  ASSERT_LE(star->vertices.row(8).norm(), 1e-15);
  std::vector<bool> free(9, false);
  free[8] = true;
  ElasticSteinerSolver solver(*star, free);
  solver.factor(0.3);
  Eigen::MatrixXd x = star->vertices;
  for (int i = 0; i < 8; ++i) {  // odd (cubic terms only): a twist about z plus a bulge
    const Eigen::Vector3d X = cube.vertices.row(i);
    x.row(i) << X(0) - 0.3 * X(2) * X(2) * X(1) + 0.2 * X(0) * X(0) * X(0), X(1) + 0.3 * X(2) * X(2) * X(0), 1.5 * X(2);
  }
  x.row(8).setConstant(7);
  solver.solve(x);
  EXPECT_LE(x.row(8).norm(), 1e-14);
  Eigen::Matrix3d A;
  A << 1.2, 0.3, -0.1, 0.05, 0.8, 0.2, 0.1, -0.2, 1.1;
  const Eigen::RowVector3d t(0.3, -2, 1);
  x = (star->vertices * A.transpose()).rowwise() + t;
  x.row(8).setConstant(7);
  solver.solve(x);
  EXPECT_LE((x.row(8) - t).norm(), 1e-14);
}

TEST(PhongMethod, RefusesPoissonRatiosWhereTheEnergyIsNotPositiveDefinite) {
  EXPECT_TRUE(elasticEnergyPositiveDefinite(0.49, 3));
  EXPECT_TRUE(elasticEnergyPositiveDefinite(-0.99, 3));
  EXPECT_FALSE(elasticEnergyPositiveDefinite(-1.0, 3));  // 2 mu + 3 lambda = 0
  EXPECT_FALSE(elasticEnergyPositiveDefinite(0.5, 3));
  EXPECT_FALSE(elasticEnergyPositiveDefinite(INFINITY, 3));  // lambda -> -1
  EXPECT_TRUE(elasticEnergyPositiveDefinite(-5, 2));         // 2D: mu + lambda > 0 for every nu < 1/2
  const Cage cube = test::makeCube();
  const auto deformer = makeDeformer(methods::phong(), cube, test::randomBoxPoints(3, 3, -0.5, 0.5, 1));
  try {
    deformer->deform(cube.vertices, atNu(-INFINITY));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "nu");
    EXPECT_NE(e.problem().find("indefinite"), std::string::npos) << e.problem();
  }
}

// The weights of F_v on stars whose closed form is known: one tetrahedron (w = 1), two with orthogonal
// directions r^ (a = -(r^1 + r^2)/2, so w_t = 1 / (2 |r_t|): normalised, proportional to 1 / |r_t|), and the
// cube's centre, whose twelve directions sum to zero at equal distances (equal weights 1/12).
TEST(PhongInterpolation, VertexWeightsMatchTheirClosedFormOnHandBuiltStars) {
  VolumeMesh one;
  one.vertices.resize(4, 3);
  one.vertices << 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3;
  one.simplices.resize(1, 4);
  one.simplices << 0, 1, 2, 3;
  const PhongVertexWeights w1 = phongVertexWeights(one);
  ASSERT_EQ(w1.start[1] - w1.start[0], 1);
  EXPECT_NEAR(w1.weight[0], 1.0, 1e-15);

  // Two tetrahedra at vertex 0 whose centroids lie along +x (at 1) and +y (at 3).
  VolumeMesh two;
  two.vertices.resize(7, 3);
  two.vertices << 0, 0, 0,                  //
      2, 0.5, 0.5, 1, -0.5, -0.5, 1, 0, 0,  // centroid (1, 0, 0): (0 + 2 + 1 + 1) / 4 = 1, y, z sum to 0
      0.5, 6, 0.5, -0.5, 3, -0.5, 0, 3, 0;  // centroid (0, 3, 0)
  two.simplices.resize(2, 4);
  two.simplices << 0, 1, 2, 3, 0, 4, 5, 6;
  const PhongVertexWeights w2 = phongVertexWeights(two);
  ASSERT_EQ(w2.start[1], 2);
  EXPECT_NEAR(w2.weight[0], (1.0 / 1) / (1.0 / 1 + 1.0 / 3), 1e-14);
  EXPECT_NEAR(w2.weight[1], (1.0 / 3) / (1.0 / 1 + 1.0 / 3), 1e-14);

  const std::unique_ptr<VolumeMesh> star = starVolumeMesh(test::makeCube());
  const PhongVertexWeights w3 = phongVertexWeights(*star);
  ASSERT_EQ(w3.start[9] - w3.start[8], 12);
  for (int k = w3.start[8]; k < w3.start[9]; ++k) EXPECT_NEAR(w3.weight[static_cast<std::size_t>(k)], 1.0 / 12, 1e-14);
}

// Every affine map is reproduced (each F_t = A, so every F_v = A and phi = A X + t), on the held-out mesh read from
// a MEDIT file and on CGAL's tetrahedra of the extruded L (Steiner vertices on its faces and inside).
TEST(PhongMethod, ReproducesAffinePosesWithGivenAndGeneratedMeshes) {
  const test::ScratchFolder scratch;
  const std::string file = scratch / "cube.mesh";
  {
    std::ofstream out(file);
    out << formatMedit(heldOutCubeMesh());
  }
  Eigen::Matrix3d A;
  A << 1.3, 0.4, -0.2, -0.1, 0.7, 0.3, 0.2, 0.1, 0.9;
  const Eigen::RowVector3d t(1, -2, 0.5);
  struct Case {
    Cage cage;
    PrecomputeOptions options;
    Eigen::MatrixXd points;
    std::string name;
  };
  std::vector<Case> cases;
  // Points inside: outside the cage the exterior rule follows the best-fit similarity, not the affine map.
  cases.push_back({test::makeCube(), {}, test::randomBoxPoints(60, 3, -0.99, 0.99, 2), "cube, MEDIT file"});
  cases.back().options.methodOptions["tets"] = file;
  for (int level : {0, 1}) {
    cases.push_back({test::makeExtrudedL(),
                     {},
                     test::randomLPoints(60, 3, 0.001, 3),
                     "extruded L, CGAL level " + std::to_string(level)});
    cases.back().options.volumeMesh = std::make_shared<VolumeMesh>(tetrahedralizeCage(cases.back().cage, level));
  }
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const auto deformer = makeDeformer(methods::phong(), c.cage, c.points, c.options);
    const Eigen::MatrixXd posed = (c.cage.vertices * A.transpose()).rowwise() + t;
    const Eigen::MatrixXd expected = (c.points * A.transpose()).rowwise() + t;
    const double diameter = cageDiameter(c.cage.vertices);
    EXPECT_LE((deformer->deform(posed, atNu(0.25)) - expected).rowwise().norm().maxCoeff() / diameter, 1e-9);
    EXPECT_LE((deformer->deform(c.cage.vertices, atNu(0.25)) - c.points).rowwise().norm().maxCoeff() / diameter, 1e-12)
        << "the rest pose is the identity";
    // The cage's own vertices are interpolated.
    const auto atVertices = makeDeformer(methods::phong(), c.cage, c.cage.vertices, c.options);
    const Eigen::MatrixXd bent = test::bendPose(c.cage.vertices, 0.3, 4);
    EXPECT_LE((atVertices->deform(bent, atNu(0.25)) - bent).rowwise().norm().maxCoeff() / diameter, 1e-12);
  }
}

// What the editor draws as the tetrahedra's wireframe: the deformer's own mesh, posed as a frame poses it (the cage's
// vertices, then the Steiner vertices where the dense reference solve puts them); methods without a mesh have none.
TEST(PhongMethod, PosedVolumeMeshIsTheCageThenTheSteinerVerticesOfTheFrame) {
  const VolumeMesh mesh = heldOutCubeMesh();
  const Cage cube = test::makeCube();
  const auto deformer = makeDeformer(methods::phong(), cube, test::randomBoxPoints(20, 3, -0.9, 0.9, 5), withMesh(mesh));
  ASSERT_TRUE(deformer->volumeMesh());
  EXPECT_EQ(deformer->volumeMesh()->vertices, mesh.vertices);
  EXPECT_EQ(deformer->volumeMesh()->simplices, mesh.simplices);
  Eigen::MatrixXd x = mesh.vertices;
  x.topRows(8) = bentCube(cube.vertices);
  for (double nu : {0.0, 0.45}) {
    const Eigen::MatrixXd posed = deformer->posedVolumeMesh(x.topRows(8), atNu(nu));
    EXPECT_LE((posed - refSteiner(mesh, x, {8, 9}, nu)).cwiseAbs().maxCoeff(), 1e-12) << "nu " << nu;
  }
  EXPECT_THROW(deformer->posedVolumeMesh(x.topRows(8), atNu(INFINITY)), InputError);
  const auto green = makeDeformer(methods::green(), cube, test::randomBoxPoints(5, 3, -0.9, 0.9, 5));
  EXPECT_FALSE(green->volumeMesh());
  EXPECT_EQ(green->posedVolumeMesh(cube.vertices, {}).rows(), 0);
}

// Across an interior face the positions agree (both sides interpolate the same x_i and F_i) while J jumps.
TEST(PhongMethod, IsContinuousAcrossInteriorFacesWhileItsJacobianJumps) {
  const Cage cube = test::makeCube();
  const VolumeMesh mesh = heldOutCubeMesh();
  // Six faces shared by two tetrahedra, a random point on each, and the two points 1e-13 to either side of it.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(0.1, 0.8);
  Eigen::MatrixXd points(0, 3);
  int faces = 0;
  for (int s = 0; s < mesh.numSimplices() && faces < 6; ++s)
    for (int r = s + 1; r < mesh.numSimplices() && faces < 6; ++r) {
      std::vector<int> shared;
      for (int k = 0; k < 4; ++k)
        for (int m = 0; m < 4; ++m)
          if (mesh.simplices(s, k) == mesh.simplices(r, m)) shared.push_back(mesh.simplices(s, k));
      if (shared.size() != 3) continue;
      const Eigen::Vector3d a = mesh.vertices.row(shared[0]), b = mesh.vertices.row(shared[1]),
                            c = mesh.vertices.row(shared[2]);
      const double u = uniform(rng), v = (1 - u) * uniform(rng);
      const Eigen::Vector3d onFace = a + u * (b - a) + v * (c - a), n = (b - a).cross(c - a).normalized();
      points.conservativeResize(points.rows() + 2, 3);
      points.row(points.rows() - 2) = (onFace + 1e-13 * n).transpose();
      points.row(points.rows() - 1) = (onFace - 1e-13 * n).transpose();
      ++faces;
    }
  ASSERT_EQ(faces, 6);
  const auto deformer = makeDeformer(methods::phong(), cube, points, withMesh(mesh));
  const DeformationGradients gradients(*deformer, points);
  Eigen::MatrixXd positions, J;
  gradients.evaluate(bentCube(cube.vertices), atNu(0.3), positions, J);
  double jump = 0;
  for (int f = 0; f < faces; ++f) {
    EXPECT_LE((positions.row(2 * f) - positions.row(2 * f + 1)).norm(), 1e-12) << "face " << f;
    jump = std::max(jump, (J.row(2 * f) - J.row(2 * f + 1)).norm());
  }
  EXPECT_GE(jump, 1e-3) << "the gradient jumps across some face";
}

// J of the method equals finite differences of its positions inside a tetrahedron (phi is quadratic there).
TEST(PhongMethod, JacobianIsTheDerivativeOfThePositions) {
  const Cage cube = test::makeCube();
  const VolumeMesh mesh = heldOutCubeMesh();
  const Eigen::MatrixXd centres = test::randomBoxPoints(5, 3, -0.8, 0.8, 9);
  const double h = 1e-5;
  Eigen::MatrixXd points(centres.rows() * 7, 3);
  for (int p = 0; p < centres.rows(); ++p)
    for (int k = 0; k < 7; ++k) {
      points.row(7 * p + k) = centres.row(p);
      if (k > 0) points(7 * p + k, (k - 1) / 2) += k % 2 ? h : -h;
    }
  const auto deformer = makeDeformer(methods::phong(), cube, points, withMesh(mesh));
  const DeformationGradients gradients(*deformer, points);
  Eigen::MatrixXd x, J;
  gradients.evaluate(bentCube(cube.vertices), atNu(0.2), x, J);
  for (int p = 0; p < centres.rows(); ++p)
    for (int b = 0; b < 3; ++b) {
      const Eigen::RowVector3d fd = (x.row(7 * p + 1 + 2 * b) - x.row(7 * p + 2 + 2 * b)) / (2 * h);
      for (int a = 0; a < 3; ++a) EXPECT_NEAR(J(7 * p, 3 * a + b), fd(a), 1e-6) << "point " << p;
    }
}

// C is stored as sparse rows (coordinate_layout.h): per point its simplex's d + 1 vertices times d + 1 terms, and an
// outside point's [x | 1]. Expanded into the dense matrix it stands for, the dense frame kernel gives the same points
// and the same J to 1e-12 diameters (double storage; float storage within its own rounding, 1e-6), inside and
// outside the cage, in 3D (TetGen's mesh of the extruded L, Steiner vertices) and 2D (the L polygon's fan); and it
// takes (d + 1)^2 (value, 32-bit column) pairs per row, which the memory estimate says.
TEST(PhongMethod, SparseCoordinatesEvaluateAsTheDenseMatrixTheyStandFor) {
  struct Case {
    Cage cage;
    PrecomputeOptions options;
    std::string name;
  };
  std::vector<Case> cases;
  cases.push_back({test::makeExtrudedL(), {}, "3D extruded L, TetGen"});
  cases.back().options.volumeMesh = std::make_shared<VolumeMesh>(tetrahedralizeCage(cases.back().cage, 0));
  cases.push_back({makePolygonCage(test::lLoop()), {}, "2D L polygon"});
  for (Case& c : cases)
    for (bool floatStorage : {false, true}) {
      SCOPED_TRACE(c.name + (floatStorage ? " float" : " double"));
      const int d = c.cage.dim();
      const Eigen::MatrixXd points = test::randomBoxPoints(80, d, -0.3, 2.3, 4);  // some outside the L
      c.options.floatStorage = floatStorage;
      const auto deformer = makeDeformer(methods::phong(), c.cage, points, c.options);
      const FrameCoordinates& C = deformer->frameCoordinates();
      const int n = deformer->volumeMesh()->numVertices(), entries = (d + 1) * (d + 1);
      ASSERT_TRUE(C.isSparse());
      ASSERT_GT(C.exteriorBlends.size(), 0u) << "the case has points outside";
      EXPECT_EQ(C.storedColumns(), entries);
      EXPECT_EQ(C.columns(), (d + 1) * n + d + 1);
      const std::size_t valueBytes = floatStorage ? 4 : 8;
      EXPECT_EQ(C.bytes(), static_cast<std::size_t>(C.rows() * entries) * (valueBytes + 4));
      EXPECT_EQ(estimateCoordinateBytes(methods::phong(), d, n, c.cage.numFaces(), 80, floatStorage),
                static_cast<std::size_t>(80 * entries) * (valueBytes + 4));

      const FrameCoordinates dense = denseFrameCoordinates(C);
      ASSERT_FALSE(dense.isSparse());
      ASSERT_EQ(dense.columns(), C.columns());
      const Eigen::MatrixXd posed = test::bendPose(c.cage.vertices, 0.3, 4);
      const FrameWeights W = deformer->frameWeights(posed, atNu(0.3));
      Eigen::MatrixXd fromDense;
      evaluateFrame(dense, W, d, 1, fromDense);
      const double diameter = cageDiameter(c.cage.vertices), tolerance = floatStorage ? 1e-6 : 1e-12;
      EXPECT_LE((deformer->deform(posed, atNu(0.3)) - fromDense).cwiseAbs().maxCoeff() / diameter, tolerance);

      // J: the gradient rows are sparse too, with C's columns.
      const std::vector<FrameCoordinates> sparseGradients = deformer->coordinateGradients(points, noProgress);
      ASSERT_EQ(sparseGradients.size(), static_cast<std::size_t>(d));
      for (const FrameCoordinates& g : sparseGradients) {
        ASSERT_TRUE(g.isSparse());
        CoordinateMatrix<double> ySparse, yDense;
        evaluateFrameOutputs(g, W, 1, ySparse);
        evaluateFrameOutputs(denseFrameCoordinates(g), W, 1, yDense);
        EXPECT_LE((ySparse - yDense).cwiseAbs().maxCoeff(), tolerance);
        EXPECT_GT(ySparse.cwiseAbs().maxCoeff(), 0.1) << "the gradients are not all zero";
      }
    }
}

// A mesher that made another mesh than asked (cage_tetrahedralization.h: Mesh_3 fell back to TetGen) is a Warning
// notice of prepareVolumeMesh, which every front end shows (the CLI on stderr, Python as a SomiCageWarning, the
// editor in its status bar); a mesh as asked gives none.
TEST(PhongMethod, AMesherFallbackIsAWarningNotice) {
  for (bool fellBack : {false, true}) {
    PrecomputeOptions options;
    options.methodOptions["tet-level"] = "2";
    options.volumeMesher = [&](const Cage& cage, const MethodOptions&, const ProgressCallback&) {
      VolumeMesh mesh = tetrahedralizeCage(cage, 0);
      if (fellBack) mesh.fallback = "CGAL's Mesh_3 did not finish";
      return mesh;
    };
    std::vector<Notice> notices;
    prepareVolumeMesh(methods::phong(), test::makeCube(), options, [&](const Notice& n) { notices.push_back(n); });
    ASSERT_TRUE(options.volumeMesh);
    ASSERT_EQ(notices.size(), fellBack ? 1u : 0u);
    if (fellBack) {
      EXPECT_EQ(notices[0].kind, Notice::Kind::Warning);
      EXPECT_EQ(describeNotice(notices[0]), "warning: CGAL's Mesh_3 did not finish");
    }
  }
}

}  // namespace
}  // namespace somicage
