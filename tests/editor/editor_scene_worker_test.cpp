// Demo scenes, the precompute worker (progress, cancel, errors) and the AppState deformation loop.
#include <gtest/gtest.h>

#include <cmath>

#include "app_state.h"
#include "precompute_worker.h"
#include "scene.h"

using namespace somicage;
using namespace somicage::editor;

TEST(EditorScene, DemoCagesEncloseTheirMeshesAndFaceOutward) {
  for (int dim : {2, 3}) {
    const Scene s = makeDemoScene(dim);
    ASSERT_EQ(s.dim(), dim);
    ASSERT_EQ(s.meshVertices.cols(), dim);
    ASSERT_EQ(s.meshTriangles.cols(), 3);
    ASSERT_GT(s.meshTriangles.rows(), 1000);
    EXPECT_GE(s.meshTriangles.minCoeff(), 0);
    EXPECT_LT(s.meshTriangles.maxCoeff(), s.meshVertices.rows());
    Eigen::Vector3d lo, hi, clo, chi;
    bounds3(s.meshVertices, lo, hi);
    bounds3(s.restCage.vertices, clo, chi);
    EXPECT_TRUE((clo.array() <= lo.array()).all() && (hi.array() <= chi.array()).all());
    if (dim == 3) {
      EXPECT_GT(signedVolume(s.restCage.vertices, s.restCage.faces), 0.0);
      EXPECT_GT(signedVolume(s.meshVertices, s.meshTriangles), 0.0);
      // Closed: every edge is shared by exactly two faces in opposite directions.
      std::map<std::pair<int, int>, int> edges;
      for (Eigen::Index f = 0; f < s.restCage.faces.rows(); ++f)
        for (int k = 0; k < 3; ++k) ++edges[{s.restCage.faces(f, k), s.restCage.faces(f, (k + 1) % 3)}];
      for (const auto& [e, n] : edges) EXPECT_EQ(edges.count({e.second, e.first}), 1u);
    }
  }
}

TEST(EditorWorker, PrecomputesEveryRequestedMethod) {
  PrecomputeWorker worker;
  PrecomputeRequest r;
  r.scene = std::make_shared<const Scene>(makeDemoScene(2));
  r.methods = {Method::Green, Method::MeanValue};
  worker.start(r);
  const std::optional<PrecomputeOutcome> out = worker.wait();
  ASSERT_TRUE(out.has_value());
  EXPECT_TRUE(out->error.empty()) << out->error;
  EXPECT_FALSE(out->cancelled);
  EXPECT_EQ(out->deformers.size(), 2u);
  EXPECT_EQ(worker.progress(), 1.0);
  EXPECT_FALSE(worker.poll().has_value());  // taken once
}

TEST(EditorWorker, LoaderErrorsAreReportedNotThrown) {
  PrecomputeWorker worker;
  PrecomputeRequest r;
  r.loadScene = []() { return loadScene("/nonexistent/mesh.obj", "/nonexistent/cage.obj"); };
  r.methods = {Method::Green};
  worker.start(r);
  const std::optional<PrecomputeOutcome> out = worker.wait();
  ASSERT_TRUE(out.has_value());
  EXPECT_FALSE(out->error.empty());
  EXPECT_TRUE(out->deformers.empty());
}

TEST(EditorWorker, CancelStopsWithoutResults) {
  PrecomputeWorker worker;
  PrecomputeRequest r;
  r.loadScene = []() { return makeDemoScene(3); };
  r.methods = {Method::Somigliana, Method::Green, Method::MeanValue};
  worker.start(r);
  worker.cancel();
  const std::optional<PrecomputeOutcome> out = worker.wait();
  ASSERT_TRUE(out.has_value());
  // The cancel may land after the last progress report; either way nothing half-done is delivered.
  if (out->cancelled) {
    EXPECT_TRUE(out->deformers.empty());
  } else {
    EXPECT_EQ(out->deformers.size(), 3u);
  }
}

TEST(EditorAppState, RestPoseReproducesTheMeshAndEditsMoveIt) {
  AppState state;
  state.compare = true;
  requestDemo(state, 3);
  std::optional<PrecomputeOutcome> out = state.worker.wait();
  ASSERT_TRUE(out.has_value());
  installOutcome(state, std::move(*out));
  ASSERT_TRUE(state.errors.empty()) << state.errors.front();
  ASSERT_TRUE(state.scene);
  ASSERT_EQ(state.deformers.size(), 3u);
  ASSERT_TRUE(updateDeformation(state));
  for (Method m : state.viewMethods()) {
    const double err = (displayedPoints(state, m) - state.scene->meshVertices).cwiseAbs().maxCoeff();
    EXPECT_LT(err, 1e-6) << methodName(m) << " at rest";
  }
  Eigen::MatrixXd pose = state.pose;
  for (Eigen::Index i = 0; i < pose.rows(); ++i) {
    if (pose(i, 0) > 2.0) pose(i, 1) += 0.5;  // lift the right end of the cage
  }
  recordEdit(state, "Grab");
  setPose(state, pose);
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_FALSE(updateDeformation(state));  // nothing changed since
  const Eigen::MatrixXd& moved = displayedPoints(state, Method::Somigliana);
  EXPECT_GT((moved - state.scene->meshVertices).cwiseAbs().maxCoeff(), 0.1);
  undo(state);
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_LT((displayedPoints(state, Method::Somigliana) - state.scene->meshVertices).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(EditorAppState, SessionOfTheDemoRoundTripsThroughTheState) {
  AppState state;
  requestDemo(state, 2);
  std::optional<PrecomputeOutcome> out = state.worker.wait();
  ASSERT_TRUE(out.has_value());
  installOutcome(state, std::move(*out));
  state.pose(0, 0) -= 0.25;
  state.params.gamma = 1.5;
  const Session s = sessionFromJson(sessionToJson(makeSession(state)), "mem");
  EXPECT_EQ(s.demoDim, 2);
  EXPECT_EQ(s.pose, state.pose);
  EXPECT_EQ(s.params.gamma, 1.5);
}
