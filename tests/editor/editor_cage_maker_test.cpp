// File > Make cage... (cage_maker.h): the worker's state machine with a generator the test controls (a newer
// request supersedes the running one, which sees its progress callback refuse and never shows its result; Stop;
// errors), a real generation on the 3D demo checked by the exact enclosure test, and Accept as one undo step that
// undo reverts to the old cage, pose and pose library bitwise, with the unsaved-changes state following.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "app_state.h"
#include "cage_enclosure.h"
#include "cage_maker.h"
#include "core/test_shapes.h"
#include "errors.h"
#include "methods/method_descriptors.h"

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

class CageMakerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    requestDemo(state, 3);
    std::optional<PrecomputeOutcome> out = state.worker.wait();
    ASSERT_TRUE(out.has_value());
    installOutcome(state, std::move(*out));
    ASSERT_TRUE(state.scene);
  }
  AppState state;
};

}  // namespace

TEST_F(CageMakerTest, ANewRequestSupersedesTheRunningOne) {
  SteeredGenerator steered;
  state.cageMaker.setGenerator(steered.generator());
  openCageMaker(state, 30);
  waitUntil(steered.started, 1);
  CageGenerationOptions options = state.cageMaker.options();
  options.maxFaces = 40;
  state.cageMaker.request(options);  // the slider moved
  EXPECT_EQ(state.cageMaker.status(), CageMaker::Status::Generating);
  waitUntil(steered.refused, 1);  // the first run was asked to stop
  waitUntil(steered.started, 2);
  steered.release = true;
  state.cageMaker.wait();
  ASSERT_EQ(state.cageMaker.status(), CageMaker::Status::Ready);
  ASSERT_TRUE(state.cageMaker.candidate());
  EXPECT_EQ(state.cageMaker.candidate()->options.maxFaces, 40);
  EXPECT_NEAR(state.cageMaker.candidate()->generated.cage.vertices.row(0).norm(), 40.0, 5.0);  // the second's cage
  EXPECT_EQ(steered.started.load(), 2);
}

TEST_F(CageMakerTest, StopShowsNothingAndCancelLeavesTheSceneUntouched) {
  const Document before = currentDocument(state);
  const std::shared_ptr<const Scene> scene = state.scene;
  const std::size_t cursor = state.history.cursor();
  SteeredGenerator steered;
  state.cageMaker.setGenerator(steered.generator());
  openCageMaker(state, 30);
  waitUntil(steered.started, 1);
  state.cageMaker.cancel();  // Stop
  EXPECT_EQ(state.cageMaker.status(), CageMaker::Status::Cancelled);
  waitUntil(steered.refused, 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the worker stores its (cancelled) result
  state.cageMaker.poll();
  EXPECT_EQ(state.cageMaker.status(), CageMaker::Status::Cancelled);
  EXPECT_FALSE(state.cageMaker.candidate());
  EXPECT_FALSE(acceptGeneratedCage(state));  // nothing to accept

  steered.release = true;
  state.cageMaker.request(state.cageMaker.options());  // generate again, then Cancel the dialog
  state.cageMaker.wait();
  ASSERT_TRUE(state.cageMaker.candidate());
  state.cageMaker.close();
  EXPECT_FALSE(state.cageMaker.isOpen());
  EXPECT_FALSE(state.cageMaker.candidate());
  EXPECT_EQ(state.scene, scene);
  EXPECT_EQ(currentDocument(state), before);
  EXPECT_EQ(state.history.cursor(), cursor);
  EXPECT_FALSE(hasUnsavedChanges(state));
}

TEST_F(CageMakerTest, AGenerationErrorIsShown) {
  state.cageMaker.setGenerator([](const Eigen::MatrixXd&, const Eigen::MatrixXi&, const CageGenerationOptions&,
                                  const std::string& source, const ProgressCallback&) -> GeneratedCage {
    throw InputError(source, -1, "no valid cage", "ask for more faces");
  });
  openCageMaker(state, 12);
  state.cageMaker.wait();
  EXPECT_EQ(state.cageMaker.status(), CageMaker::Status::Failed);
  EXPECT_NE(state.cageMaker.error().find("no valid cage"), std::string::npos) << state.cageMaker.error();
  EXPECT_FALSE(state.cageMaker.candidate());
}

TEST_F(CageMakerTest, TwoDimensionalScenesAreRefused) {
  requestDemo(state, 2);
  std::optional<PrecomputeOutcome> out = state.worker.wait();
  ASSERT_TRUE(out.has_value());
  installOutcome(state, std::move(*out));
  openCageMaker(state, 40);
  EXPECT_FALSE(state.cageMaker.isOpen());
  ASSERT_EQ(state.errors.size(), 1u);
  EXPECT_NE(state.errors[0].find("3D"), std::string::npos) << state.errors[0];
}

// The real generator, then Accept: the exact enclosure check passes on the candidate, the scene deforms with it at
// rest onto the mesh, and undo / redo swap the whole cage back and forth as one step.
TEST_F(CageMakerTest, AcceptIsOneUndoStepThatUndoRevertsExactly) {
  // A posed, saved document with a pose in the library: what undo must bring back.
  Eigen::MatrixXd posed = state.pose;
  posed(0, 1) += 0.25;
  setPose(state, posed);
  ASSERT_TRUE(commitEdit(state, "Grab"));
  state.animation.poses.store("bent", posed);
  ASSERT_TRUE(commitEdit(state, "Store pose"));
  state.history.markSaved();
  const Document before = currentDocument(state);
  const Cage oldCage = state.scene->restCage;

  openCageMaker(state, 40);
  state.cageMaker.wait();
  ASSERT_EQ(state.cageMaker.status(), CageMaker::Status::Ready) << state.cageMaker.error();
  const Cage generated = state.cageMaker.candidate()->generated.cage;
  EXPECT_LE(generated.numFaces(), 40);
  const EnclosureReport enclosure =
      checkEnclosure(generated, state.scene->meshVertices, state.scene->meshTriangles);  // exact predicates
  EXPECT_TRUE(enclosure.encloses()) << enclosure.outsideVertices.size() << " outside, " << enclosure.crossedFaces.size()
                                    << " crossed faces";

  ASSERT_TRUE(acceptGeneratedCage(state));
  EXPECT_FALSE(state.cageMaker.isOpen());
  EXPECT_TRUE(sameCage(state.scene->restCage, generated));
  EXPECT_EQ(state.pose, generated.vertices);  // at rest
  EXPECT_TRUE(state.animation.poses.poses().empty());
  EXPECT_EQ(state.history.step(state.history.cursor()).name, "Make cage");
  EXPECT_TRUE(hasUnsavedChanges(state));
  const Document after = currentDocument(state);

  // The new cage deforms right away: its rest pose reproduces the mesh (Somigliana, to its integration error).
  std::optional<PrecomputeOutcome> out = state.worker.wait();
  ASSERT_TRUE(out.has_value());
  installOutcome(state, std::move(*out));
  ASSERT_TRUE(hasDeformer(state, methods::somigliana()));
  updateDeformation(state);
  const Eigen::MatrixXd& shown = displayedPoints(state, methods::somigliana());
  ASSERT_EQ(shown.rows(), state.scene->meshVertices.rows());
  EXPECT_LT((shown - state.scene->meshVertices).cwiseAbs().maxCoeff(), 1e-6);

  undo(state);
  EXPECT_EQ(state.statusMessage, "undo Make cage");
  EXPECT_TRUE(sameCage(state.scene->restCage, oldCage));
  EXPECT_EQ(currentDocument(state), before);  // pose, library and cage, bitwise
  EXPECT_EQ(state.selection.flags().size(), static_cast<std::size_t>(oldCage.numVertices()));
  EXPECT_FALSE(hasUnsavedChanges(state));
  redo(state);
  EXPECT_EQ(currentDocument(state), after);
  EXPECT_TRUE(hasUnsavedChanges(state));
}
