// File > Make cage... (cage_maker.h): the worker's state machine with a generator the test controls (a newer
// request supersedes the running one, which sees its progress callback refuse and never shows its result; Stop;
// errors), a real generation on the 3D demo checked by the exact enclosure test, Accept as one undo step that
// undo reverts to the old cage, pose and pose library bitwise, with the unsaved-changes state following, and the made
// cage kept by the session file and the autosave (it has no file of its own).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <thread>

#include "base/errors.h"
#include "core/test_shapes.h"
#include "editor_test_support.h"
#include "generation/cage_enclosure.h"
#include "io/obj_io.h"
#include "jobs/cage_maker.h"
#include "methods/method_descriptors.h"
#include "model/app_state.h"
#include "model/autosave.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

// A generator whose runs the test steers: each run reports progress until `release` is set or the callback refuses,
// then returns an icosphere (levels 1) around the mesh whose radius is options.maxFaces (so results tell which
// request they belong to), or throws Cancelled.
struct SteeredGenerator {
  std::atomic<bool> release{false};
  std::atomic<int> started{0}, refused{0}, finished{0};

  CageGenerator generator() {
    return [this](const Eigen::MatrixXd& vertices, const Eigen::MatrixXi&, const CageGenerationOptions& options,
                  const std::string&, const ProgressCallback& progress) {
      ++started;
      for (;;) {
        if (!progress(0.5)) {
          ++refused;
          ++finished;
          throw Cancelled();
        }
        if (release) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
      GeneratedCage generated;
      generated.cage = test::makeIcosphere(1);
      const Eigen::RowVector3d center = 0.5 * (vertices.colwise().minCoeff() + vertices.colwise().maxCoeff());
      generated.cage.vertices = (generated.cage.vertices.rowwise().normalized() * options.maxFaces).rowwise() + center;
      ++finished;
      return generated;
    };
  }
};

void waitUntil(const std::atomic<int>& counter, int value) {
  for (int i = 0; i < 20000 && counter.load() < value; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ASSERT_GE(counter.load(), value) << "the worker did not get there in 20 s";
}

// A folder under the test temp dir, removed at the end.
class TempFolder {
 public:
  explicit TempFolder(const std::string& name) : root_(std::filesystem::path(::testing::TempDir()) / name) {
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(root_);
  }
  ~TempFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(root_, ignored);
  }
  std::string path(const std::string& name) const { return (root_ / name).string(); }

 private:
  std::filesystem::path root_;
};

class CageMakerTest : public ::testing::Test {
 protected:
  void SetUp() override { openDemoScene(state); }
  AppState state;
};

}  // namespace

TEST_F(CageMakerTest, ANewRequestSupersedesTheRunningOne) {
  SteeredGenerator steered;
  state.jobs.cageMaker.setGenerator(steered.generator());
  openCageMaker(state, 30);
  waitUntil(steered.started, 1);
  CageGenerationOptions options = state.jobs.cageMaker.options();
  options.maxFaces = 40;
  state.jobs.cageMaker.request(options);  // the slider moved
  EXPECT_EQ(state.jobs.cageMaker.status(), CageMaker::Status::Generating);
  waitUntil(steered.refused, 1);  // the first run was asked to stop
  waitUntil(steered.started, 2);
  steered.release = true;
  waitThenPoll(state.jobs.cageMaker);
  ASSERT_EQ(state.jobs.cageMaker.status(), CageMaker::Status::Ready);
  ASSERT_TRUE(state.jobs.cageMaker.candidate());
  EXPECT_EQ(state.jobs.cageMaker.candidate()->options.maxFaces, 40);
  EXPECT_NEAR(state.jobs.cageMaker.candidate()->generated.cage.vertices.row(0).norm(), 40.0, 5.0);  // the second's cage
  EXPECT_EQ(steered.started.load(), 2);
}

TEST_F(CageMakerTest, StopShowsNothingAndCancelLeavesTheSceneUntouched) {
  const Document before = currentDocument(state);
  const std::shared_ptr<const Scene> scene = state.model.scene;
  const std::size_t cursor = state.document.history.cursor();
  SteeredGenerator steered;
  state.jobs.cageMaker.setGenerator(steered.generator());
  openCageMaker(state, 30);
  waitUntil(steered.started, 1);
  state.jobs.cageMaker.cancel();  // Stop
  EXPECT_EQ(state.jobs.cageMaker.status(), CageMaker::Status::Cancelled);
  waitUntil(steered.refused, 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the worker stores its (cancelled) result
  state.jobs.cageMaker.poll();
  EXPECT_EQ(state.jobs.cageMaker.status(), CageMaker::Status::Cancelled);
  EXPECT_FALSE(state.jobs.cageMaker.candidate());
  EXPECT_FALSE(acceptGeneratedCage(state));  // nothing to accept

  steered.release = true;
  state.jobs.cageMaker.request(state.jobs.cageMaker.options());  // generate again, then Cancel the dialog
  waitThenPoll(state.jobs.cageMaker);
  ASSERT_TRUE(state.jobs.cageMaker.candidate());
  state.jobs.cageMaker.close();
  EXPECT_FALSE(state.jobs.cageMaker.isOpen());
  EXPECT_FALSE(state.jobs.cageMaker.candidate());
  EXPECT_EQ(state.model.scene, scene);
  EXPECT_EQ(currentDocument(state), before);
  EXPECT_EQ(state.document.history.cursor(), cursor);
  EXPECT_FALSE(hasUnsavedChanges(state));
}

TEST_F(CageMakerTest, AGenerationErrorIsShown) {
  state.jobs.cageMaker.setGenerator([](const Eigen::MatrixXd&, const Eigen::MatrixXi&, const CageGenerationOptions&,
                                       const std::string& source, const ProgressCallback&) -> GeneratedCage {
    throw InputError(source, -1, "no valid cage", "ask for more faces");
  });
  openCageMaker(state, 12);
  waitThenPoll(state.jobs.cageMaker);
  EXPECT_EQ(state.jobs.cageMaker.status(), CageMaker::Status::Failed);
  EXPECT_NE(state.jobs.cageMaker.error().find("no valid cage"), std::string::npos) << state.jobs.cageMaker.error();
  EXPECT_FALSE(state.jobs.cageMaker.candidate());
}

TEST_F(CageMakerTest, TwoDimensionalScenesAreRefused) {
  openDemoScene(state, 2);
  openCageMaker(state, 40);
  EXPECT_FALSE(state.jobs.cageMaker.isOpen());
  ASSERT_EQ(state.status.errors.size(), 1u);
  EXPECT_NE(state.status.errors[0].find("3D"), std::string::npos) << state.status.errors[0];
}

// The real generator, then Accept: the exact enclosure check passes on the candidate, the scene deforms with it at
// rest onto the mesh, and undo / redo swap the whole cage back and forth as one step.
TEST_F(CageMakerTest, AcceptIsOneUndoStepThatUndoRevertsExactly) {
  // A posed, saved document with a pose in the library: what undo must bring back.
  Eigen::MatrixXd posed = state.document.pose;
  posed(0, 1) += 0.25;
  setPose(state, posed);
  ASSERT_TRUE(commitEdit(state, "Grab"));
  state.animation.poses.store("bent", posed);
  ASSERT_TRUE(commitEdit(state, "Store pose"));
  state.document.history.markSaved();
  const Document before = currentDocument(state);
  const Cage oldCage = state.model.scene->restCage;

  openCageMaker(state, 40);
  waitThenPoll(state.jobs.cageMaker);
  ASSERT_EQ(state.jobs.cageMaker.status(), CageMaker::Status::Ready) << state.jobs.cageMaker.error();
  const Cage generated = state.jobs.cageMaker.candidate()->generated.cage;
  EXPECT_LE(generated.numFaces(), 40);
  const EnclosureReport enclosure =
      checkEnclosure(generated, state.model.scene->meshVertices, state.model.scene->meshTriangles);  // exact predicates
  EXPECT_TRUE(enclosure.encloses()) << enclosure.outsideVertices.size() << " outside, " << enclosure.crossedFaces.size()
                                    << " crossed faces";

  ASSERT_TRUE(acceptGeneratedCage(state));
  EXPECT_FALSE(state.jobs.cageMaker.isOpen());
  EXPECT_TRUE(sameCage(state.model.scene->restCage, generated));
  EXPECT_EQ(state.document.pose, generated.vertices);  // at rest
  EXPECT_TRUE(state.animation.poses.poses().empty());
  EXPECT_EQ(state.document.history.step(state.document.history.cursor()).name, "Make cage");
  EXPECT_TRUE(hasUnsavedChanges(state));
  const Document after = currentDocument(state);

  // The new cage deforms right away: its rest pose reproduces the mesh (Somigliana, to its integration error).
  installNextOutcome(state);
  ASSERT_TRUE(hasDeformer(state, methods::somigliana()));
  updateDeformation(state);
  const Eigen::MatrixXd& shown = displayedPoints(state, 0);
  ASSERT_EQ(shown.rows(), state.model.scene->meshVertices.rows());
  EXPECT_LT((shown - state.model.scene->meshVertices).cwiseAbs().maxCoeff(), 1e-6);

  undo(state);
  EXPECT_EQ(state.status.message, "undo Make cage");
  EXPECT_TRUE(sameCage(state.model.scene->restCage, oldCage));
  EXPECT_EQ(currentDocument(state), before);  // pose, library and cage, bitwise
  EXPECT_EQ(state.input.selection.flags().size(), static_cast<std::size_t>(oldCage.numVertices()));
  EXPECT_FALSE(hasUnsavedChanges(state));
  redo(state);
  EXPECT_EQ(currentDocument(state), after);
  EXPECT_TRUE(hasUnsavedChanges(state));
}

// The lost-work bug: a made cage has no file, so the session holds it inline. A fresh editor that opens the saved
// session, or restores the autosave of a crashed run, gets this very cage (bitwise) and the pose on it, where it used
// to make a new default cage for the mesh.
TEST_F(CageMakerTest, TheSessionAndTheAutosaveKeepTheMadeCageAndItsPose) {
  openCageMaker(state, 60);  // not the default 200: a regenerated default cage could not pass for it
  waitThenPoll(state.jobs.cageMaker);
  ASSERT_EQ(state.jobs.cageMaker.status(), CageMaker::Status::Ready) << state.jobs.cageMaker.error();
  ASSERT_TRUE(acceptGeneratedCage(state));
  installNextOutcome(state);  // its deformers
  const Cage made = state.model.scene->restCage;
  ASSERT_LE(made.numFaces(), 60);
  ASSERT_FALSE(sameCage(made, makeDemoScene(3).restCage));
  Eigen::MatrixXd posed = state.document.pose;
  posed.row(0) += Eigen::RowVector3d(0.1, 1.0 / 3.0, -0.2);
  posed.row(made.numVertices() - 1) *= 1.0 + 1e-15;  // the last bits count
  setPose(state, posed);
  ASSERT_TRUE(commitEdit(state, "Grab"));

  TempFolder folder("somicage_made_cage_session");
  const std::string sessionPath = folder.path("made.json");
  ASSERT_TRUE(saveSessionFile(state, sessionPath)) << state.status.errors.front();
  AppState reopened;
  loadSessionFile(reopened, sessionPath);
  finishSessionRead(reopened);
  ASSERT_TRUE(reopened.status.errors.empty()) << reopened.status.errors.front();
  installNextOutcome(reopened);
  ASSERT_TRUE(reopened.status.errors.empty()) << reopened.status.errors.front();
  ASSERT_TRUE(reopened.model.scene);
  EXPECT_TRUE(reopened.model.scene->cagePath.empty());
  EXPECT_TRUE(sameCage(reopened.model.scene->restCage, made)) << reopened.model.scene->restCage.numFaces() << " faces";
  EXPECT_EQ(reopened.document.pose, posed);
  EXPECT_FALSE(hasUnsavedChanges(reopened));
  EXPECT_EQ(reopened.document.path, sessionPath);

  // A crash: the autosave holds the same, and restoring it in a new editor gives it back (unsaved, as it exists
  // nowhere else).
  const AutosavePaths paths = autosavePaths(folder.path("config").c_str(), nullptr);
  {
    Autosave autosave(paths, 1.0);
    autosave.begin();
    autosave.tick(makeSession(state), 0.0);
    ASSERT_TRUE(autosave.tick(makeSession(state), 1.0));
  }  // no finish()
  const AutosaveLeftover leftover = Autosave(paths, 1.0).begin();
  ASSERT_TRUE(leftover.session.has_value()) << leftover.error;
  AppState restored;
  restored.files.restoreOffer = leftover.session;
  acceptRestoreOffer(restored);
  installNextOutcome(restored);
  ASSERT_TRUE(restored.status.errors.empty()) << restored.status.errors.front();
  ASSERT_TRUE(restored.model.scene);
  EXPECT_TRUE(sameCage(restored.model.scene->restCage, made));
  EXPECT_EQ(restored.document.pose, posed);
  EXPECT_TRUE(hasUnsavedChanges(restored));
}

// A scene whose cage comes from a file: Make cage drops the file (the session then holds the cage inline), and undo
// brings the file back with the cage, so the session names it again instead of copying it.
TEST_F(CageMakerTest, UndoingMakeCageGivesTheCageItsFileBack) {
  TempFolder folder("somicage_make_cage_file");
  const std::string meshPath = folder.path("bar.obj"), cagePath = folder.path("bar_cage.obj");
  PolygonMesh triangles;
  for (Eigen::Index f = 0; f < state.model.scene->meshTriangles.rows(); ++f) {
    const Eigen::RowVector3i t = state.model.scene->meshTriangles.row(f);
    triangles.faces.push_back({t[0], t[1], t[2]});
  }
  saveObj(meshPath, state.model.scene->meshVertices, triangles);
  saveObj(cagePath, state.model.scene->restCage.vertices, cageTopology(state.model.scene->restCage));
  requestSceneFiles(state, meshPath, cagePath);
  installNextOutcome(state);
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  ASSERT_EQ(state.model.scene->cagePath, cagePath);
  EXPECT_EQ(makeSession(state).cagePath, cagePath);
  EXPECT_EQ(makeSession(state).restCage.numVertices(), 0) << "a cage with a file is named, not copied";

  SteeredGenerator steered;
  steered.release = true;
  state.jobs.cageMaker.setGenerator(steered.generator());
  openCageMaker(state, 20);
  waitThenPoll(state.jobs.cageMaker);
  ASSERT_TRUE(acceptGeneratedCage(state));
  const Session afterMake = makeSession(state);
  EXPECT_TRUE(afterMake.cagePath.empty());
  EXPECT_TRUE(sameCage(afterMake.restCage, state.model.scene->restCage));

  undo(state);
  EXPECT_EQ(state.model.scene->cagePath, cagePath);
  EXPECT_EQ(makeSession(state).restCage.numVertices(), 0);
  redo(state);
  EXPECT_TRUE(state.model.scene->cagePath.empty());
}
