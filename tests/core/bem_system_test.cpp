// The boundary element system: for affine displacements the exact tractions sigma n (Hooke's law, mu = 1), zero for
// rigid translations and infinitesimal rotations, balance for any displacement, the nu = 1/2 refusal, the
// factorizations cached per nu; 2D and 3D.
#include "coordinates/bem_system.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "base/errors.h"
#include "test_shapes.h"

namespace somicage {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Cage cageOf(int dim) { return dim == 3 ? test::makeBumpySphere(1) : test::makeStarPolygon(6); }

Eigen::MatrixXd randomMatrix(int rows, int cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Eigen::MatrixXd M(rows, cols);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) M(r, c) = uniform(rng);
  return M;
}

// Hooke's law with mu = 1, lambda = 2 nu / (1 - 2 nu) (-1 in the limit nu = +-inf), for the gradient A.
Eigen::MatrixXd stress(const Eigen::MatrixXd& A, double nu) {
  const Eigen::MatrixXd strain = 0.5 * (A + A.transpose());
  const double lambda = std::isinf(nu) ? -1.0 : 2 * nu / (1 - 2 * nu);
  return lambda * strain.trace() * Eigen::MatrixXd::Identity(A.rows(), A.cols()) + 2 * strain;
}

class BemSystemTest : public ::testing::TestWithParam<int> {};

TEST_P(BemSystemTest, AffineDisplacementsGiveTheExactTractions) {
  // u = A x + c is an exact elastic state with traction sigma n_j on each face, which piecewise-constant tractions
  // represent exactly: the collocation solution must be it, to round-off (1e-9 relative to |sigma|).
  const int d = GetParam();
  const Cage cage = cageOf(d);
  const BemSystem system(cage);
  const Eigen::MatrixXd A = randomMatrix(d, d, 5), c = randomMatrix(1, d, 6);
  const Eigen::MatrixXd u = (cage.vertices * A.transpose()).rowwise() + c.row(0);
  const Eigen::MatrixXd normals = faceNormals(cage, cage.vertices);
  for (double nu : {-0.5, 0.0, 0.3, 0.45, kInf}) {
    const BemSolution s = system.solve(*system.factor(nu), u);
    const Eigen::MatrixXd sigma = stress(A, nu);
    const Eigen::MatrixXd exact = normals * sigma.transpose();
    EXPECT_LT((s.tractions - exact).cwiseAbs().maxCoeff(), 1e-9 * sigma.norm()) << "nu " << nu;
    EXPECT_LT(s.omega.norm(), 1e-9 * A.norm()) << "nu " << nu;
  }
}

TEST_P(BemSystemTest, RigidMotionsGiveZeroTraction) {
  const int d = GetParam();
  const Cage cage = cageOf(d);
  const BemSystem system(cage);
  const Eigen::MatrixXd translation = Eigen::MatrixXd::Ones(cage.numVertices(), 1) * randomMatrix(1, d, 7);
  Eigen::MatrixXd W = randomMatrix(d, d, 8);
  W = (W - W.transpose()).eval();  // an infinitesimal rotation: no strain
  for (double nu : {0.0, 0.3}) {
    const auto f = system.factor(nu);
    EXPECT_LT(system.solve(*f, translation).tractions.cwiseAbs().maxCoeff(), 1e-12) << "nu " << nu;
    EXPECT_LT(system.solve(*f, cage.vertices * W.transpose()).tractions.cwiseAbs().maxCoeff(), 1e-10) << "nu " << nu;
  }
}

TEST_P(BemSystemTest, TractionsBalanceForAnyDisplacement) {
  // sum_j A_j t_j = 0 (no body force): relative to sum_j A_j |t_j|, to 1e-12, for random vertex displacements.
  const int d = GetParam();
  const Cage cage = cageOf(d);
  const BemSystem system(cage);
  const Eigen::VectorXd areas = faceAreas(cage, cage.vertices);
  for (unsigned seed : {1u, 2u, 3u}) {
    const BemSolution s = system.solve(*system.factor(0.3), 0.2 * randomMatrix(cage.numVertices(), d, seed));
    const Eigen::VectorXd net = s.tractions.transpose() * areas;
    EXPECT_LT(net.norm(), 1e-12 * areas.dot(s.tractions.rowwise().norm())) << "seed " << seed;
  }
}

TEST_P(BemSystemTest, RefusesTheIncompressibleLimitAndBadRatios) {
  const BemSystem system(cageOf(GetParam()));
  for (double nu : {0.5, 0.7, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    try {
      system.factor(nu);
      ADD_FAILURE() << "nu " << nu << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "nu");
      if (nu == 0.5) {
        EXPECT_NE(std::string(e.what()).find("incompressible"), std::string::npos) << e.what();
      }
    }
  }
}

TEST_P(BemSystemTest, FactorizationsAreCachedPerNuLeastRecentlyUsedFirst) {
  // Two views at nu = 0.1 and 0.45 drawn in turn (issue 24: the deformer kept one nu and re-factored every frame):
  // two factorizations for twenty frames, each the one factor() makes at its nu (the same solution, bitwise).
  const BemSystem system(cageOf(GetParam()));
  const Eigen::MatrixXd u = randomMatrix(system.restCage().numVertices(), GetParam(), 7);
  for (int frame = 0; frame < 20; ++frame) {
    const double nu = frame % 2 ? 0.45 : 0.1;
    const BemSolution cached = system.solve(*system.factorization(nu), u);
    if (frame < 2) {
      const BemSolution fresh = system.solve(*system.factor(nu), u);
      EXPECT_EQ(cached.tractions, fresh.tractions);
      EXPECT_EQ(cached.omega, fresh.omega);
    }
  }
  EXPECT_EQ(system.factorizationsMade(), 2u);
  // inf is a value like any other; a refused nu makes nothing.
  system.factorization(kInf);
  system.factorization(kInf);
  EXPECT_THROW(system.factorization(0.5), InputError);
  EXPECT_EQ(system.factorizationsMade(), 3u);
  // One more value than the cache holds, cycled: the least recently used is always the one asked for next, so every
  // request misses; asking again for the most recent one hits.
  const std::size_t n = BemSystem::kCachedFactorizations + 1, before = system.factorizationsMade();
  for (int round = 0; round < 2; ++round)
    for (std::size_t k = 0; k < n; ++k) system.factorization(-0.5 + 0.1 * static_cast<double>(k));
  EXPECT_EQ(system.factorizationsMade() - before, 2 * n);
  system.factorization(-0.5 + 0.1 * static_cast<double>(n - 1));
  EXPECT_EQ(system.factorizationsMade() - before, 2 * n);
}

INSTANTIATE_TEST_SUITE_P(Dimensions, BemSystemTest, ::testing::Values(2, 3),
                         [](const auto& info) { return std::to_string(info.param) + "D"; });

}  // namespace
}  // namespace somicage
