// The stable variant (VariantKind::Stable, boundary_conditions.cpp): the local variant with the non-uniform part of
// its volumetric tractions damped by 1 / (1 + (nu/(1-2nu))^2). Issue 26's goals, against the local and global
// variants as the references: the same as local at nu = 0; no fold-overs where local folds in the paper's poses;
// where local does not fold, closer to local than half the local-global distance.
#include <gtest/gtest.h>

#include "analysis/deformation_analysis.h"
#include "deform/deformer.h"
#include "deform/jacobian.h"
#include "io/obj_io.h"
#include "methods/method_descriptors.h"
#include "test_models.h"
#include "test_shapes.h"

namespace somicage {
namespace {

DeformParams variant(VariantKind kind, double blend, double nu, double gamma = 0) {
  DeformParams p{blend, nu, gamma, true};
  p.kind = kind;
  return p;
}
DeformParams local(double nu, double gamma = 0) { return variant(VariantKind::Blend, 1, nu, gamma); }
DeformParams global(double nu) { return variant(VariantKind::Blend, 0, nu); }
DeformParams stable(double nu, double gamma = 0) { return variant(VariantKind::Stable, 1, nu, gamma); }

double meanDistance(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).rowwise().norm().mean(); }

TEST(StableVariant, IsTheLocalVariantAtNuZero) {
  for (int d : {2, 3}) {
    const Cage cage = d == 3 ? test::makeBumpySphere(1) : test::makeStarPolygon(6);
    const Eigen::MatrixXd points = d == 3 ? test::randomBallPoints(40, 0.6, 3) : test::randomDiscPoints(40, 0.4, 3);
    const auto deformer = makeDeformer(methods::somigliana(), cage, points, {}, noProgress);
    const Eigen::MatrixXd pose = test::bendPose(cage.vertices, 0.4, 5);
    for (double gamma : {0.0, 2.0}) {
      const double gap = (deformer->deform(pose, stable(0, gamma)) - deformer->deform(pose, local(0, gamma)))
                             .rowwise()
                             .norm()
                             .maxCoeff();
      EXPECT_LE(gap, 1e-12 * cageDiameter(pose)) << d << "D gamma " << gamma;
    }
  }
}

struct FoldCase {
  const char* folder;
  int stride;  // every stride-th mesh vertex
  std::vector<double> nus;
};

// Fold-over vertices (det J <= 0) of the paper's pose for a variant.
int foldovers(const DeformationGradients& gradients, const Eigen::MatrixXd& points, const Eigen::MatrixXd& posed,
              const DeformParams& params) {
  return analyzeDeformation(gradients, points, {}, posed, params).points.foldovers;
}

// Issue 26's goal: at most 1 % of the local variant's fold-overs (measured: none at all on the whole meshes,
// against FIREHYDRANT's 16,550 / 19,026 at nu = 0.45 / 0.49 and CACTUS's 778 / 951 at 0.4 / 0.45).
TEST(StableVariant, DoesNotFoldWhereTheLocalVariantFolds) {
#ifdef SOMICAGE_SANITIZE
  const std::vector<FoldCase> cases = {{"cactus", 10, {0.45}}};
#else
  const std::vector<FoldCase> cases = {{"cactus", 1, {0.4, 0.45}}, {"firehydrant", 8, {0.45, 0.49}}};
#endif
  for (const FoldCase& c : cases) {
    test::ModelCase model;
    for (const test::ModelCase& m : test::modelCases())
      if (m.folder == c.folder) model = m;
    Cage cage;
    Eigen::MatrixXd points;
    if (!test::loadModel(model, cage, points, c.stride)) return;
    const Eigen::MatrixXd posed = loadCage(test::modelPath(model, model.pose)).vertices;
    const auto deformer = makeDeformer(methods::somigliana(), cage, points, {}, noProgress);
    const DeformationGradients gradients(*deformer, points);
    for (double nu : c.nus) {
      const int byLocal = foldovers(gradients, points, posed, local(nu));
      const int byStable = foldovers(gradients, points, posed, stable(nu));
      EXPECT_GT(byLocal, 50) << c.folder << " nu " << nu << ": the case tests a folding pose";
      EXPECT_LE(100 * byStable, byLocal) << c.folder << " nu " << nu;
      std::printf("  %s nu %.2f: fold-overs local %d, stable %d (of %d points)\n", c.folder, nu, byLocal, byStable,
                  static_cast<int>(points.rows()));
    }
  }
}

// Where the local variant does not fold it acts little: FIREHYDRANT at nu = 0.3 (measured on the whole mesh: mean
// distance to local 0.29 of local-global) and a bent bumpy sphere at 0.3.
TEST(StableVariant, StaysNearTheLocalVariantWhereThatDoesNotFold) {
  test::ModelCase hydrant;
  for (const test::ModelCase& m : test::modelCases())
    if (m.folder == "firehydrant") hydrant = m;
  struct Scene {
    Cage cage;
    Eigen::MatrixXd points, posed;
  };
  std::vector<Scene> scenes;
  const Cage sphere = test::makeBumpySphere(1);
  scenes.push_back({sphere, test::randomBallPoints(200, 0.6, 3), test::bendPose(sphere.vertices, 0.3, 5)});
  Scene model;
  if (test::loadModel(hydrant, model.cage, model.points, 16)) {
    model.posed = loadCage(test::modelPath(hydrant, hydrant.pose)).vertices;
    scenes.push_back(model);
  }
  for (const Scene& s : scenes) {
    const auto deformer = makeDeformer(methods::somigliana(), s.cage, s.points, {}, noProgress);
    const DeformationGradients gradients(*deformer, s.points);
    const double nu = 0.3;
    ASSERT_EQ(foldovers(gradients, s.points, s.posed, local(nu)), 0) << "the case has local not folding";
    const Eigen::MatrixXd l = deformer->deform(s.posed, local(nu));
    const double toLocal = meanDistance(deformer->deform(s.posed, stable(nu)), l);
    const double localToGlobal = meanDistance(deformer->deform(s.posed, global(nu)), l);
    EXPECT_LE(toLocal, 0.5 * localToGlobal) << s.cage.numVertices() << "-vertex cage";
    EXPECT_GT(toLocal, 0.0) << "it acts at nu > 0";
  }
}

}  // namespace
}  // namespace somicage
