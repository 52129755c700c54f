// Opening a session reads and parses its file on a job (JobsState::session, jobs/session_read.h), never on the UI
// thread: the frame loop keeps running while it is read, a cancel or an error leaves the open document as it was, and
// a good session is applied, on the UI thread, as its file says.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "core/scratch_folder.h"
#include "editor_test_support.h"
#include "interaction/shortcuts.h"
#include "interaction/transform.h"
#include "job_waiting.h"
#include "jobs/session_read.h"
#include "jobs/thread_budget.h"
#include "model/app_state.h"
#include "model/pose_keys.h"
#include "ui/unsaved_changes.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

// A cube cage around one triangle and a session of them, written by hand: what the tests expect is read off this text.
constexpr const char* kCage =
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
constexpr const char* kMesh = "v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0 0.5 0.3\nf 1 2 3\n";
constexpr const char* kStretched =
    "[[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1], [-1, -1, 1], [1, -1, 1], [1.5, 1.25, 1], [-1, 1, 1]]";

std::string sessionText(const std::string& mesh) {
  return std::string(R"({
  "format": "somicage-session",
  "version": 3,
  "mesh": ")") +
         mesh + R"(",
  "cage": "cage.obj",
  "pose": )" +
         kStretched + R"(,
  "method": "green",
  "params": {"nu": 0.25, "gamma": 1.5},
  "compare": false,
  "camera": {"target": [0.5, 0.25, -0.125], "distance": 6.5, "yaw": 0.75, "pitch": -0.25},
  "poses": [{"name": "stretched", "vertices": )" +
         kStretched + R"(}],
  "timeline": {"fps": 12, "first": 3, "last": 40, "loop": true, "interpolation": "linear",
               "keys": [{"frame": 5, "pose": "stretched"}]}
}
)";
}

// The files of one test: cage.obj, mesh.obj and s.json (the session of them) in a fresh folder.
struct SessionFiles {
  test::ScratchFolder dir;
  std::string session = dir / "s.json";
  SessionFiles() {
    std::ofstream(dir / "cage.obj") << kCage;
    std::ofstream(dir / "mesh.obj") << kMesh;
    std::ofstream(session) << sessionText("mesh.obj");
  }
};

// The document open before: the 2D demo with edits (a parameter, a moved vertex, a stored pose), unsaved.
void openEditedDemo(AppState& state) {
  openDemoScene(state, 2);
  DeformParams params = state.document.params;
  params.gamma = 0.5;
  setParams(state, params);
  Eigen::MatrixXd pose = state.document.pose;
  pose(0, 0) -= 0.25;
  setPose(state, pose);
  commitEdit(state, "Grab");
  storeCurrentPose(state, "mine");
  ASSERT_TRUE(hasUnsavedChanges(state));
}

// What a cancelled or failed open must leave as it was: the scene, its deformers, the document and its history, the
// views.
struct Kept {
  std::shared_ptr<const Scene> scene;
  DeformerSet deformers;
  Document document;
  std::size_t steps = 0, cursor = 0;
  std::string path;
  std::vector<ViewSpec> views;
};

Kept keep(const AppState& state) {
  return {state.model.scene,
          state.model.deformers,
          currentDocument(state),
          state.document.history.size(),
          state.document.history.cursor(),
          state.document.path,
          state.views()};
}

void expectKept(const AppState& state, const Kept& kept) {
  EXPECT_EQ(state.model.scene, kept.scene);
  EXPECT_EQ(state.model.deformers, kept.deformers);
  EXPECT_TRUE(currentDocument(state) == kept.document) << "the open document changed";
  EXPECT_EQ(state.document.history.size(), kept.steps);
  EXPECT_EQ(state.document.history.cursor(), kept.cursor);
  EXPECT_EQ(state.document.path, kept.path);
  EXPECT_TRUE(state.views() == kept.views) << "the views changed";
  EXPECT_TRUE(hasUnsavedChanges(state));
}

// What the frame loop polls each frame (editor.cpp, frame()): the session read, then the scene's load.
void frame(AppState& state) {
  pollSessionRead(state);
  pollWorker(state);
}

// Frames until the session and its scene have arrived or failed.
void framesUntilSettled(AppState& state) {
  waitUntil([&state] {
    frame(state);
    return !state.jobs.session.busy() && !state.jobs.session.ready() && !state.loadingScene() &&
           !state.jobs.precompute.busy();
  });
}

// Opens the session as File > Open session does: asked first over unsaved changes (answered Don't save), then read
// by `steered`, which holds the read until released. Returns once the reader runs.
void startOpening(AppState& state, const std::string& session, SteeredSessionReader& steered) {
  guardUnsaved(state, "open session s.json",
               [session, read = steered.reader()](AppState& s) { loadSessionFile(s, session, read); });
  if (state.document.unsaved.asking) answerUnsaved(state, UnsavedChoice::DontSave);
  waitUntil([&steered] { return steered.entered.load(); });
}

// Releases the reader, waits until the file is read and runs one frame: the frame that takes the read session.
void finishReading(AppState& state, SteeredSessionReader& steered) {
  steered.released = true;
  waitUntilDone(state.jobs.session);
  frame(state);
}

// One edit of the open document as the user makes it: a vertex moved, committed as "Grab".
void grab(AppState& state) {
  Eigen::MatrixXd pose = state.document.pose;
  pose(1, 0) += 0.125;
  setPose(state, pose);
  ASSERT_TRUE(commitEdit(state, "Grab"));
}

// The finished read is there, untaken: nothing of the session was applied or started (its scene's load).
void expectReadWaiting(const AppState& state) {
  EXPECT_TRUE(state.jobs.session.ready()) << "the read session was taken";
  EXPECT_FALSE(state.loadingScene());
}

// The session's own method and file, against the demo's (Somigliana, no file): was it applied?
bool sessionApplied(const AppState& state, const std::string& session) {
  return methodName(state.document.method) == "green" && state.document.path == session;
}

// Every core of the machine's budget, held by the test: a job started meanwhile waits for its cores.
struct HeldCores {
  ThreadBudget::Lease lease;
  std::atomic<bool> stop{false};
  HeldCores() { ThreadBudget::machine().acquire(lease, ThreadBudget::machine().cores(), stop); }
  ~HeldCores() { ThreadBudget::machine().release(lease); }
  HeldCores(const HeldCores&) = delete;
  HeldCores& operator=(const HeldCores&) = delete;
};

}  // namespace

// (a) While the file is read (a reader held by the test), each frame returns at once, the panel's stage names the
// file, and the open document still takes edits and deforms; released, the session is applied. Before, the UI thread
// read the file itself and drew nothing until it had.
TEST(EditorSessionOpen, TheFrameLoopRunsWhileTheSessionIsRead) {
  const SessionFiles files;
  SteeredSessionReader steered;
  AppState state;
  openEditedDemo(state);
  const std::size_t steps = state.document.history.size();
  loadSessionFile(state, files.session, steered.reader());
  waitUntil([&steered] { return steered.entered.load(); });
  for (int f = 1; f <= 10; ++f) {
    frame(state);
    EXPECT_TRUE(state.jobs.session.busy());
    Eigen::MatrixXd pose = state.document.pose;
    pose(1, 1) += 0.01;
    setPose(state, pose);
    EXPECT_TRUE(commitEdit(state, "Grab"));
    EXPECT_TRUE(updateDeformation(state)) << "frame " << f;
  }
  EXPECT_EQ(state.jobs.session.stage(), "Reading session s.json");
  EXPECT_EQ(state.document.history.size(), steps + 10);
  EXPECT_EQ(methodName(state.document.method), "somigliana") << "the session is not applied before it is read";
  EXPECT_FALSE(steered.timedOut) << "something waited for the reader";
  steered.released = true;
  framesUntilSettled(state);
  ASSERT_TRUE(state.document.unsaved.asking) << "the edits made meanwhile are not discarded without asking";
  answerUnsaved(state, UnsavedChoice::DontSave);
  framesUntilSettled(state);
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  EXPECT_EQ(methodName(state.document.method), "green");
  EXPECT_EQ(state.document.path, files.session);
}

// (b) A cancel (Esc; the panel's Cancel calls the same job's cancel) while the file is read, and one after it was
// read while its scene loads (the load job waits for cores the test holds, so the cancel lands before the mesh is
// read): each leaves the open document, its history, its views and its scene as they were. Before, the session's
// method, parameters, views and poses replaced the document's when its scene was asked for, so a cancelled or
// failed load left the old scene with the session's settings.
TEST(EditorSessionOpen, ACancelKeepsTheOpenDocument) {
  const SessionFiles files;
  SteeredSessionReader steered;
  AppState state;
  openEditedDemo(state);
  const Kept kept = keep(state);

  loadSessionFile(state, files.session, steered.reader());
  waitUntil([&steered] { return steered.entered.load(); });
  cancelPrecompute(state);
  framesUntilSettled(state);
  EXPECT_FALSE(steered.timedOut);
  EXPECT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  EXPECT_EQ(state.status.message, "opening session " + files.session + " cancelled");
  expectKept(state, kept);

  loadSessionFile(state, files.session);
  waitUntilDone(state.jobs.session);
  {
    const HeldCores held;
    ASSERT_TRUE(pollSessionRead(state));
    ASSERT_TRUE(state.loadingScene());
    EXPECT_TRUE(currentDocument(state) == kept.document) << "changed while its scene loads";
    EXPECT_TRUE(state.views() == kept.views);
    cancelPrecompute(state);
  }
  framesUntilSettled(state);
  EXPECT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  EXPECT_EQ(state.status.message, "precomputation cancelled");
  expectKept(state, kept);
}

// (c) A session that cannot be opened is reported, naming the file (and the line of a syntax error), and the open
// document stays: a missing session file, a syntax error on line 4, an unknown method, a mesh that is not there (found
// only when the scene is read, after the session was).
TEST(EditorSessionOpen, ABadSessionIsReportedAndTheOpenDocumentKept) {
  const SessionFiles files;
  const std::string syntax = files.dir / "syntax.json", method = files.dir / "method.json",
                    noMesh = files.dir / "no_mesh.json";
  std::ofstream(syntax) << "{\n  \"format\": \"somicage-session\",\n  \"version\": 3,\n  \"mesh\" \"mesh.obj\"\n}\n";
  std::string text = sessionText("mesh.obj");
  text.replace(text.find("\"green\""), 7, "\"bogus\"");
  std::ofstream(method) << text;
  std::ofstream(noMesh) << sessionText("missing.obj");
  struct Case {
    std::string path;
    std::vector<std::string> named;  // what the error must name
  };
  const std::vector<Case> cases = {{files.dir / "nothing.json", {files.dir / "nothing.json"}},
                                   {syntax, {syntax + ":4:"}},
                                   {method, {method, "bogus"}},
                                   {noMesh, {"missing.obj"}}};
  AppState state;
  openEditedDemo(state);
  const Kept kept = keep(state);
  for (const Case& c : cases) {
    SCOPED_TRACE(c.path);
    loadSessionFile(state, c.path);
    framesUntilSettled(state);
    ASSERT_EQ(state.status.errors.size(), 1u);
    for (const std::string& name : c.named)
      EXPECT_NE(state.status.errors.front().find(name), std::string::npos) << state.status.errors.front();
    expectKept(state, kept);
    state.status.errors.clear();
  }
}

// (d) A good session, opened from File > Open Recent over unsaved changes (asked first: nothing is read before the
// answer), is applied as its file says: the files next to it, the pose, the method and parameters, the camera, the
// pose library and timeline, the frame cursor at the range's start; opened clean, named by its file, recent first.
TEST(EditorSessionOpen, AGoodSessionIsAppliedAsItsFileSays) {
  const SessionFiles files;
  AppState state;
  openEditedDemo(state);
  openRecent(state, RecentEntry::sessionFile(files.session));
  ASSERT_TRUE(state.document.unsaved.asking.has_value()) << "opening over unsaved changes asks first";
  EXPECT_FALSE(state.jobs.session.busy());
  answerUnsaved(state, UnsavedChoice::DontSave);
  framesUntilSettled(state);
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  ASSERT_TRUE(state.model.scene);
  EXPECT_EQ(state.model.scene->meshPath, files.dir / "mesh.obj");
  EXPECT_EQ(state.model.scene->cagePath, files.dir / "cage.obj");
  EXPECT_EQ(state.model.scene->meshVertices.rows(), 3);
  Eigen::MatrixXd stretched(8, 3);
  stretched << -1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1.5, 1.25, 1, -1, 1, 1;
  EXPECT_EQ(state.document.pose, stretched);
  EXPECT_EQ(methodName(state.document.method), "green");
  EXPECT_EQ(state.document.params.nu, 0.25);
  EXPECT_EQ(state.document.params.gamma, 1.5);
  EXPECT_FALSE(state.view.compare);
  const CameraState camera = state.view.camera.state();
  EXPECT_EQ(camera.target, Eigen::Vector3d(0.5, 0.25, -0.125));
  EXPECT_EQ(camera.distance, 6.5);
  EXPECT_EQ(camera.yaw, 0.75);
  EXPECT_EQ(camera.pitch, -0.25);
  ASSERT_EQ(state.animation.poses.poses().size(), 1u);
  EXPECT_EQ(state.animation.poses.poses()[0].name, "stretched");
  EXPECT_EQ(state.animation.poses.poses()[0].vertices, stretched);
  EXPECT_EQ(state.animation.timeline.fps, 12);
  EXPECT_EQ(state.animation.timeline.firstFrame, 3);
  EXPECT_EQ(state.animation.timeline.lastFrame, 40);
  ASSERT_EQ(state.animation.timeline.keys.size(), 1u);
  EXPECT_EQ(state.animation.timeline.keys[0].frame, 5);
  EXPECT_EQ(state.animation.frame, 3);
  EXPECT_TRUE(state.animation.showPanels);
  EXPECT_TRUE(hasDeformer(state, deformerKey(state.views().front())));
  EXPECT_EQ(state.document.path, files.session);
  EXPECT_FALSE(hasUnsavedChanges(state));
  EXPECT_EQ(state.document.history.size(), 1u);
  EXPECT_EQ(state.files.recent.entries().front(), RecentEntry::sessionFile(files.session));
  EXPECT_EQ(state.status.message.rfind("loaded ", 0), 0u) << state.status.message;
}

// (e) The user was asked before the read began; a change of the document while the file is read (an edit, an undo,
// an undo and its redo: the state the user agreed to discard may be back, but its redo step is the user's work) makes
// the finished read ask again, and nothing is applied until the answer: Don't save applies the session, Cancel drops
// it and keeps the document, its history and its views exactly. Before, the read session replaced them unasked.
TEST(EditorSessionOpen, AChangeWhileTheSessionIsReadAsksAgainBeforeItIsApplied) {
  const SessionFiles files;
  struct Change {
    std::string name;
    std::function<void(AppState&)> make;
  };
  const std::vector<Change> changes = {{"an edit", [](AppState& s) { grab(s); }},
                                       {"an undo", [](AppState& s) { undo(s); }},
                                       {"an undo and its redo", [](AppState& s) {
                                          undo(s);
                                          redo(s);
                                        }}};
  for (const Change& change : changes) {
    for (const UnsavedChoice answer : {UnsavedChoice::DontSave, UnsavedChoice::Cancel}) {
      SCOPED_TRACE(change.name + (answer == UnsavedChoice::Cancel ? ", Cancel" : ", Don't save"));
      SteeredSessionReader steered;
      AppState state;
      openEditedDemo(state);
      startOpening(state, files.session, steered);
      change.make(state);
      const Kept kept = keep(state);
      finishReading(state, steered);
      framesUntilSettled(state);
      ASSERT_TRUE(state.document.unsaved.asking) << "the finished read asks";
      EXPECT_EQ(state.document.unsaved.asking->what, "open session s.json");
      expectKept(state, kept);  // nothing applied while it asks
      answerUnsaved(state, answer);
      framesUntilSettled(state);
      ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
      EXPECT_FALSE(state.document.unsaved.asking);
      if (answer == UnsavedChoice::Cancel) {
        EXPECT_EQ(state.status.message, "cancelled: open session s.json");
        expectKept(state, kept);
      } else {
        EXPECT_TRUE(sessionApplied(state, files.session));
        EXPECT_FALSE(hasUnsavedChanges(state));
      }
    }
  }
}

// (f) Without a change while the file is read, the session is applied at once, unasked: over a clean document, over
// an unsaved one whose user answered Don't save before the read (what was unsaved then was asked about), with a
// commit that changed nothing meanwhile; and after an edit that was saved meanwhile (nothing is lost: it is on disk).
TEST(EditorSessionOpen, WithoutAChangeWhileTheSessionIsReadItIsAppliedUnasked) {
  const SessionFiles files;
  struct Case {
    std::string name;
    bool edited = false;                       // the document is unsaved when the read begins
    std::function<void(AppState&)> meanwhile;  // what the user does while the file is read
  };
  const std::string mine = files.dir / "mine.json";
  const std::vector<Case> cases = {
      {"clean", false, [](AppState&) {}},
      {"unsaved, answered Don't save", true, [](AppState& s) { EXPECT_FALSE(commitEdit(s, "Grab")); }},
      {"an edit saved meanwhile", true, [&mine](AppState& s) {
         grab(s);
         ASSERT_TRUE(saveSessionFile(s, mine));
       }}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    SteeredSessionReader steered;
    AppState state;
    if (c.edited) {
      openEditedDemo(state);
    } else {
      openDemoScene(state, 2);
    }
    startOpening(state, files.session, steered);
    c.meanwhile(state);
    finishReading(state, steered);
    EXPECT_FALSE(state.document.unsaved.asking) << "asked again";
    framesUntilSettled(state);
    ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
    EXPECT_TRUE(sessionApplied(state, files.session));
  }
}

// (g) Save: the document with the edit made during the read is written first, to its file or (none yet) through the
// Save session dialog, then the session is applied. A session of the scene shown (the 2D demo, Green, nu = 0.25) is
// applied at once as an edit, so the order shows in the saved file, read back: the edited pose and Somigliana, not
// the session's rest pose and Green.
TEST(EditorSessionOpen, SaveWritesTheDocumentWithTheEditThenAppliesTheSession) {
  const test::ScratchFolder dir;
  const std::string session = dir / "demo.json", mine = dir / "mine.json";
  for (const bool hasFile : {true, false}) {
    SCOPED_TRACE(hasFile ? "the document has a file" : "the Save session dialog");
    SteeredSessionReader steered;
    AppState state;
    openDemoScene(state, 2);
    Session demo = makeSession(state);
    demo.method = parseMethod("green");
    demo.params.nu = 0.25;
    saveSession(session, demo);
    if (hasFile) {
      ASSERT_TRUE(saveSessionFile(state, mine));
    }
    startOpening(state, session, steered);
    grab(state);
    const Eigen::MatrixXd edited = state.document.pose;
    finishReading(state, steered);
    ASSERT_TRUE(state.document.unsaved.asking);
    answerUnsaved(state, UnsavedChoice::Save);
    if (!hasFile) {  // the dialog is open; its OK saves, then runs the action
      EXPECT_TRUE(state.document.unsaved.afterSave);
      EXPECT_FALSE(sessionApplied(state, session));
      ASSERT_TRUE(saveSessionFile(state, mine));
      sessionDialogFinished(state, true);
    }
    const Session saved = loadSession(mine);
    EXPECT_EQ(saved.pose, edited) << "the edit made during the read is saved, before the session is applied";
    EXPECT_EQ(methodName(saved.method), "somigliana");
    framesUntilSettled(state);
    ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
    EXPECT_TRUE(sessionApplied(state, session));
    EXPECT_EQ(state.document.pose, demo.pose);
    EXPECT_EQ(state.document.params.nu, 0.25);
    EXPECT_FALSE(hasUnsavedChanges(state));
  }
}

// (h) A finished read waits while another question is open (Ctrl+Q meanwhile: the quit question stays, not replaced
// by the session's) and during a live edit: a handle moving the cage (G: its edit, once confirmed, asks; an Esc'd
// transform changes nothing, so the session then comes unasked) and a slider held (nu: committed on release, asks).
TEST(EditorSessionOpen, AFinishedReadWaitsForAnOpenQuestionAndAMovingHandle) {
  const SessionFiles files;
  {
    SCOPED_TRACE("quit asked meanwhile");
    SteeredSessionReader steered;
    AppState state;
    openEditedDemo(state);
    startOpening(state, files.session, steered);
    requestQuit(state);
    finishReading(state, steered);
    ASSERT_TRUE(state.document.unsaved.asking);
    EXPECT_EQ(state.document.unsaved.asking->what, "quit");
    expectReadWaiting(state);
    answerUnsaved(state, UnsavedChoice::Cancel);
    framesUntilSettled(state);
    EXPECT_FALSE(state.document.quitRequested);
    EXPECT_TRUE(sessionApplied(state, files.session));
  }
  for (const bool confirmed : {true, false}) {
    SCOPED_TRACE(confirmed ? "G confirmed" : "G cancelled");
    SteeredSessionReader steered;
    AppState state;
    openEditedDemo(state);
    startOpening(state, files.session, steered);
    const Eigen::MatrixXd original = state.document.pose;
    state.input.mouse.mode = Interaction::Mode::Modal;
    state.input.mouse.transform =
        beginTransform(TransformKind::Grab, {1}, original, Eigen::Vector2d(10, 10), Eigen::Vector2d(100, 100));
    Eigen::MatrixXd moved = original;
    moved(1, 0) += 0.125;
    setPose(state, moved);
    finishReading(state, steered);
    expectReadWaiting(state);
    EXPECT_EQ(state.document.pose, moved);
    if (confirmed) {
      EXPECT_TRUE(commitEdit(state, "Grab"));  // Enter (confirmTransform)
    } else {
      setPose(state, original);  // Esc (cancelTransform)
    }
    state.input.mouse.transform.reset();
    state.input.mouse.mode = Interaction::Mode::Idle;
    framesUntilSettled(state);
    EXPECT_EQ(state.document.unsaved.asking.has_value(), confirmed);
    EXPECT_EQ(sessionApplied(state, files.session), !confirmed);
  }
  {
    SCOPED_TRACE("nu slider held");
    SteeredSessionReader steered;
    AppState state;
    openEditedDemo(state);
    startOpening(state, files.session, steered);
    state.input.widgetActive = true;
    DeformParams params = state.document.params;
    params.nu = 0.125;
    setParams(state, params);
    finishReading(state, steered);
    expectReadWaiting(state);
    EXPECT_EQ(state.document.params.nu, 0.125);
    EXPECT_TRUE(commitEdit(state, "nu"));  // released (IsItemDeactivatedAfterEdit)
    state.input.widgetActive = false;
    framesUntilSettled(state);
    EXPECT_TRUE(state.document.unsaved.asking);
    EXPECT_FALSE(sessionApplied(state, files.session));
  }
}
