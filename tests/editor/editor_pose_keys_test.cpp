// The editor's pose library and timeline: each change is undoable and redoable, a failed change records nothing,
// scrubbing shows the timeline's cage (a key's pose at its frame, the linear mean between two), and sessions keep
// the library and the keys (version 1 sessions still load, with neither). File > Export animation runs one frame
// per editor frame, matches the core export and leaves nothing when cancelled.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

#include "animation/animation_export.h"
#include "animation/normal_transform.h"
#include "base/errors.h"
#include "core/scratch_folder.h"
#include "deform/jacobian.h"
#include "engine/session.h"
#include "io/mesh_document.h"
#include "io/obj_io.h"
#include "job_waiting.h"
#include "jobs/export_jobs.h"
#include "model/app_state.h"
#include "model/pose_keys.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

void loadDemo(AppState& state) {
  state.model.scene = std::make_shared<const Scene>(makeDemoScene(3));
  state.document.pose = state.model.scene->restCage.vertices;
  state.document.history.reset(currentDocument(state), "Original", true);
}

TEST(EditorPoseKeys, LibraryEditsAreUndoable) {
  AppState state;
  loadDemo(state);
  const Eigen::MatrixXd rest = state.document.pose;
  storeCurrentPose(state, "rest");
  Eigen::MatrixXd moved = rest;
  moved.row(0) += Eigen::RowVector3d(0.5, 0, 0);
  setPose(state, moved);
  storeCurrentPose(state, "moved");
  renameNamedPose(state, "moved", "reach");
  ASSERT_NE(state.animation.poses.find("reach"), nullptr);
  applyNamedPose(state, "rest");
  EXPECT_EQ(state.document.pose, rest);
  deleteNamedPose(state, "rest");
  EXPECT_EQ(state.animation.poses.find("rest"), nullptr);

  undo(state);  // delete
  ASSERT_NE(state.animation.poses.find("rest"), nullptr);
  undo(state);  // apply
  EXPECT_EQ(state.document.pose, moved);
  undo(state);  // rename
  EXPECT_NE(state.animation.poses.find("moved"), nullptr);
  EXPECT_EQ(state.animation.poses.find("reach"), nullptr);
  redo(state);
  EXPECT_NE(state.animation.poses.find("reach"), nullptr);

  const size_t undoCount = state.document.history.size();
  renameNamedPose(state, "reach", "rest");  // taken: an error, no edit
  EXPECT_EQ(state.document.history.size(), undoCount);
  EXPECT_EQ(state.status.errors.size(), 1u);
}

TEST(EditorPoseKeys, ScrubbingShowsKeysAndTheLinearMean) {
  AppState state;
  loadDemo(state);
  const Eigen::MatrixXd rest = state.document.pose;
  state.animation.timeline.interpolation = Interpolation::Linear;
  state.animation.frame = 0;
  keyCurrentPose(state);
  Eigen::MatrixXd moved = rest;
  moved.col(1).array() += 0.4;
  setPose(state, moved);
  state.animation.frame = 10;
  state.animation.keyParams = true;
  state.document.params.gamma = 2.0;
  keyCurrentPose(state);
  ASSERT_EQ(state.animation.timeline.keys.size(), 2u);

  scrubTo(state, 0);
  EXPECT_EQ(state.document.pose, rest);
  scrubTo(state, 5);
  EXPECT_LE((state.document.pose - 0.5 * (rest + moved)).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_DOUBLE_EQ(state.document.params.gamma, 2.0) << "the first key sets no gamma: it takes the second's";
  undo(state);  // the second key
  EXPECT_EQ(state.animation.timeline.keys.size(), 1u);
}

TEST(EditorPoseKeys, SessionsKeepPosesAndKeysAndVersion1Loads) {
  AppState state;
  loadDemo(state);
  storeCurrentPose(state, "a");
  Eigen::MatrixXd moved = state.document.pose;
  moved.row(2) += Eigen::RowVector3d(0, 0.25, 0);
  setPose(state, moved);
  keyCurrentPose(state);
  const Session saved = makeSession(state);
  const Session read = sessionFromJson(sessionToJson(saved), "s.json");
  ASSERT_EQ(read.poses.poses().size(), 2u);
  EXPECT_EQ(read.poses.poses()[0].vertices, makeDemoScene(3).restCage.vertices);
  EXPECT_EQ(read.poses.poses()[1].vertices, state.document.pose);
  ASSERT_EQ(read.timeline.keys.size(), 1u);
  EXPECT_EQ(read.timeline.keys[0].pose, state.animation.timeline.keys[0].pose);

  const std::string v1 = R"({"format": "somicage-session", "version": 1, "mesh": "", "cage": "", "demoDim": 3,
    "pose": [], "method": "green", "params": {"blend": 0, "nu": 0, "gamma": 0, "tractionCorrection": true},
    "compare": false, "compareMethods": ["green"],
    "camera": {"target": [0, 0, 0], "distance": 3, "yaw": 0, "pitch": 0}})";
  const Session old = sessionFromJson(v1, "old.json");
  EXPECT_TRUE(old.poses.poses().empty());
  EXPECT_TRUE(old.timeline.keys.empty());
}

// A session whose range is 1..48 opens with the frame cursor at 1 (before, it stayed at whatever frame the editor
// was on, 0 after a start: the timeline read "frame 0" outside the session's range).
TEST(EditorPoseKeys, ASessionOpensWithTheFrameCursorAtTheStartOfItsRange) {
  AppState state;
  loadDemo(state);
  keyCurrentPose(state);
  Session session = makeSession(state);
  session.timeline.firstFrame = 1;
  session.timeline.lastFrame = 48;
  state.animation.frame = 30;
  state.animation.playing = true;
  applySession(state, session);
  EXPECT_EQ(state.animation.frame, 1.0);
  EXPECT_FALSE(state.animation.playing);
}

// Issue 24, row 11: Reset pose, then another frame. The timeline's cage replaces the unkeyed reset pose, as in
// Blender, but as an undo step that says so: Ctrl+Z gives the reset pose back (before, the frame change recorded
// nothing and undo removed the Reset pose itself). Scrubbing over the timeline's own cages records nothing.
TEST(EditorPoseKeys, ChangingTheFrameAfterResetPoseIsAStepThatUndoes) {
  AppState state;
  loadDemo(state);
  const Eigen::MatrixXd rest = state.document.pose;
  state.animation.timeline.interpolation = Interpolation::Linear;
  Eigen::MatrixXd a = rest, b = rest;
  a.col(0).array() += 0.3;
  b.col(1).array() += 0.6;
  setPose(state, a);
  keyCurrentPose(state);  // frame 0
  setPose(state, b);
  state.animation.frame = 10;
  keyCurrentPose(state);
  const std::size_t keyed = state.document.history.size();
  scrubTo(state, 4);  // the timeline's cage at frame 10 was shown: nothing unkeyed
  scrubTo(state, 10);
  EXPECT_EQ(state.document.history.size(), keyed);
  EXPECT_EQ(state.document.pose, b);

  resetPose(state);
  ASSERT_EQ(state.document.pose, rest);
  scrubTo(state, 5);
  EXPECT_LE((state.document.pose - 0.5 * (a + b)).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_EQ(state.document.history.step(state.document.history.cursor()).name, "Frame 5");
  EXPECT_NE(state.status.message.find("unkeyed pose was replaced"), std::string::npos) << state.status.message;
  undo(state);
  EXPECT_EQ(state.document.pose, rest) << "undo did not give the reset pose back";
  EXPECT_EQ(state.document.history.step(state.document.history.cursor()).name, "Reset pose");
}

// Issue 24, row 11: Key pose at several frames with one cage stores that cage once; a new cage a new pose.
TEST(EditorPoseKeys, KeyingOneCageAtSeveralFramesStoresItOnce) {
  AppState state;
  loadDemo(state);
  storeCurrentPose(state, "rest");
  for (double frame : {0.0, 12.0, 24.0}) {
    state.animation.frame = frame;
    keyCurrentPose(state);
  }
  ASSERT_EQ(state.animation.poses.poses().size(), 1u);
  ASSERT_EQ(state.animation.timeline.keys.size(), 3u);
  for (const Keyframe& key : state.animation.timeline.keys) EXPECT_EQ(key.pose, "rest");
  Eigen::MatrixXd moved = state.document.pose;
  moved.row(0) += Eigen::RowVector3d(0.1, 0, 0);
  setPose(state, moved);
  state.animation.frame = 36;
  keyCurrentPose(state);
  ASSERT_EQ(state.animation.poses.poses().size(), 2u);
  EXPECT_EQ(state.animation.poses.find(state.animation.timeline.keys.back().pose)->vertices, moved);
}

// The 3D demo's outcome, with its cage or with another numbering of it (vertices 0 and 1 swapped: the same shape
// and size, but a pose of the first would move the wrong corners).
PrecomputeOutcome demoOutcome(const std::string& name, bool renumbered) {
  Scene scene = makeDemoScene(3);
  scene.name = name;
  if (renumbered) {
    Cage& cage = scene.restCage;
    cage.vertices.row(0).swap(cage.vertices.row(1));
    for (Eigen::Index k = 0; k < cage.faces.size(); ++k) {
      int& v = cage.faces.data()[k];
      v = v == 0 ? 1 : v == 1 ? 0 : v;
    }
  }
  PrecomputeOutcome outcome;
  outcome.scene = std::make_shared<const Scene>(scene);
  return outcome;
}

// Issue 24, row 2: the bunny's poses and keys leaked into the cactus. Opening another scene keeps the poses only on
// a cage of the same topology; the dropped ones (and their keys) are named in the status bar, and the opened state
// (history step 0, what Save session writes) has none of them.
TEST(EditorPoseKeys, OpeningAnotherSceneDropsThePosesThatDoNotFitItsCage) {
  AppState state;
  installOutcome(state, demoOutcome("first", false));
  storeCurrentPose(state, "rest");
  Eigen::MatrixXd moved = state.document.pose;
  moved.col(2).array() += 0.2;
  setPose(state, moved);
  state.animation.frame = 24;
  keyCurrentPose(state);
  ASSERT_EQ(state.animation.poses.poses().size(), 2u);

  installOutcome(state, demoOutcome("same cage, another mesh", false));  // same topology: kept
  EXPECT_EQ(state.animation.poses.poses().size(), 2u);
  EXPECT_EQ(state.animation.timeline.keys.size(), 1u);

  PrecomputeOutcome demo2d;
  demo2d.scene = std::make_shared<const Scene>(makeDemoScene(2));
  installOutcome(state, demo2d);  // 10 vertices in 2D: no pose fits
  EXPECT_TRUE(state.animation.poses.poses().empty());
  EXPECT_TRUE(state.animation.timeline.keys.empty());
  EXPECT_NE(state.status.message.find("dropped 2 poses and 1 key"), std::string::npos) << state.status.message;
  EXPECT_FALSE(state.document.history.canUndo())
      << "the open is the history's first step, with the library as filtered";
  EXPECT_TRUE(makeSession(state).poses.poses().empty());
  EXPECT_FALSE(hasUnsavedChanges(state));

  installOutcome(state, demoOutcome("first", false));
  storeCurrentPose(state, "rest");
  installOutcome(state, demoOutcome("20 vertices, other faces", true));  // same size, another cage: dropped
  EXPECT_TRUE(state.animation.poses.poses().empty());
  EXPECT_NE(state.status.message.find("another topology"), std::string::npos) << state.status.message;
}

// A session brings its own library: its poses are kept when they have its cage's shape, a pose of another size is
// dropped with the notice (a hand-edited or mismatched session).
TEST(EditorPoseKeys, ASessionsPosesAreKeptWhenTheyFitItsCage) {
  AppState state;
  installOutcome(state, demoOutcome("before", false));
  state.animation.poses.store("fits", makeDemoScene(3).restCage.vertices);
  state.animation.poses.store("too small", Eigen::MatrixXd::Zero(10, 3));
  state.jobs.load.emplace().documentPath = "session.json";  // what loadSessionFile sets while the session's scene loads
  installOutcome(state, demoOutcome("session scene", true));
  ASSERT_EQ(state.animation.poses.poses().size(), 1u);
  EXPECT_EQ(state.animation.poses.poses()[0].name, "fits");
  EXPECT_NE(state.status.message.find("dropped 1 pose and 0 keys"), std::string::npos) << state.status.message;
}

}  // namespace

namespace {

// File > Export animation without a window: the frame loop's hooks run one timeline frame per call; the GLB
// written must hold the same frames as the core writer's `deformTimelineFrames` (base = frame 0, one target per
// later frame), the pose is restored, and Cancel leaves nothing.
class EditorAnimationExport : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ofstream(folder / "cage.obj")
        << "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\n"
           "v -1 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    std::ofstream(folder / "mesh.obj")
        << "v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0 0.5 0.3\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 -0.5 1\nf 1/1/1 2/2/1 3/3/1\n";
    requestSceneFiles(state, (folder / "mesh.obj").string(), (folder / "cage.obj").string());
    std::optional<PrecomputeOutcome> out = waitForOutcome(state.jobs.precompute);
    ASSERT_TRUE(out.has_value());
    installOutcome(state, std::move(*out));
    ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
    state.animation.timeline.firstFrame = 0;
    state.animation.timeline.lastFrame = 4;
    state.animation.frame = 0;
    keyCurrentPose(state);
    Eigen::MatrixXd moved = state.document.pose;
    moved.row(6) += Eigen::RowVector3d(0.3, 0.2, 0.1);
    setPose(state, moved);
    state.animation.frame = 4;
    keyCurrentPose(state);
    posed = state.document.pose;
  }
  // Runs the hooks the way the frame loop does until the job ends (or `frames` editor frames passed).
  void runFrames(int frames) {
    for (int k = 0; k < frames && state.animation.exportJob; ++k) {
      showNextExportFrame(state);
      updateDeformation(state);
      captureExportFrame(state, 0, 0);
    }
  }

  const test::ScratchFolder scratch;  // removed after `state` has ended its jobs
  const std::filesystem::path folder = scratch.path();
  AppState state;
  Eigen::MatrixXd posed;
};

TEST_F(EditorAnimationExport, ObjSequenceRunsOnTheWorkerAndHoldsTheTimelineFrames) {
  startAnimationExport(state, AnimationExportJob::Kind::ObjSequence, (folder / "seq").string());
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  EXPECT_FALSE(state.animation.exportJob.has_value()) << "no frame-loop job: the worker does it";
  waitForOutcome(state.jobs.exporter);
  EXPECT_EQ(state.jobs.exporter.progress(), 1.0);
  EXPECT_EQ(state.document.pose, posed) << "the pose is never touched";
  const std::vector<Eigen::MatrixXd> expected = deformTimelineFrames(
      *state.model.deformers.at(state.document.method), state.model.scene->restCage, state.animation.timeline,
      state.animation.poses, state.document.params, state.model.scene->document->geometry.vertices, 3, 0, 4);
  for (int f = 0; f <= 4; ++f) {
    const std::string name = (folder / "seq" / ("mesh_000" + std::to_string(f) + ".obj")).string();
    const PolygonMesh frame = loadMesh(name);
    EXPECT_LE((frame.vertices - expected[static_cast<size_t>(f)]).cwiseAbs().maxCoeff(), 1e-12) << name;
  }
}

// The folder's entries other than the inputs.
std::vector<std::string> leftOver(const std::filesystem::path& folder) {
  std::vector<std::string> left;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name != "cage.obj" && name != "mesh.obj") left.push_back(name);
  }
  return left;
}

// Runs an export job with a progress callback that says stop at its k-th report, for k = 1, 2, ... until the job
// completes: every cancelled run throws Cancelled and leaves neither the output nor a temporary file. Returns how
// many reports the job makes (the cancel points tested).
int cancelAtEveryReport(const std::filesystem::path& folder, const std::function<ExportWorker::Job()>& makeJob,
                        const std::string& out) {
  for (int k = 1; k < 1000; ++k) {
    const ExportWorker::Job job = makeJob();
    int reports = 0;
    try {
      job([&](double) { return ++reports < k; });
    } catch (const Cancelled&) {
      EXPECT_TRUE(leftOver(folder).empty()) << "cancelled at report " << k << ": " << leftOver(folder).front();
      continue;
    }
    EXPECT_TRUE(std::filesystem::exists(out)) << "completed at k = " << k;
    std::error_code ignored;
    std::filesystem::remove_all(out, ignored);
    return k - 1;
  }
  ADD_FAILURE() << "the job never completed";
  return 0;
}

TEST_F(EditorAnimationExport, CancelAtAnyPointLeavesNoFileAndNoTemporaryFile) {
  const std::string glb = (folder / "anim.glb").string(), seq = (folder / "seq").string();
  EXPECT_GE(cancelAtEveryReport(
                folder, [&] { return makeAnimationExportJob(state, AnimationExportJob::Kind::Glb, glb); }, glb),
            6)
      << "each of the 5 frames, then the write";
  EXPECT_GE(cancelAtEveryReport(
                folder, [&] { return makeAnimationExportJob(state, AnimationExportJob::Kind::ObjSequence, seq); }, seq),
            10)
      << "each frame deformed, then each file written (the temporary folder holds some of them)";
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  EXPECT_EQ(state.document.pose, posed);
}

TEST_F(EditorAnimationExport, MeshExportRunsOnTheWorkerAndCancelLeavesNothing) {
  const std::string out = (folder / "deformed.obj").string();
  ASSERT_TRUE(exportDeformedMesh(state, out));
  while (state.jobs.exporter.busy())
    std::this_thread::sleep_for(std::chrono::milliseconds(1));  // as the frame loop polls
  pollExport(state);
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  EXPECT_NE(state.status.message.find("exported the deformed mesh"), std::string::npos) << state.status.message;
  EXPECT_LE((loadMesh(out).vertices - displayedPoints(state, 0)).cwiseAbs().maxCoeff(), 1e-12);
  std::filesystem::remove(out);
  EXPECT_GE(cancelAtEveryReport(
                folder, [&] { return makeMeshExportJob(state, out); }, out),
            1);

  // Through the worker: one export at a time, and the real job held until cancel() was called ends cancelled.
  const ExportWorker::Job job = makeMeshExportJob(state, out);
  std::atomic<bool> release{false};
  ASSERT_TRUE(state.jobs.exporter.start(out, "", [&](const ProgressCallback& progress) {
    while (!release) std::this_thread::yield();
    return job(progress);
  }));
  EXPECT_FALSE(exportDeformedMesh(state, out)) << "one export at a time";
  ASSERT_EQ(state.status.errors.size(), 1u);
  EXPECT_NE(state.status.errors[0].find("another export is running"), std::string::npos) << state.status.errors[0];
  state.status.errors.clear();
  state.jobs.exporter.cancel();
  release = true;
  const std::optional<ExportOutcome> outcome = waitForOutcome(state.jobs.exporter);
  ASSERT_TRUE(outcome.has_value());
  EXPECT_TRUE(outcome->cancelled);
  EXPECT_TRUE(leftOver(folder).empty());
}

// The `vn` records of an exported OBJ.
Eigen::MatrixXd exportedNormals(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return parseObjDocument(text.str(), path).normals;
}

// The normals J carries at the editor's current pose, from gradients integrated here (no cache).
Eigen::MatrixXd normalsFromFreshGradients(const AppState& state) {
  const CageDeformer& deformer = *state.model.deformers.at(state.document.method);
  const Scene& scene = *state.model.scene;
  return transformNormals(*scene.document, deformer.deform(state.document.pose, state.document.params),
                          DeformationGradients(deformer, scene.meshVertices), state.document.pose,
                          state.document.params)
      .normals;
}

// Issue 27: the exports take the gradients kept with the coordinates (CageDeformer::gradients): two mesh exports and
// an OBJ sequence at other poses integrate them once, and a new rest cage (a new deformer) integrates its own,
// whose normals are the new cage's.
TEST_F(EditorAnimationExport, ExportsReuseTheGradientsKeptWithTheCoordinates) {
  const std::string out = (folder / "deformed.obj").string();
  const std::shared_ptr<const CageDeformer> deformer = state.model.deformers.at(state.document.method);
  EXPECT_EQ(deformer->gradientIntegrations(), 0) << "lazy: no view needed them yet";
  makeMeshExportJob(state, out)(noProgress);
  EXPECT_LE((exportedNormals(out) - normalsFromFreshGradients(state)).cwiseAbs().maxCoeff(), 1e-12);
  Eigen::MatrixXd moved = state.document.pose;
  moved.row(1) += Eigen::RowVector3d(-0.2, 0.1, 0.3);
  setPose(state, moved);
  updateDeformation(state);
  makeMeshExportJob(state, out)(noProgress);
  EXPECT_LE((exportedNormals(out) - normalsFromFreshGradients(state)).cwiseAbs().maxCoeff(), 1e-12);
  makeAnimationExportJob(state, AnimationExportJob::Kind::ObjSequence, (folder / "seq").string())(noProgress);
  EXPECT_EQ(deformer->gradientIntegrations(), 1) << "two mesh exports and a sequence at other poses";

  const Eigen::MatrixXd before = exportedNormals(out);
  std::ofstream(folder / "wide.obj")  // the cage stretched along x: another map, other normals
      << "v -1.6 -1 -1\nv 1.6 -1 -1\nv 1.6 1 -1\nv -1.6 1 -1\nv -1.6 -1 1\nv 1.6 -1 1\nv 1.6 1 1\n"
         "v -1.6 1 1\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  requestSceneFiles(state, (folder / "mesh.obj").string(), (folder / "wide.obj").string());
  std::optional<PrecomputeOutcome> outcome = waitForOutcome(state.jobs.precompute);
  ASSERT_TRUE(outcome.has_value());
  installOutcome(state, std::move(*outcome));
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  const std::shared_ptr<const CageDeformer> wide = state.model.deformers.at(state.document.method);
  ASSERT_NE(wide, deformer);
  setPose(state, moved);
  updateDeformation(state);
  makeMeshExportJob(state, out)(noProgress);
  EXPECT_EQ(wide->gradientIntegrations(), 1) << "the new cage's gradients, integrated for it";
  EXPECT_LE((exportedNormals(out) - normalsFromFreshGradients(state)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_GT((exportedNormals(out) - before).cwiseAbs().maxCoeff(), 1e-3) << "not the old cage's normals";
}

}  // namespace
