// Golden deformations of two shared models in the Somigliana paper's poses (FIREHYDRANT, Fig. 4; CACTUS), made by
// an independent high-order route: the reference evaluation of Eq. 11 (reference/somigliana_reference.h, adaptive
// Gauss-Legendre quadrature of Eqs. 3-4 at order 10 with pieces of diameter <= dist / 2, converged to ~5e-15 from
// order 8 in somigliana_reference_test.cpp; boundary conditions from docs/method.md) on a deterministic subset of the
// mesh vertices, computed here rather than stored, and compared with the core deformer. Skips visibly when the
// shared models are absent.
//
// Tolerance: 1e-10 cage diameters, as in somigliana_reference_test.cpp (measured here: <= 4e-15, printed). The
// subset is every k-th mesh vertex (60 of them); vertices closer than 1e-3 diameters to the cage are left out,
// since only they would make the quadrature slow.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "deform/deformer.h"
#include "io/mesh_formats.h"
#include "methods/method_descriptors.h"
#include "reference/somigliana_reference.h"
#include "test_models.h"

namespace somicage {
namespace {

#ifdef SOMICAGE_SANITIZE
constexpr int kGoldenPoints = 6;  // instrumented code is ~20x slower
#else
constexpr int kGoldenPoints = 60;
#endif

struct GoldenCase {
  test::ModelCase model;
  std::vector<reference::PoseParameters> parameters;
};

void PrintTo(const GoldenCase& c, std::ostream* out) { *out << c.model.folder; }

std::vector<GoldenCase> goldenCases() {
  const auto model = [](const std::string& folder) {
    for (const test::ModelCase& c : test::modelCases())
      if (c.folder == folder) return c;
    return test::ModelCase{};
  };
  // FIREHYDRANT with the settings of the paper's Fig. 4 (nu = 0.3, gamma = 0, global and local), then bulging and a
  // blend; CACTUS with Fig. 5's nu = 0 and bulging.
  return {{model("firehydrant"), {{0, 0.3, 0, true}, {1, 0.3, 0, true}, {0.5, 0.3, 1.5, true}, {1, 0.3, 1, false}}},
          {model("cactus"), {{0, 0, 1, true}, {1, 0, 0, true}, {0.5, 0, 2, false}, {1, 0, 1.5, true}}}};
}

class GoldenDeformation : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(GoldenDeformation, CoreMatchesTheHighOrderReference) {
  const GoldenCase& c = GetParam();
  if (test::skipIfModelAbsent(c.model)) return;
  Cage cage;
  Eigen::MatrixXd vertices;
  ASSERT_TRUE(test::loadModel(c.model, cage, vertices, 1));
  const Eigen::MatrixXd posed = loadCage(test::modelPath(c.model, c.model.pose)).vertices;
  ASSERT_EQ(posed.rows(), cage.numVertices());
  const double diameter = cageDiameter(cage.vertices);

  // Every k-th vertex at least 1e-3 diameters inside the cage.
  const int stride = static_cast<int>(vertices.rows() / kGoldenPoints);
  std::vector<Eigen::VectorXd> chosen;
  for (Eigen::Index v = 0; v < vertices.rows() && static_cast<int>(chosen.size()) < kGoldenPoints; v += stride) {
    const Eigen::VectorXd x = vertices.row(v).transpose();
    if (reference::windingNumber(cage, x) > 0.5 && reference::distanceToCage(cage, x) >= 1e-3 * diameter)
      chosen.push_back(x);
  }
  ASSERT_GE(chosen.size(), static_cast<size_t>(kGoldenPoints * 3 / 4)) << "too few mesh vertices inside the cage";
  Eigen::MatrixXd points(chosen.size(), 3);
  for (size_t p = 0; p < chosen.size(); ++p) points.row(p) = chosen[p].transpose();

  std::vector<double> nus;
  for (const auto& p : c.parameters)
    if (std::find(nus.begin(), nus.end(), p.nu) == nus.end()) nus.push_back(p.nu);
  std::vector<std::vector<reference::Coordinates>> coordinates;  // [point][nu]
  const reference::QuadratureOptions highOrder{10, 0.5, 40};
  for (const Eigen::VectorXd& x : chosen)
    coordinates.push_back(reference::integrateCoordinates(cage, x, nus, highOrder));

  PrecomputeOptions options;
  options.threads = 1;
  const auto deformer = makeDeformer(methods::somigliana(), cage, points, options);
  for (const reference::PoseParameters& p : c.parameters) {
    const size_t k = std::find(nus.begin(), nus.end(), p.nu) - nus.begin();
    const reference::BoundaryConditions bc = reference::boundaryConditions(cage, posed, p);
    Eigen::MatrixXd golden(points.rows(), 3);
    for (Eigen::Index q = 0; q < points.rows(); ++q)
      golden.row(q) = reference::deformPoint(cage, posed, coordinates[q][k], bc).transpose();
    const Eigen::MatrixXd actual = deformer->deform(posed, DeformParams{p.blend, p.nu, p.gamma, p.tractionCorrection});
    const double error = (actual - golden).rowwise().norm().maxCoeff() / diameter;
    const double displacement = (golden - points).rowwise().norm().maxCoeff() / diameter;
    std::printf(
        "  %s blend %.1f nu %.1f gamma %.1f%s: %ld points moved by up to %.3f diameters, "
        "largest |core - golden| %.1e diameters\n",
        c.model.folder.c_str(), p.blend, p.nu, p.gamma, p.tractionCorrection ? "" : " nofix",
        static_cast<long>(points.rows()), displacement, error);
    EXPECT_LE(error, 1e-10) << "blend " << p.blend << " nu " << p.nu << " gamma " << p.gamma;
    EXPECT_GT(displacement, 1e-2) << "the pose should move the mesh (else the comparison shows little)";
  }
}

INSTANTIATE_TEST_SUITE_P(SharedModels, GoldenDeformation, ::testing::ValuesIn(goldenCases()),
                         [](const auto& info) { return info.param.model.folder; });

}  // namespace
}  // namespace somicage
