// The gradients' cache (CageDeformer::gradients, core/deform/deformer.h): the exact J's coordinate gradients are
// integrated once per deformer and reused at any pose and parameters; a deformer of another cage or other points
// integrates its own; release and cancel keep nothing. The reference for what the cache returns is an independent
// integration (a DeformationGradients constructed here): a cache must give exactly what no cache would.
#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <thread>

#include "base/errors.h"
#include "deform/deformer.h"
#include "deform/jacobian.h"
#include "methods/method_descriptors.h"
#include "test_shapes.h"

namespace somicage {
namespace {

// J at a pose and parameters, from the given gradients.
Eigen::MatrixXd jacobians(const DeformationGradients& gradients, const Eigen::MatrixXd& posed,
                          const DeformParams& params) {
  Eigen::MatrixXd positions, J;
  gradients.evaluate(posed, params, positions, J);
  return J;
}

struct Scene {
  Cage cage;
  Eigen::MatrixXd points;
};

Scene starScene() { return {test::makeStarPolygon(7), test::randomDiscPoints(10, 0.35, 3)}; }

TEST(GradientCache, IntegratesOnceForAnyPoseAndParameters) {
  for (const Method method : {Method(methods::somigliana()), Method(methods::mvc())}) {
    SCOPED_TRACE(method->name);
    const Scene s = starScene();
    const auto deformer = makeDeformer(method, s.cage, s.points);
    EXPECT_EQ(deformer->gradientIntegrations(), 0) << "lazy: nothing before the first use";
    EXPECT_EQ(deformer->keptGradients(), nullptr);
    const std::shared_ptr<const DeformationGradients> first = deformer->gradients(s.points);
    const DeformationGradients fresh(*deformer, s.points);  // the reference: integrated without the cache
    // nu, gamma, the variant and the traction fix change W, never the rows: every one is served by the first rows.
    const DeformParams settings[] = {{0.0, 0.3, 0.0, true}, {1.0, 0.45, 0.7, true}, {0.5, -0.5, 0.2, false}};
    for (unsigned seed = 1; seed <= 3; ++seed)
      for (const DeformParams& params : settings) {
        const Eigen::MatrixXd posed = test::bendPose(s.cage.vertices, 0.1 * seed, seed);
        const std::shared_ptr<const DeformationGradients> again = deformer->gradients(s.points);
        EXPECT_EQ(again, first) << "the kept gradients, not a second integration";
        EXPECT_TRUE(jacobians(*again, posed, params).cwiseEqual(jacobians(fresh, posed, params)).all());
      }
    EXPECT_EQ(deformer->gradientIntegrations(), 1);
  }
}

TEST(GradientCache, AnotherCageOrOtherPointsIntegrateTheirOwn) {
  const Scene s = starScene();
  const auto deformer = makeDeformer(methods::somigliana(), s.cage, s.points);
  const Eigen::MatrixXd posed = test::bendPose(s.cage.vertices, 0.3, 5);
  const DeformParams params{0.0, 0.3, 0.0, true};
  const Eigen::MatrixXd J = jacobians(*deformer->gradients(s.points), posed, params);

  Cage bigger = s.cage;  // the rest cage scaled by 1.25 about the origin, posed alike: J is that of the old map
  bigger.vertices *= 1.25;
  const auto scaled = makeDeformer(methods::somigliana(), bigger, 1.25 * s.points);
  const Eigen::MatrixXd Jscaled = jacobians(*scaled->gradients(1.25 * s.points), 1.25 * posed, params);
  EXPECT_EQ(scaled->gradientIntegrations(), 1) << "a new cage: its own integration";
  EXPECT_LE((Jscaled - J).cwiseAbs().maxCoeff(), 1e-12) << "scaling rest and pose alike leaves J unchanged";

  const Eigen::MatrixXd others = test::randomDiscPoints(10, 0.35, 11);
  const auto moved = makeDeformer(methods::somigliana(), s.cage, others);
  const Eigen::MatrixXd Jothers = jacobians(*moved->gradients(others), posed, params);
  EXPECT_EQ(moved->gradientIntegrations(), 1) << "other points: their own integration";
  EXPECT_TRUE(Jothers.cwiseEqual(jacobians(DeformationGradients(*moved, others), posed, params)).all());
  EXPECT_GT((Jothers - J).cwiseAbs().maxCoeff(), 1e-3) << "the other points' J, not the first points'";
  EXPECT_EQ(deformer->gradientIntegrations(), 1);
}

TEST(GradientCache, ReleaseForgetsThemAndAHolderKeepsItsCopy) {
  const Scene s = starScene();
  const auto deformer = makeDeformer(methods::somigliana(), s.cage, s.points);
  const Eigen::MatrixXd posed = test::bendPose(s.cage.vertices, 0.3, 5);
  const std::shared_ptr<const DeformationGradients> held = deformer->gradients(s.points);
  const Eigen::MatrixXd J = jacobians(*held, posed, DeformParams{});
  deformer->releaseGradients();
  EXPECT_EQ(deformer->keptGradients(), nullptr);
  EXPECT_TRUE(jacobians(*held, posed, DeformParams{}).cwiseEqual(J).all()) << "a holder's copy stays usable";
  EXPECT_NE(deformer->gradients(s.points), held) << "integrated again after the release";
  EXPECT_EQ(deformer->gradientIntegrations(), 2);
}

TEST(GradientCache, ACancelledIntegrationKeepsNothing) {
  const Scene s = starScene();
  const auto deformer = makeDeformer(methods::somigliana(), s.cage, s.points);
  EXPECT_THROW(deformer->gradients(s.points, [](double) { return false; }), Cancelled);
  EXPECT_EQ(deformer->keptGradients(), nullptr);
  EXPECT_EQ(deformer->gradientIntegrations(), 0);
  EXPECT_NE(deformer->gradients(s.points), nullptr);
  EXPECT_EQ(deformer->gradientIntegrations(), 1);
}

TEST(GradientCache, ConcurrentCallersShareOneIntegration) {
  const Scene s = starScene();
  const auto deformer = makeDeformer(methods::somigliana(), s.cage, s.points);
  std::shared_ptr<const DeformationGradients> a, b;
  std::atomic<int> started{0};
  const auto take = [&](std::shared_ptr<const DeformationGradients>& out) {
    started += 1;
    while (started < 2) std::this_thread::yield();
    out = deformer->gradients(s.points);
  };
  std::thread first(take, std::ref(a)), second(take, std::ref(b));
  first.join();
  second.join();
  EXPECT_EQ(a, b);
  EXPECT_EQ(deformer->gradientIntegrations(), 1);
}

}  // namespace
}  // namespace somicage
