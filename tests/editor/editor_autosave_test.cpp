// Autosave and crash recovery without a window: the paths (XDG), saving only when the interval passed and the
// session changed, a clean exit removing the files, a crash leaving them for the next start (which gives back the
// same session), a malformed autosave set aside as .bad and reported, and a second editor leaving the first alone.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "base/errors.h"
#include "core/scratch_folder.h"
#include "editor_options.h"
#include "engine/session.h"
#include "job_waiting.h"
#include "methods/method_descriptors.h"
#include "model/app_state.h"
#include "model/autosave.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

namespace fs = std::filesystem;

// A fresh config folder, removed at the end of the test.
class ConfigDir {
 public:
  AutosavePaths paths() const { return autosavePaths(root_.path().c_str(), nullptr); }

 private:
  test::ScratchFolder root_;
};

Session demoSession(double x) {
  Session s;
  s.demoDim = 2;
  s.pose.resize(2, 2);
  s.pose << x, 0.25, 1.0 / 3.0, -2.5;
  s.params.gamma = 1.5;
  s.camera.distance = 4.0;
  return s;
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// A pid that belonged to a process that has exited (a child, reaped).
long deadPid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

}  // namespace

TEST(EditorAutosave, PathsFollowXdgConfigHomeThenHome) {
  EXPECT_EQ(autosavePaths("/x/config", "/home/u").session, "/x/config/somicage/autosave.json");
  EXPECT_EQ(autosavePaths("/x/config", "/home/u").marker, "/x/config/somicage/autosave.running");
  EXPECT_EQ(autosavePaths("relative", "/home/u").session, "/home/u/.config/somicage/autosave.json");
  EXPECT_EQ(autosavePaths(nullptr, "/home/u").marker, "/home/u/.config/somicage/autosave.running");
  EXPECT_TRUE(autosavePaths(nullptr, "").session.empty());
  Autosave off(autosavePaths(nullptr, nullptr));
  EXPECT_FALSE(off.begin().session.has_value());
  EXPECT_FALSE(off.enabled());
  EXPECT_FALSE(off.tick(demoSession(0), 1000));
}

TEST(EditorAutosave, SavesOnlyAfterTheIntervalAndOnlyWhenTheSessionChanged) {
  ConfigDir dir;
  Autosave autosave(dir.paths(), 30.0);
  const AutosaveLeftover start = autosave.begin();
  EXPECT_TRUE(start.error.empty()) << start.error;
  ASSERT_TRUE(autosave.enabled());
  EXPECT_TRUE(fs::exists(dir.paths().marker));
  EXPECT_FALSE(autosave.tick(demoSession(0), 100.0));  // the first tick starts the clock
  EXPECT_FALSE(autosave.tick(demoSession(0), 129.9));
  EXPECT_FALSE(fs::exists(dir.paths().session));
  EXPECT_TRUE(autosave.tick(demoSession(0), 130.0));
  EXPECT_EQ(loadSession(dir.paths().session).pose, demoSession(0).pose);
  EXPECT_FALSE(autosave.tick(demoSession(0), 170.0)) << "unchanged: nothing to write";
  EXPECT_FALSE(autosave.tick(demoSession(1), 180.0)) << "changed, but within the interval of the last check";
  EXPECT_TRUE(autosave.tick(demoSession(1), 200.0));
  EXPECT_EQ(loadSession(dir.paths().session).pose, demoSession(1).pose);
}

TEST(EditorAutosave, ACleanExitRemovesTheAutosaveAndTheMarker) {
  ConfigDir dir;
  {
    Autosave autosave(dir.paths(), 1.0);
    autosave.begin();
    autosave.tick(demoSession(0), 0.0);
    ASSERT_TRUE(autosave.tick(demoSession(0), 1.0));
    autosave.finish();
  }
  EXPECT_FALSE(fs::exists(dir.paths().session));
  EXPECT_FALSE(fs::exists(dir.paths().marker));
  Autosave next(dir.paths(), 1.0);
  const AutosaveLeftover leftover = next.begin();
  EXPECT_FALSE(leftover.session.has_value());
  EXPECT_TRUE(leftover.error.empty()) << leftover.error;
}

TEST(EditorAutosave, ACrashLeavesTheSessionAndTheNextStartGivesItBack) {
  ConfigDir dir;
  const Session saved = demoSession(0.125);
  {
    Autosave autosave(dir.paths(), 1.0);
    autosave.begin();
    autosave.tick(saved, 0.0);
    ASSERT_TRUE(autosave.tick(saved, 1.0));
    // No finish(): the process "crashed". The marker names this process, which a new start never takes for a
    // running editor (it is the new start itself).
  }
  ASSERT_TRUE(fs::exists(dir.paths().session));
  Autosave next(dir.paths(), 1.0);
  const AutosaveLeftover leftover = next.begin();
  ASSERT_TRUE(leftover.session.has_value()) << leftover.error;
  EXPECT_EQ(sessionToJson(*leftover.session), sessionToJson(saved));
  EXPECT_EQ(leftover.savedAt.size(), 16u) << leftover.savedAt;  // "YYYY-MM-DD HH:MM"
  EXPECT_TRUE(next.enabled());
}

TEST(EditorAutosave, TheMarkerOfAnExitedProcessMeansACrash) {
  ConfigDir dir;
  fs::create_directories(fs::path(dir.paths().marker).parent_path());
  saveSession(dir.paths().session, demoSession(2));
  writeText(dir.paths().marker, "somicage-autosave 1\npid " + std::to_string(deadPid()) + "\n");
  Autosave autosave(dir.paths());
  const AutosaveLeftover leftover = autosave.begin();
  ASSERT_TRUE(leftover.session.has_value()) << leftover.error;
  EXPECT_EQ(leftover.session->pose, demoSession(2).pose);
}

TEST(EditorAutosave, AnAutosaveWithoutAMarkerIsNotOffered) {
  ConfigDir dir;
  fs::create_directories(fs::path(dir.paths().session).parent_path());
  saveSession(dir.paths().session, demoSession(3));  // e.g. the marker was removed by hand
  Autosave autosave(dir.paths());
  EXPECT_FALSE(autosave.begin().session.has_value());
}

TEST(EditorAutosave, AMalformedAutosaveIsReportedAndSetAsideNotFatal) {
  ConfigDir dir;
  fs::create_directories(fs::path(dir.paths().marker).parent_path());
  writeText(dir.paths().session, "{ \"format\": \"somicage-session\", \"version\": ");
  writeText(dir.paths().marker, "somicage-autosave 1\npid " + std::to_string(deadPid()) + "\n");
  Autosave autosave(dir.paths(), 1.0);
  const AutosaveLeftover leftover = autosave.begin();
  EXPECT_FALSE(leftover.session.has_value());
  EXPECT_NE(leftover.error.find("the autosave of the last session cannot be restored"), std::string::npos)
      << leftover.error;
  EXPECT_NE(leftover.error.find("autosave.json.bad"), std::string::npos) << leftover.error;
  EXPECT_TRUE(fs::exists(dir.paths().session + ".bad"));
  EXPECT_FALSE(fs::exists(dir.paths().session));
  // Autosave still works, and the next start finds nothing to report.
  ASSERT_TRUE(autosave.enabled());
  autosave.tick(demoSession(4), 0.0);
  EXPECT_TRUE(autosave.tick(demoSession(4), 1.0));
  autosave.finish();
  Autosave next(dir.paths());
  const AutosaveLeftover again = next.begin();
  EXPECT_TRUE(again.error.empty()) << again.error;
  EXPECT_FALSE(again.session.has_value());
}

TEST(EditorAutosave, AMalformedMarkerCountsAsACrash) {
  ConfigDir dir;
  fs::create_directories(fs::path(dir.paths().marker).parent_path());
  saveSession(dir.paths().session, demoSession(5));
  writeText(dir.paths().marker, "garbage");
  Autosave autosave(dir.paths());
  EXPECT_TRUE(autosave.begin().session.has_value());
}

TEST(EditorAutosave, ASecondEditorLeavesTheRunningOnesAutosaveAlone) {
  ConfigDir dir;
  fs::create_directories(fs::path(dir.paths().marker).parent_path());
  saveSession(dir.paths().session, demoSession(6));
  const std::string marker = "somicage-autosave 1\npid 1\n";  // pid 1 always runs
  writeText(dir.paths().marker, marker);
  Autosave second(dir.paths(), 1.0);
  const AutosaveLeftover leftover = second.begin();
  EXPECT_TRUE(leftover.otherEditorRunning);
  EXPECT_FALSE(leftover.session.has_value()) << "not a crash: that editor is still running";
  EXPECT_FALSE(second.enabled());
  second.tick(demoSession(7), 0.0);
  EXPECT_FALSE(second.tick(demoSession(7), 5.0));
  second.finish();
  EXPECT_EQ(loadSession(dir.paths().session).pose, demoSession(6).pose);
  EXPECT_TRUE(fs::exists(dir.paths().marker));
}

TEST(EditorAutosave, AnUnwritableFolderTurnsAutosaveOffWithAMessage) {
  Autosave autosave(autosavePaths("/proc/somicage-no-such-folder", nullptr));
  const AutosaveLeftover leftover = autosave.begin();
  EXPECT_FALSE(autosave.enabled());
  EXPECT_NE(leftover.error.find("autosave is off"), std::string::npos) << leftover.error;
}

TEST(EditorAutosave, RestoreAutosaveIsACommandLineFlag) {
  EXPECT_FALSE(parseEditorArgs({}).restoreAutosave);
  EXPECT_TRUE(parseEditorArgs({"--restore-autosave"}).restoreAutosave);
  EXPECT_NE(editorUsage().find("--restore-autosave"), std::string::npos);
}

TEST(EditorAutosave, AcceptingTheOfferAppliesTheSessionAndDiscardingDropsIt) {
  AppState state;
  Session crashed = demoSession(0.5);
  crashed.params.gamma = 2.5;
  crashed.method = methods::green();
  crashed.pose.resize(0, 0);  // the rest pose of the demo
  state.files.restoreOffer = crashed;
  state.files.restoreOfferTime = "2026-11-23 19:40";
  acceptRestoreOffer(state);
  EXPECT_FALSE(state.files.restoreOffer.has_value());
  EXPECT_EQ(state.status.message, "restored the session from 2026-11-23 19:40");
  std::optional<PrecomputeOutcome> out = waitForOutcome(state.jobs.precompute);  // the 2D demo of the session loads
  ASSERT_TRUE(out.has_value());
  installOutcome(state, std::move(*out));
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  ASSERT_TRUE(state.model.scene);
  EXPECT_EQ(state.model.scene->dim(), 2);
  EXPECT_EQ(state.document.params.gamma, 2.5);  // set with the session's scene
  EXPECT_EQ(state.document.method, methods::green());

  state.files.restoreOffer = demoSession(1);
  discardRestoreOffer(state);
  EXPECT_FALSE(state.files.restoreOffer.has_value());
  EXPECT_EQ(state.document.params.gamma, 2.5) << "discarding changes nothing";
}

TEST(EditorAutosave, AFailedWriteThrowsAndIsTriedAgainOneIntervalLater) {
  ConfigDir dir;
  Autosave autosave(dir.paths(), 10.0);
  autosave.begin();
  ASSERT_TRUE(autosave.enabled());
  const fs::path folder = fs::path(dir.paths().session).parent_path();
  fs::remove_all(folder);  // e.g. the folder was deleted under the running editor
  autosave.tick(demoSession(0), 0.0);
  EXPECT_THROW(autosave.tick(demoSession(0), 10.0), InputError);
  fs::create_directories(folder);
  EXPECT_FALSE(autosave.tick(demoSession(0), 15.0)) << "not before the next interval";
  EXPECT_TRUE(autosave.tick(demoSession(0), 20.0));
  EXPECT_TRUE(fs::exists(dir.paths().session));
}
