// Recent files (recent_files.h): most recent first, no duplicates, at most ten, an exact text round trip,
// malformed lines ignored, the XDG/HOME location, and AppState recording what was opened.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "editor_test_support.h"
#include "model/app_state.h"
#include "model/recent_files.h"
#include "model/scene.h"

using namespace somicage;
using namespace somicage::editor;

TEST(EditorRecentFiles, MostRecentFirstWithoutDuplicates) {
  RecentFiles r;
  EXPECT_TRUE(r.add(RecentEntry::files("/a.obj", "/a_cage.obj")));
  EXPECT_TRUE(r.add(RecentEntry::sessionFile("/s.json")));
  EXPECT_TRUE(r.add(RecentEntry::files("/b.obj", "/b_cage.obj", "/b_pose.obj")));
  ASSERT_EQ(r.entries().size(), 3u);
  EXPECT_EQ(r.entries()[0], RecentEntry::files("/b.obj", "/b_cage.obj", "/b_pose.obj"));
  EXPECT_EQ(r.entries()[2], RecentEntry::files("/a.obj", "/a_cage.obj"));

  // Re-opening moves the entry to the front instead of adding a copy.
  r.add(RecentEntry::files("/a.obj", "/a_cage.obj"));
  ASSERT_EQ(r.entries().size(), 3u);
  EXPECT_EQ(r.entries()[0], RecentEntry::files("/a.obj", "/a_cage.obj"));
  EXPECT_EQ(r.entries()[1], RecentEntry::files("/b.obj", "/b_cage.obj", "/b_pose.obj"));
  EXPECT_EQ(r.entries()[2], RecentEntry::sessionFile("/s.json"));
  // The same files with another pose are another entry.
  r.add(RecentEntry::files("/a.obj", "/a_cage.obj", "/a_pose.obj"));
  EXPECT_EQ(r.entries().size(), 4u);
}

TEST(EditorRecentFiles, KeepsTheTenMostRecent) {
  RecentFiles r;
  for (int i = 0; i < 15; ++i) r.add(RecentEntry::sessionFile("/s" + std::to_string(i) + ".json"));
  ASSERT_EQ(r.entries().size(), RecentFiles::kMaxEntries);
  EXPECT_EQ(r.entries().front().session, "/s14.json");
  EXPECT_EQ(r.entries().back().session, "/s5.json");
}

TEST(EditorRecentFiles, RejectsEntriesItCannotStore) {
  RecentFiles r;
  EXPECT_FALSE(r.add(RecentEntry::files("/a.obj", "")));
  EXPECT_FALSE(r.add(RecentEntry::sessionFile("")));
  EXPECT_FALSE(r.add(RecentEntry::sessionFile("/tab\there.json")));
  EXPECT_FALSE(r.add(RecentEntry::files("/a.obj", "/line\nbreak.obj")));
  EXPECT_TRUE(r.entries().empty());
}

TEST(EditorRecentFiles, TextRoundTripIsExact) {
  RecentFiles r;
  r.add(RecentEntry::files("/m/a mesh.obj", "/m/cage.obj"));
  r.add(RecentEntry::sessionFile("/home/u/ünïcode session.json"));
  r.add(RecentEntry::files("/m/b.obj", "/m/b_cage.obj", "/m/b_posed.obj"));
  const RecentFiles back = RecentFiles::fromText(r.toText());
  EXPECT_EQ(back.entries(), r.entries());
  EXPECT_EQ(back.toText(), r.toText());
  EXPECT_TRUE(RecentFiles::fromText("").entries().empty());
}

TEST(EditorRecentFiles, MalformedLinesAreIgnored) {
  const std::string text =
      "somicage-recent 1\n"
      "# a comment\n"
      "\n"
      "files\t/a.obj\t/a_cage.obj\t\n"
      "garbage without tabs\n"
      "files\t/only_mesh.obj\n"
      "files\t\t/cage.obj\t\n"
      "files\t/a\t/b\t/c\t/d\n"
      "session\n"
      "session\t/s.json\textra\n"
      "movie\t/x.mp4\n"
      "session\t/s.json\r\n"
      "files\t/a.obj\t/a_cage.obj\n"  // an older duplicate of the first entry
      "files\t/b.obj\t/b_cage.obj\n";
  const RecentFiles r = RecentFiles::fromText(text);
  ASSERT_EQ(r.entries().size(), 3u);
  EXPECT_EQ(r.entries()[0], RecentEntry::files("/a.obj", "/a_cage.obj"));
  EXPECT_EQ(r.entries()[1], RecentEntry::sessionFile("/s.json"));
  EXPECT_EQ(r.entries()[2], RecentEntry::files("/b.obj", "/b_cage.obj"));

  std::string many;
  for (int i = 0; i < 30; ++i) many += "session\t/s" + std::to_string(i) + ".json\n";
  EXPECT_EQ(RecentFiles::fromText(many).entries().size(), RecentFiles::kMaxEntries);
  EXPECT_TRUE(RecentFiles::fromText(std::string("\0\x01\xff binary", 10)).entries().empty());
}

TEST(EditorRecentFiles, LabelsNameTheFiles) {
  EXPECT_EQ(RecentEntry::files("/m/a.obj", "/m/a_cage.obj").label(), "a.obj + a_cage.obj");
  EXPECT_EQ(RecentEntry::files("/m/a.obj", "/m/a_cage.obj", "/p/pose.obj").label(), "a.obj + a_cage.obj (+ pose.obj)");
  EXPECT_EQ(RecentEntry::sessionFile("/s/x.json").label(), "session x.json");
  EXPECT_EQ(RecentEntry::files("/m/a.obj", "/m/c.obj", "/p.obj").paths().size(), 3u);
}

TEST(EditorRecentFiles, LocationFollowsXdgThenHome) {
  EXPECT_EQ(recentFilesPath("/xdg", "/home/u"), "/xdg/somicage/recent.txt");
  EXPECT_EQ(recentFilesPath(nullptr, "/home/u"), "/home/u/.config/somicage/recent.txt");
  EXPECT_EQ(recentFilesPath("", "/home/u"), "/home/u/.config/somicage/recent.txt");
  EXPECT_EQ(recentFilesPath("relative", "/home/u"), "/home/u/.config/somicage/recent.txt");  // XDG spec: ignored
  EXPECT_EQ(recentFilesPath(nullptr, nullptr), "");
  EXPECT_EQ(recentFilesPath("", ""), "");
}

TEST(EditorRecentFiles, FileRoundTripAndMissingFiles) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "somicage_recent_test";
  std::filesystem::remove_all(dir);
  const std::string path = (dir / "somicage" / "recent.txt").string();
  EXPECT_TRUE(loadRecentFiles(path).entries().empty());  // missing: no error
  EXPECT_TRUE(loadRecentFiles("").entries().empty());
  RecentFiles r;
  r.add(RecentEntry::files("/a.obj", "/a_cage.obj", "/a_pose.obj"));
  r.add(RecentEntry::sessionFile("/s.json"));
  saveRecentFiles(path, r);  // creates the folders
  EXPECT_EQ(loadRecentFiles(path).entries(), r.entries());
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << "\177ELF garbage\tnot\ta list\n";
  }
  EXPECT_TRUE(loadRecentFiles(path).entries().empty());
  EXPECT_TRUE(loadRecentFiles(dir.string()).entries().empty());  // a folder, not a file
  std::filesystem::remove_all(dir);
}

TEST(EditorRecentFiles, AppStateRecordsLoadedScenesAndSessions) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "somicage_recent_state";
  std::filesystem::remove_all(dir);
  AppState state;
  state.files.recentPath = (dir / "recent.txt").string();

  // A scene that arrives for the pending files is recorded, with absolute paths, and saved.
  auto scene = std::make_shared<Scene>(makeDemoScene(2));
  scene->meshPath = "rel/mesh.obj";
  scene->cagePath = "/abs/cage.obj";
  state.jobs.load.emplace().recent = RecentEntry::files("rel/mesh.obj", "/abs/cage.obj");
  PrecomputeOutcome outcome;
  outcome.scene = scene;
  installOutcome(state, outcome);
  ASSERT_EQ(state.files.recent.entries().size(), 1u);
  const RecentEntry& e = state.files.recent.entries().front();
  EXPECT_EQ(e.mesh, (std::filesystem::current_path() / "rel/mesh.obj").lexically_normal().string());
  EXPECT_EQ(e.cage, "/abs/cage.obj");
  EXPECT_FALSE(state.loadingScene());
  EXPECT_EQ(loadRecentFiles(state.files.recentPath).entries(), state.files.recent.entries());

  // A failed load records nothing.
  state.jobs.load.emplace().recent = RecentEntry::files("/x.obj", "/x_cage.obj");
  PrecomputeOutcome failed;
  failed.error = "cannot open";
  installOutcome(state, failed);
  EXPECT_EQ(state.files.recent.entries().size(), 1u);
  state.status.errors.clear();

  // A session that fails to parse records nothing; one that loads is recorded first.
  const std::string bad = (dir / "bad.json").string();
  { std::ofstream(bad) << "{ not json"; }
  loadSessionFile(state, bad);
  finishSessionRead(state);
  EXPECT_EQ(state.files.recent.entries().size(), 1u);
  EXPECT_EQ(state.status.errors.size(), 1u);
  state.status.errors.clear();
  const std::string good = (dir / "good.json").string();
  saveSessionFile(state, good);
  loadSessionFile(state, good);
  finishSessionRead(state);
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  ASSERT_EQ(state.files.recent.entries().size(), 2u);
  EXPECT_EQ(state.files.recent.entries().front(), RecentEntry::sessionFile(good));
  EXPECT_FALSE(state.jobs.load && state.jobs.load->recent);  // the session's files are not a separate entry
  state.jobs.precompute.cancel();
  std::filesystem::remove_all(dir);
}

// Issue 24, row 10: a session just saved is in the recent list (File > Open Recent) before it was ever opened; an
// entry whose file is gone is named so that the menu greys it out.
TEST(EditorRecentFiles, ASavedSessionIsRecentAtOnce) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "somicage_recent_saved";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  AppState state;
  state.model.scene = std::make_shared<const Scene>(makeDemoScene(2));
  state.document.pose = state.model.scene->restCage.vertices;
  const std::string saved = (dir / "saved.json").string();
  ASSERT_TRUE(saveSessionFile(state, saved));
  ASSERT_EQ(state.files.recent.entries().size(), 1u);
  EXPECT_EQ(state.files.recent.entries().front(), RecentEntry::sessionFile(saved));
  EXPECT_EQ(missingRecentPath(state.files.recent.entries().front()), "");
  std::filesystem::remove(saved);
  EXPECT_EQ(missingRecentPath(state.files.recent.entries().front()), saved);
  std::filesystem::remove_all(dir);
}
