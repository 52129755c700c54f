// Opening another scene (Open, a demo, Open Recent, a drop, a session of another scene) asks about unsaved changes
// before its load starts, and the open document stays editable while the scene loads on the worker. An edit, undo or
// redo made meanwhile is not replaced unasked when the scene arrives: the same question again (pollWorker), and the
// scene is shown only on Save / Don't save; Cancel drops it and keeps the document exactly.
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/scratch_folder.h"
#include "editor_test_support.h"
#include "job_waiting.h"
#include "model/app_state.h"
#include "open_over_edits.h"
#include "ui/unsaved_changes.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

// Opens another copy of the 2D demo ("demo (2D strip)") as Open does: asked first over unsaved changes (answered
// Don't save), then loaded on the worker. Returns the scene being loaded, held by nothing of the test.
std::weak_ptr<const Scene> startLoading(AppState& state) {
  auto scene = std::make_shared<const Scene>(makeDemoScene(2));
  const std::weak_ptr<const Scene> loading = scene;
  guardUnsaved(state, "open the 2D demo", [scene](AppState& s) { requestScene(s, scene); });
  scene.reset();
  if (state.document.unsaved.asking) answerUnsaved(state, UnsavedChoice::DontSave);
  EXPECT_TRUE(state.loadingScene());
  return loading;
}

// `meanwhile` while the scene loads: the load waits for cores the test holds until it returns.
std::weak_ptr<const Scene> loadWhile(AppState& state, const std::function<void(AppState&)>& meanwhile) {
  const HeldCores held;
  const std::weak_ptr<const Scene> loading = startLoading(state);
  meanwhile(state);
  return loading;
}

// Until the load's job has ended (its scene and deformers are there, untaken), then one frame: the frame that takes it.
void finishLoading(AppState& state) {
  waitUntilDone(state.jobs.precompute);
  frame(state);
}

// The loaded scene is shown, with its deformers, as the new document opened clean.
void expectShown(const AppState& state, const std::weak_ptr<const Scene>& loading) {
  ASSERT_FALSE(loading.expired());
  EXPECT_EQ(state.model.scene, loading.lock());
  EXPECT_FALSE(state.loadingScene());
  EXPECT_TRUE(hasDeformer(state, deformerKey(state.views().front())));
  EXPECT_FALSE(hasUnsavedChanges(state));
  EXPECT_EQ(state.document.history.size(), 1u);
}

// The load was dropped: nothing of it is left, and its scene is freed (once its job's thread has let go).
void expectDropped(AppState& state, const std::weak_ptr<const Scene>& loading, const Kept& kept) {
  EXPECT_FALSE(state.loadingScene());
  waitUntilDone(state.jobs.precompute);
  EXPECT_TRUE(waitUntil([&loading] { return loading.expired(); })) << "the loaded scene is still held";
  for (int f = 0; f < 3; ++f) frame(state);  // no outcome of it arrives later
  expectKept(state, kept);
}

}  // namespace

// (a) A change while the scene loads (an edit, an undo, an undo and its redo) asks again when the scene has arrived,
// whether the frame finds the loaded scene (shown before its deformers) or the finished precompute (it ended before a
// frame took its scene); nothing is shown before the answer. Don't save shows the scene; Cancel drops the load, frees
// its scene and keeps the scene, document, history and views exactly. Before, the loaded scene replaced them unasked.
TEST(EditorSceneOpen, AChangeWhileTheSceneLoadsAsksBeforeItIsShown) {
  for (const Meanwhile& change : changesMeanwhile()) {
    for (const bool precomputeFirst : {false, true}) {
      for (const UnsavedChoice answer : {UnsavedChoice::DontSave, UnsavedChoice::Cancel}) {
        SCOPED_TRACE(change.name + (precomputeFirst ? ", the precompute found first" : ", the loaded scene found") +
                     (answer == UnsavedChoice::Cancel ? ", Cancel" : ", Don't save"));
        AppState state;
        openEditedDemo(state);
        const std::weak_ptr<const Scene> loading = loadWhile(state, change.make);
        const Kept kept = keep(state);
        waitUntilDone(state.jobs.precompute);
        if (precomputeFirst) state.jobs.precompute.takeLoadedScene();  // as if no frame came before it ended
        frame(state);
        ASSERT_TRUE(state.document.unsaved.asking) << "the scene would replace the change unasked";
        EXPECT_EQ(state.document.unsaved.asking->what, "open demo (2D strip)");
        frame(state);  // it waits for the answer
        expectKept(state, kept);
        EXPECT_TRUE(state.loadingScene());
        answerUnsaved(state, answer);
        frame(state);
        EXPECT_FALSE(state.document.unsaved.asking);
        ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
        if (answer == UnsavedChoice::Cancel) {
          EXPECT_EQ(state.status.message, "cancelled: open demo (2D strip); the loaded scene was dropped");
          expectDropped(state, loading, kept);
        } else {
          expectShown(state, loading);
        }
      }
    }
  }
}

// (b) Without a change while the scene loads it is shown as soon as it has arrived, unasked: over a clean document,
// over an unsaved one whose user answered Don't save before the load (what was unsaved then was asked about), with a
// commit that changed nothing meanwhile; and after an edit that was saved meanwhile (it is on disk).
TEST(EditorSceneOpen, WithoutAChangeWhileTheSceneLoadsItIsShownUnasked) {
  const test::ScratchFolder dir;
  const std::string mine = dir / "mine.json";
  for (const Meanwhile& c : noChangeMeanwhile(mine)) {
    SCOPED_TRACE(c.name);
    AppState state;
    openDocumentFor(state, c);
    const std::weak_ptr<const Scene> loading = loadWhile(state, c.make);
    finishLoading(state);
    EXPECT_FALSE(state.document.unsaved.asking) << "asked again";
    frame(state);
    expectShown(state, loading);
  }
}

// (c) Save: the document with the edit made during the load is written first, then the scene is shown; a save that
// fails (the document's file is a folder) shows nothing and drops the load, as Cancel does, with the save's error.
TEST(EditorSceneOpen, SaveWritesTheEditThenShowsTheScene) {
  const test::ScratchFolder dir;
  for (const bool saves : {true, false}) {
    SCOPED_TRACE(saves ? "saved" : "the save fails");
    AppState state;
    openEditedDemo(state);
    const std::string mine = saves ? dir / "mine.json" : dir.path().string();
    ASSERT_TRUE(saveSessionFile(state, dir / "mine.json"));
    state.document.path = mine;
    const std::weak_ptr<const Scene> loading = loadWhile(state, [](AppState& s) { grab(s); });
    const Eigen::MatrixXd edited = state.document.pose;
    const Kept kept = keep(state);
    finishLoading(state);
    ASSERT_TRUE(state.document.unsaved.asking);
    answerUnsaved(state, UnsavedChoice::Save);
    frame(state);
    if (saves) {
      EXPECT_EQ(loadSession(mine).pose, edited) << "the edit made during the load is saved";
      ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
      expectShown(state, loading);
    } else {
      ASSERT_EQ(state.status.errors.size(), 1u);
      EXPECT_NE(state.status.message.find("the loaded scene was dropped"), std::string::npos) << state.status.message;
      expectDropped(state, loading, kept);
    }
  }
}

// (d) A session of another scene (the 3D demo's, with Green and nu = 0.25) whose scene loads while the document is
// edited: Cancel drops the scene and the session's settings with it, held in PendingLoad::session, none applied: the
// method, parameters, pose library, views, camera and file stay the open document's.
TEST(EditorSceneOpen, CancelOnASessionsSceneAppliesNothingOfTheSession) {
  const test::ScratchFolder dir;
  const std::string path = dir / "bar.json";
  {
    AppState bar;
    openDemoScene(bar, 3);
    Session session = makeSession(bar);
    session.method = parseMethod("green");
    session.params.nu = 0.25;
    session.camera.distance = 42.0;
    saveSession(path, session);
  }
  AppState state;
  openEditedDemo(state);
  guardUnsaved(state, "open session bar.json", [path](AppState& s) { loadSessionFile(s, path); });
  answerUnsaved(state, UnsavedChoice::DontSave);
  waitUntilDone(state.jobs.session);
  {
    const HeldCores held;
    frame(state);  // the session is read: its scene loads
    ASSERT_TRUE(state.loadingScene());
    grab(state);
  }
  const Kept kept = keep(state);
  const CameraState camera = state.view.camera.state();
  finishLoading(state);
  ASSERT_TRUE(state.document.unsaved.asking);
  EXPECT_EQ(state.document.unsaved.asking->what, "open session bar.json");
  answerUnsaved(state, UnsavedChoice::Cancel);
  frame(state);
  EXPECT_FALSE(state.loadingScene());
  expectKept(state, kept);
  EXPECT_EQ(methodName(state.document.method), "somigliana");
  ASSERT_EQ(state.animation.poses.poses().size(), 1u);
  EXPECT_EQ(state.animation.poses.poses()[0].name, "mine");
  EXPECT_EQ(state.view.camera.state().distance, camera.distance);
  EXPECT_EQ(state.document.path, "");
}

// (e) A loaded scene waits while another question is open (Ctrl+Q meanwhile: the quit question stays; Cancel, and the
// scene, unchanged since, comes unasked) and during a live edit: a handle moving the cage (G: once confirmed its edit
// asks; an Esc'd transform changes nothing, so the scene then comes unasked) and a widget held (nu: committed on
// release, asks). Before, the scene replaced the document under the user's hand.
TEST(EditorSceneOpen, ALoadedSceneWaitsForAnOpenQuestionAndAMovingHandle) {
  {
    SCOPED_TRACE("quit asked meanwhile");
    AppState state;
    openEditedDemo(state);
    const std::weak_ptr<const Scene> loading = loadWhile(state, [](AppState& s) { requestQuit(s); });
    const std::shared_ptr<const Scene> open = state.model.scene;
    finishLoading(state);
    ASSERT_TRUE(state.document.unsaved.asking);
    EXPECT_EQ(state.document.unsaved.asking->what, "quit");
    EXPECT_EQ(state.model.scene, open) << "shown while the quit question is open";
    answerUnsaved(state, UnsavedChoice::Cancel);
    frame(state);
    frame(state);
    EXPECT_FALSE(state.document.quitRequested);
    EXPECT_FALSE(state.document.unsaved.asking);
    expectShown(state, loading);
  }
  for (const bool confirmed : {true, false}) {
    SCOPED_TRACE(confirmed ? "G confirmed" : "G cancelled");
    AppState state;
    openEditedDemo(state);
    Eigen::MatrixXd original;
    const std::weak_ptr<const Scene> loading = loadWhile(state, [&original](AppState& s) { original = beginGrab(s); });
    const Eigen::MatrixXd moved = state.document.pose;
    const std::shared_ptr<const Scene> open = state.model.scene;
    finishLoading(state);
    frame(state);
    EXPECT_EQ(state.model.scene, open) << "shown while the handle moves";
    EXPECT_FALSE(state.document.unsaved.asking);
    EXPECT_EQ(state.document.pose, moved);
    endGrab(state, original, confirmed);
    frame(state);
    EXPECT_EQ(state.document.unsaved.asking.has_value(), confirmed);
    if (!confirmed) {
      frame(state);
      expectShown(state, loading);
    }
  }
  {
    SCOPED_TRACE("nu slider held");
    AppState state;
    openEditedDemo(state);
    loadWhile(state, holdNuSlider);
    const std::shared_ptr<const Scene> open = state.model.scene;
    finishLoading(state);
    frame(state);
    EXPECT_EQ(state.model.scene, open) << "shown while the slider is held";
    releaseNuSlider(state);
    frame(state);
    EXPECT_TRUE(state.document.unsaved.asking);
    EXPECT_EQ(state.model.scene, open);
  }
}
