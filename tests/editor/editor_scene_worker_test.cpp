// Demo scenes, the precompute worker (progress, cancel, errors) and the AppState deformation loop.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <thread>

#include "base/errors.h"
#include "cage/cage_repair.h"
#include "cage/cage_validation.h"
#include "core/constant_method.h"
#include "core/scratch_folder.h"
#include "deform/memory_estimate.h"
#include "interaction/shortcuts.h"
#include "io/obj_io.h"
#include "job_waiting.h"
#include "jobs/precompute_worker.h"
#include "methods/method_descriptors.h"
#include "model/app_state.h"
#include "model/scene.h"
#include "tetrahedralization/cage_tetrahedralization.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

// For a convex body: each face's (3D) or edge's (2D, (e_y, -e_x)) normal has a positive component along the
// direction from the vertices' centroid to the face's centroid.
void expectNormalsPointAwayFromCentroid(const Eigen::MatrixXd& V, const Eigen::MatrixXi& faces, const char* what) {
  const Eigen::RowVectorXd centroid = V.colwise().mean();
  int inward = 0;
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    Eigen::RowVectorXd faceCentroid = Eigen::RowVectorXd::Zero(V.cols());
    for (Eigen::Index k = 0; k < faces.cols(); ++k) faceCentroid += V.row(faces(f, k)) / double(faces.cols());
    const Eigen::RowVectorXd toFace = faceCentroid - centroid, e1 = V.row(faces(f, 1)) - V.row(faces(f, 0));
    double outward = e1(1) * toFace(0) - e1(0) * toFace(1);  // 2D: (e_y, -e_x) . toFace
    if (V.cols() == 3) {
      const Eigen::RowVectorXd e2 = V.row(faces(f, 2)) - V.row(faces(f, 0));
      outward = (e1(1) * e2(2) - e1(2) * e2(1)) * toFace(0) + (e1(2) * e2(0) - e1(0) * e2(2)) * toFace(1) +
                (e1(0) * e2(1) - e1(1) * e2(0)) * toFace(2);  // (e1 x e2) . toFace
    }
    inward += outward <= 0;
  }
  EXPECT_EQ(inward, 0) << what << ": faces whose normal points into the body";
}

}  // namespace

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
    // The engine would take the demo cage as it is: valid (closed, manifold, consistently oriented, enclosing a
    // positive measure), with nothing to repair.
    EXPECT_TRUE(validateCage(s.restCage).valid());
    EXPECT_TRUE(repairCage(s.restCage).fixes.empty());
    // Outward, face by face: the cage (a box) and the 3D mesh (a capped cylinder) are convex, so every face's
    // normal points away from the body's centroid.
    expectNormalsPointAwayFromCentroid(s.restCage.vertices, s.restCage.faces, "cage");
    if (dim == 3) {
      expectNormalsPointAwayFromCentroid(s.meshVertices, s.meshTriangles, "mesh");
      EXPECT_GT(signedMeasure(s.meshVertices, s.meshTriangles), 0.0);
      // Closed and consistently wound: every directed edge once, and its reverse once.
      std::map<std::pair<int, int>, int> edges;
      for (Eigen::Index f = 0; f < s.restCage.faces.rows(); ++f)
        for (int k = 0; k < 3; ++k) ++edges[{s.restCage.faces(f, k), s.restCage.faces(f, (k + 1) % 3)}];
      for (const auto& [e, n] : edges) {
        EXPECT_EQ(n, 1) << "edge " << e.first << "-" << e.second;
        EXPECT_EQ(edges.count({e.second, e.first}), 1u) << "edge " << e.first << "-" << e.second;
      }
    }
  }
}

TEST(EditorWorker, PrecomputesEveryRequestedMethod) {
  PrecomputeWorker worker;
  PrecomputeRequest r;
  r.scene = std::make_shared<const Scene>(makeDemoScene(2));
  r.methods = {methods::green(), methods::mvc()};
  worker.start(r);
  const std::optional<PrecomputeOutcome> out = waitForOutcome(worker);
  ASSERT_TRUE(out.has_value());
  EXPECT_TRUE(out->error.empty()) << out->error;
  EXPECT_FALSE(out->cancelled);
  EXPECT_EQ(out->scene, r.scene);
  ASSERT_EQ(out->deformers.size(), 2u);
  // Each delivered deformer is the requested method's, made for the scene's points: at the rest pose it gives the
  // points back (both methods reproduce the identity, float storage: 1e-5 diameters), and a translated pose
  // translates them (partition of unity).
  const Scene& scene = *r.scene;
  const double diameter = cageDiameter(scene.restCage.vertices);
  for (const DeformerKey& m : r.methods) {
    SCOPED_TRACE(methodName(m.method));
    ASSERT_EQ(out->deformers.count(m), 1u);
    const CageDeformer& deformer = *out->deformers.at(m);
    ASSERT_EQ(deformer.numPoints(), scene.meshVertices.rows());
    EXPECT_LE((deformer.deform(scene.restCage.vertices, {}) - scene.meshVertices).cwiseAbs().maxCoeff(),
              1e-5 * diameter);
    const Eigen::RowVector2d shift(0.25, -0.5);
    EXPECT_LE((deformer.deform(scene.restCage.vertices.rowwise() + shift, {}) - (scene.meshVertices.rowwise() + shift))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-5 * diameter);
  }
  EXPECT_EQ(worker.progress(), 1.0);
  EXPECT_FALSE(worker.poll().has_value());  // taken once
}

TEST(EditorWorker, LoaderErrorsAreReportedNotThrown) {
  PrecomputeWorker worker;
  PrecomputeRequest r;
  r.loadScene = []() { return loadScene("/nonexistent/mesh.obj", "/nonexistent/cage.obj"); };
  r.methods = {methods::green()};
  worker.start(r);
  const std::optional<PrecomputeOutcome> out = waitForOutcome(worker);
  ASSERT_TRUE(out.has_value());
  EXPECT_FALSE(out->error.empty());
  EXPECT_TRUE(out->deformers.empty());
}

TEST(EditorWorker, CancelStopsWithoutResults) {
  // A loader that waits for the cancel, so that it lands before any precompute (deterministically): the outcome
  // must say cancelled and deliver no deformer, not some of the three.
  PrecomputeWorker worker;
  PrecomputeRequest r;
  std::atomic<bool> loading{false}, cancelled{false};
  r.loadScene = [&]() {
    loading = true;
    while (!cancelled) std::this_thread::yield();
    return makeDemoScene(3);
  };
  r.methods = {methods::somigliana(), methods::green(), methods::mvc()};
  worker.start(r);
  while (!loading) std::this_thread::yield();
  worker.cancel();
  cancelled = true;
  const std::optional<PrecomputeOutcome> out = waitForOutcome(worker);
  ASSERT_TRUE(out.has_value());
  EXPECT_TRUE(out->cancelled);
  EXPECT_TRUE(out->deformers.empty());
  EXPECT_TRUE(out->error.empty()) << out->error;
  // A cancel after the request finished changes nothing: the next request runs whole.
  r.loadScene = []() { return makeDemoScene(2); };
  r.methods = {methods::green()};
  worker.start(r);
  const std::optional<PrecomputeOutcome> done = waitForOutcome(worker);
  worker.cancel();
  ASSERT_TRUE(done.has_value());
  EXPECT_FALSE(done->cancelled);
  EXPECT_EQ(done->deformers.size(), 1u);
}

namespace {

// A method whose precompute reports progress until it is told to stop, then stops as every precompute does
// (throws Cancelled): a cancel that arrives while a method is precomputing, deterministically, whatever the speed.
// While blockingHolds is false it precomputes the constant method's deformer (y = x + the mean displacement).
std::atomic<bool> blockingEntered{false}, blockingHolds{true};
const MethodDescriptor& blockingMethod() {
  static const MethodDescriptor descriptor = [] {
    MethodDescriptor d = test::constantMethod();
    d.name = "blocking";
    d.displayName = "Blocking";
    d.precompute = [](const Cage& cage, const Eigen::MatrixXd& points, const PrecomputeOptions& options,
                      const ProgressCallback& progress) -> std::unique_ptr<CageDeformer> {
      if (!blockingHolds) return test::constantMethod().precompute(cage, points, options, progress);
      blockingEntered = true;
      while (progress(0.5)) std::this_thread::yield();
      throw Cancelled();
    };
    return d;
  }();
  return descriptor;
}

}  // namespace

// Issue 23: the cancel tests accepted both outcomes. A cancel in the middle of the second method's precompute: the
// outcome is cancelled and delivers nothing, not even the first method's finished deformer; the worker then runs the
// next request whole.
TEST(EditorWorker, ACancelDuringAPrecomputeDeliversNoDeformer) {
  PrecomputeWorker worker;
  PrecomputeRequest r;
  r.scene = std::make_shared<const Scene>(makeDemoScene(3));
  r.methods = {methods::green(), Method(blockingMethod())};
  blockingEntered = false;
  worker.start(r);
  while (!blockingEntered) std::this_thread::yield();  // green is done, the blocking precompute runs
  worker.cancel();
  const std::optional<PrecomputeOutcome> out = waitForOutcome(worker);
  ASSERT_TRUE(out.has_value());
  EXPECT_TRUE(out->cancelled);
  EXPECT_TRUE(out->deformers.empty());
  EXPECT_TRUE(out->error.empty()) << out->error;
  r.methods = {methods::green()};
  worker.start(r);
  const std::optional<PrecomputeOutcome> again = waitForOutcome(worker);
  ASSERT_TRUE(again.has_value());
  EXPECT_FALSE(again->cancelled);
  EXPECT_EQ(again->deformers.size(), 1u);
}

// Issue 24: Esc after the scene was shown (its deformers still precomputing) left it without deformers until the
// views changed: a handle moved the cage and not the mesh, silently. Esc stops the precompute (the cores come back
// at once) and the scene stays at rest, its label saying so; the next edit of the pose starts the precompute again,
// and its deformer then deforms the mesh: y = x + the cage's mean displacement (the constant method), to 1e-5 (the
// editor stores C in float).
TEST(EditorWorker, AnEditAfterEscCancelledTheShownScenesPrecomputeStartsItAgain) {
  const ParameterRegistration shift{test::shiftParameter()};  // the constant method's parameter (0 here)
  AppState state;
  state.document.method = Method(blockingMethod());
  blockingEntered = false;
  blockingHolds = true;
  requestDemo(state, 3);
  waitUntil([] { return blockingEntered.load(); });
  pollWorker(state);  // the frame loop: the scene is shown, undeformed, while its deformer is computed
  ASSERT_TRUE(state.model.scene);
  ASSERT_TRUE(state.jobs.load && state.jobs.load->sceneShown);
  cancelPrecompute(state);  // Esc
  waitUntilDone(state.jobs.precompute);
  pollWorker(state);
  EXPECT_FALSE(state.loadingScene());
  EXPECT_FALSE(state.jobs.precompute.busy()) << "Esc did not stop the precompute";
  EXPECT_NE(viewLabel(state, 0).find("(cancelled: an edit precomputes it)"), std::string::npos) << viewLabel(state, 0);
  EXPECT_TRUE(state.status.errors.empty());

  blockingHolds = false;  // the precompute asked for next runs to its end
  Eigen::MatrixXd pose = state.model.scene->restCage.vertices;
  pose.row(0) += Eigen::RowVector3d(0.3, 0.0, 0.0);
  setPose(state, pose);  // a handle moved
  commitEdit(state, "Grab");
  ASSERT_TRUE(state.jobs.precompute.busy()) << "the edit did not ask for the deformers again";
  waitUntilDone(state.jobs.precompute);
  pollWorker(state);
  ASSERT_TRUE(hasDeformer(state, state.deformerKeys().front()));
  ASSERT_TRUE(updateDeformation(state));
  const Eigen::RowVectorXd u = (pose - state.model.scene->restCage.vertices).colwise().mean();
  const Eigen::MatrixXd expected = state.model.scene->meshVertices.rowwise() + u;
  EXPECT_LT((displayedPoints(state, 0) - expected).cwiseAbs().maxCoeff(), 1e-5);
  EXPECT_EQ(viewLabel(state, 0).find("cancelled"), std::string::npos);
}

// A posed cage given with the scene (somicage MESH CAGE POSED) is read on the load job with the scene, not on the UI
// thread when the scene is shown: here the file is replaced by another pose after the job has finished and before
// the frame loop takes the outcome, and the scene opens in the pose the job read (exactly), as one undo step.
TEST(EditorWorker, APosedCageGivenWithTheSceneIsReadOnTheLoadJob) {
  const test::ScratchFolder dir;
  const Scene demo = makeDemoScene(3);
  const std::string mesh = dir / "mesh.obj", cage = dir / "cage.obj", posed = dir / "posed.obj";
  PolygonMesh triangles;
  for (Eigen::Index t = 0; t < demo.meshTriangles.rows(); ++t)
    triangles.faces.push_back({demo.meshTriangles(t, 0), demo.meshTriangles(t, 1), demo.meshTriangles(t, 2)});
  saveObj(mesh, demo.meshVertices, triangles);
  saveObj(cage, demo.restCage.vertices, cageTopology(demo.restCage));
  Eigen::MatrixXd read = demo.restCage.vertices, later = demo.restCage.vertices;
  read.row(2) += Eigen::RowVector3d(0.25, -0.5, 0.125);  // exact in binary and in the OBJ's text
  later.row(2) += Eigen::RowVector3d(-1.0, 0.0, 0.0);
  saveObj(posed, read, cageTopology(demo.restCage));
  AppState state;
  requestSceneFiles(state, mesh, cage, posed);
  waitUntilDone(state.jobs.precompute);
  saveObj(posed, later, cageTopology(demo.restCage));  // what a read on the UI thread would see
  pollWorker(state);
  ASSERT_TRUE(state.model.scene) << (state.status.errors.empty() ? "" : state.status.errors.front());
  EXPECT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  EXPECT_EQ(state.document.pose, read);
  EXPECT_EQ(state.document.history.step(state.document.history.cursor()).name, "Load posed cage");
}

// File > Load posed cage and a posed cage dropped on the scene shown are read on their job too
// (JobsState::posedCage): the file replaced after the job has finished changes nothing; a pose read for a scene that
// is no longer shown is not applied.
TEST(EditorWorker, APosedCageLoadedOrDroppedOnTheSceneIsReadOnItsJob) {
  const test::ScratchFolder dir;
  AppState state;
  requestDemo(state, 3);
  std::optional<PrecomputeOutcome> out = waitForOutcome(state.jobs.precompute);
  ASSERT_TRUE(out.has_value());
  installOutcome(state, std::move(*out));
  const Cage& cage = state.model.scene->restCage;
  const std::string posed = dir / "posed.obj";
  Eigen::MatrixXd read = cage.vertices, later = cage.vertices;
  read.row(1) += Eigen::RowVector3d(0.5, 0.25, -0.125);  // exact in binary and in the OBJ's text
  later.row(1) += Eigen::RowVector3d(-1.0, 0.0, 0.0);
  for (const bool dropped : {false, true}) {
    SCOPED_TRACE(dropped ? "dropped" : "File > Load posed cage");
    resetPose(state);
    saveObj(posed, read, cageTopology(cage));
    if (dropped)
      openDroppedFiles(state, {posed});
    else
      ASSERT_TRUE(loadPosedCage(state, posed));
    EXPECT_EQ(state.document.pose, cage.vertices) << "not read on the UI thread";
    waitUntilDone(state.jobs.posedCage);
    saveObj(posed, later, cageTopology(cage));  // what a read on the UI thread would see
    ASSERT_TRUE(pollPosedCage(state)) << (state.status.errors.empty() ? "" : state.status.errors.front());
    EXPECT_EQ(state.document.pose, read);
    EXPECT_EQ(state.document.history.step(state.document.history.cursor()).name, "Load posed cage");
  }
  ASSERT_TRUE(loadPosedCage(state, posed));
  waitUntilDone(state.jobs.posedCage);
  state.model.scene = std::make_shared<const Scene>(makeDemoScene(3));  // another scene shown meanwhile
  EXPECT_FALSE(pollPosedCage(state));
  EXPECT_EQ(state.document.pose, read) << "a pose read for another scene is not applied";
  ASSERT_EQ(state.status.errors.size(), 1u);
  EXPECT_NE(state.status.errors[0].find("another scene was opened"), std::string::npos) << state.status.errors[0];
}

TEST(EditorAppState, RestPoseReproducesTheMeshAndEditsMoveIt) {
  AppState state;
  state.view.compare = true;
  requestDemo(state, 3);
  std::optional<PrecomputeOutcome> out = waitForOutcome(state.jobs.precompute);
  ASSERT_TRUE(out.has_value());
  installOutcome(state, std::move(*out));
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  ASSERT_TRUE(state.model.scene);
  ASSERT_EQ(state.model.deformers.size(), 3u);
  ASSERT_TRUE(updateDeformation(state));
  for (std::size_t v = 0; v < state.views().size(); ++v) {
    const double err = (displayedPoints(state, v) - state.model.scene->meshVertices).cwiseAbs().maxCoeff();
    EXPECT_LT(err, 1e-6) << methodName(state.views()[v].method) << " at rest";
  }
  Eigen::MatrixXd pose = state.document.pose;
  for (Eigen::Index i = 0; i < pose.rows(); ++i) {
    if (pose(i, 0) > 2.0) pose(i, 1) += 0.5;  // lift the right end of the cage
  }
  setPose(state, pose);
  commitEdit(state, "Grab");
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_FALSE(updateDeformation(state));                    // nothing changed since
  const Eigen::MatrixXd& moved = displayedPoints(state, 0);  // Somigliana
  EXPECT_GT((moved - state.model.scene->meshVertices).cwiseAbs().maxCoeff(), 0.1);
  undo(state);
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_LT((displayedPoints(state, 0) - state.model.scene->meshVertices).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(EditorAppState, SessionOfTheDemoRoundTripsThroughTheState) {
  AppState state;
  requestDemo(state, 2);
  std::optional<PrecomputeOutcome> out = waitForOutcome(state.jobs.precompute);
  ASSERT_TRUE(out.has_value());
  installOutcome(state, std::move(*out));
  state.document.pose(0, 0) -= 0.25;
  state.document.params.gamma = 1.5;
  const Session s = sessionFromJson(sessionToJson(makeSession(state)), "mem");
  EXPECT_EQ(s.demoDim, 2);
  EXPECT_EQ(s.pose, state.document.pose);
  EXPECT_EQ(s.params.gamma, 1.5);
}

// ---- a request that fails or is cancelled leaves the current scene and its deformers as they were ----

namespace {

// The 3D demo with Somigliana and Green deformers installed.
void loadDemo(AppState& state) {
  state.view.compare = true;
  state.view.compareViews = viewsOf({methods::somigliana(), methods::green()});
  requestDemo(state, 3);
  std::optional<PrecomputeOutcome> out = waitForOutcome(state.jobs.precompute);
  ASSERT_TRUE(out.has_value());
  installOutcome(state, std::move(*out));
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  ASSERT_EQ(state.model.deformers.size(), 2u);
}

// What must survive a failed or cancelled load: the scene, its deformers (the same objects) and the pose.
struct KeptScene {
  std::shared_ptr<const Scene> scene;
  DeformerSet deformers;
  Eigen::MatrixXd pose;
};

// ... and a working deformation.
void expectSceneKept(AppState& state, const KeptScene& kept) {
  EXPECT_EQ(state.model.scene, kept.scene);
  EXPECT_EQ(state.model.deformers, kept.deformers);
  EXPECT_EQ(state.document.pose, kept.pose);
  EXPECT_FALSE(state.loadingScene());
  state.model.deformDirty = true;
  EXPECT_TRUE(updateDeformation(state));
  EXPECT_GT((displayedPoints(state, 0) - kept.scene->meshVertices).cwiseAbs().maxCoeff(), 0.01);
}

// A bent pose, so that a kept deformation is told apart from the rest mesh.
void bend(AppState& state) {
  Eigen::MatrixXd pose = state.document.pose;
  for (Eigen::Index i = 0; i < pose.rows(); ++i)
    if (pose(i, 0) > 2.0) pose(i, 1) += 0.5;
  setPose(state, pose);
}

// The bent 3D demo, installed, and what of it must be kept.
KeptScene loadBentDemo(AppState& state) {
  loadDemo(state);
  bend(state);
  return {state.model.scene, state.model.deformers, state.document.pose};
}

}  // namespace

TEST(EditorWorker, AFailedLoadKeepsTheCurrentScene) {
  AppState state;
  const KeptScene kept = loadBentDemo(state);
  requestSceneFiles(state, "/nonexistent/mesh.obj", "/nonexistent/cage.obj");
  EXPECT_TRUE(state.loadingScene());
  std::optional<PrecomputeOutcome> out = waitForOutcome(state.jobs.precompute);
  ASSERT_TRUE(out.has_value());
  installOutcome(state, std::move(*out));
  ASSERT_EQ(state.status.errors.size(), 1u);
  EXPECT_NE(state.status.errors.front().find("/nonexistent/"), std::string::npos)
      << state.status.errors.front();  // names the file
  expectSceneKept(state, kept);
}

TEST(EditorWorker, AScenePastTheFreeMemoryIsRefusedAndTheCurrentOneKept) {
  AppState state;
  const KeptScene kept = loadBentDemo(state);
  ::setenv("SOMICAGE_MEMORY_LIMIT_BYTES", "10000", 1);  // 10 kB: far less than the 2D demo needs
  requestDemo(state, 2);
  std::optional<PrecomputeOutcome> out = waitForOutcome(state.jobs.precompute);
  ::unsetenv("SOMICAGE_MEMORY_LIMIT_BYTES");
  ASSERT_TRUE(out.has_value());
  EXPECT_TRUE(out->deformers.empty());
  installOutcome(state, std::move(*out));
  ASSERT_EQ(state.status.errors.size(), 1u);
  EXPECT_NE(state.status.errors.front().find("points need"), std::string::npos) << state.status.errors.front();
  EXPECT_NE(state.status.errors.front().find("but only 10 kB are free"), std::string::npos)
      << state.status.errors.front();
  expectSceneKept(state, kept);
}

// A Phong deformer's layout has columns per vertex of its tetrahedral mesh, stored as sparse rows (16 entries a point
// whatever the mesh): the check is made with the mesh made first, which the precompute then uses, and a limit just
// below what it needs refuses it.
TEST(EditorWorker, APhongPrecomputeCountsItsTetrahedralMeshInTheMemoryCheck) {
  const auto scene = std::make_shared<const Scene>(makeDemoScene(3));
  PrecomputeRequest request;
  request.scene = scene;
  request.methods = {methods::phong()};
  request.options.volumeMesher = tetrahedralizeCageWithOptions;
  const std::size_t points = static_cast<std::size_t>(scene->meshVertices.rows());
  const int meshVertices = volumeMeshFor(scene->restCage, request.options)->numVertices();
  ASSERT_GT(meshVertices, scene->restCage.numVertices());
  const auto total = [&](int vertices) {
    return estimatePrecomputeMemory(methods::phong(), 3, vertices, scene->restCage.numFaces(), points,
                                    request.options.floatStorage, request.options.threads)
        .total();
  };
  // Sparse rows: C's size does not depend on the mesh (coordinate_layout.h).
  EXPECT_EQ(total(scene->restCage.numVertices()), total(meshVertices));
  const double limit = 0.99 * static_cast<double>(total(meshVertices)) / kMemorySafetyFraction;
  PrecomputeWorker worker;
  ::setenv("SOMICAGE_MEMORY_LIMIT_BYTES", std::to_string(static_cast<long long>(limit)).c_str(), 1);
  worker.start(request);
  std::optional<PrecomputeOutcome> out = waitForOutcome(worker);
  ::unsetenv("SOMICAGE_MEMORY_LIMIT_BYTES");
  ASSERT_TRUE(out.has_value());
  EXPECT_TRUE(out->deformers.empty());
  EXPECT_NE(out->error.find("points need"), std::string::npos) << out->error;
  worker.start(request);  // without the limit it is built, over the mesh the check made
  out = waitForOutcome(worker);
  ASSERT_TRUE(out.has_value() && out->error.empty()) << (out ? out->error : "");
  EXPECT_EQ(out->deformers.at(methods::phong())->volumeMesh()->numVertices(), meshVertices);
}

TEST(EditorWorker, ACancelledLoadKeepsTheCurrentScene) {
  AppState state;
  const KeptScene kept = loadBentDemo(state);
  // A loader that waits for the cancel, so that it lands before any precompute (deterministically).
  PrecomputeRequest request;
  PrecomputeWorker& worker = state.jobs.precompute;
  std::atomic<bool> loading{false}, cancelled{false};
  request.loadScene = [&]() {
    loading = true;
    while (!cancelled) std::this_thread::yield();
    return makeDemoScene(2);
  };
  request.methods = {methods::somigliana()};
  state.jobs.load.emplace();
  worker.start(std::move(request));
  while (!loading) std::this_thread::yield();
  worker.cancel();
  cancelled = true;
  std::optional<PrecomputeOutcome> out = waitForOutcome(worker);
  ASSERT_TRUE(out.has_value());
  EXPECT_TRUE(out->cancelled);
  installOutcome(state, std::move(*out));
  EXPECT_TRUE(state.status.errors.empty());
  EXPECT_EQ(state.status.message, "precomputation cancelled");
  expectSceneKept(state, kept);
}

// When Mesh_3 does not finish the tetrahedral mesh asked for (here: a millisecond's bound at level 3) and TetGen's
// comes instead, the user is told: the outcome carries the warning and installing it puts it in the status bar.
TEST(EditorWorker, AMesh3FallbackToTetGenIsShownInTheStatusBar) {
  AppState state;
  requestDemo(state, 3);
  std::optional<PrecomputeOutcome> loaded = waitForOutcome(state.jobs.precompute);
  ASSERT_TRUE(loaded.has_value());
  installOutcome(state, std::move(*loaded));
  ASSERT_TRUE(state.model.scene);
  PrecomputeRequest request;
  request.scene = state.model.scene;
  request.methods = {DeformerKey(methods::phong(), {{"tet-level", "3"}})};  // not the demo cage's star
  request.options.volumeMesher = [](const Cage& cage, const MethodOptions&, const ProgressCallback& progress) {
    return tetrahedralizeCage(cage, 3, progress, {1e-3, 500000});
  };
  PrecomputeWorker worker;
  worker.start(request);
  std::optional<PrecomputeOutcome> out = waitForOutcome(worker);
  ASSERT_TRUE(out.has_value() && out->error.empty()) << (out ? out->error : "");
  ASSERT_EQ(out->notices.size(), 1u);
  EXPECT_NE(out->notices[0].find("Phong: warning: CGAL's Mesh_3 did not finish"), std::string::npos)
      << out->notices[0];
  state.status.message.clear();
  installOutcome(state, std::move(*out));
  EXPECT_NE(state.status.message.find("TetGen's constrained tetrahedralization"), std::string::npos)
      << state.status.message;
}
