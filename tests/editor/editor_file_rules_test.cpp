// The file dialogs' rules without a window (file_rules.h, file_dialog.h): per-kind folders and names, the
// overwrite question, refusal of foreign extensions and of foreign content (the case: Export deformed
// mesh over a session JSON), the folder listing of the browser; and the unsaved-changes state machine
// (unsaved_changes.h) for quit, open and demo, with the autosave surviving Cancel.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "base/file_util.h"
#include "editor_test_support.h"
#include "model/app_state.h"
#include "model/autosave.h"

using namespace somicage;
using namespace somicage::editor;
namespace fs = std::filesystem;

namespace {

class Folder : public ::testing::Test {
 protected:
  void SetUp() override {
    root = fs::path(::testing::TempDir()) /
           ("somicage_files_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(root);
    fs::create_directories(root / "sub");
  }
  void TearDown() override { fs::remove_all(root); }
  std::string path(const std::string& name) const { return (root / name).string(); }
  void write(const std::string& name, const std::string& text) const { std::ofstream(root / name) << text; }
  fs::path root;
};

void makeAChange(AppState& state) {
  Eigen::MatrixXd p = state.document.pose;
  p(0, 0) += 0.3;
  setPose(state, p);
  commitEdit(state, "Grab");
}

}  // namespace

TEST_F(Folder, ContentIsJudgedByTheBytesNotTheName) {
  write("s.obj", "{\n  \"format\": \"somicage-session\",\n  \"version\": 1\n}\n");
  write("m.json", "# mesh\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write("other.json", "{\"hello\": 1}");
  write("text.obj", "hello world\n");
  EXPECT_EQ(sniffFileContent(path("s.obj")), FileContent::Session);
  EXPECT_EQ(sniffFileContent(path("m.json")), FileContent::Obj);
  EXPECT_EQ(sniffFileContent(path("other.json")), FileContent::Other);
  EXPECT_EQ(sniffFileContent(path("text.obj")), FileContent::Other);
  EXPECT_EQ(sniffFileContent(path("sub")), FileContent::Folder);
  EXPECT_EQ(sniffFileContent(path("none")), FileContent::Missing);
}

TEST_F(Folder, SaveChecksAskRefuseAndAddTheExtension) {
  write("my_session.json", "{\"format\": \"somicage-session\", \"version\": 1}");
  write("old.obj", "v 0 0 0\n");
  PathCheck c = checkSavePath(FileKind::DeformedMesh, path("new"));
  EXPECT_EQ(c.verdict, PathCheck::Verdict::Ok);
  EXPECT_EQ(c.path, path("new.obj"));
  c = checkSavePath(FileKind::DeformedMesh, path("old.obj"));
  EXPECT_EQ(c.verdict, PathCheck::Verdict::AskOverwrite);
  c = checkSavePath(FileKind::DeformedMesh, path("my_session.json"));  // foreign extension
  EXPECT_EQ(c.verdict, PathCheck::Verdict::Refuse);
  EXPECT_NE(c.message.find(".obj"), std::string::npos) << c.message;
  c = checkSavePath(FileKind::Session, path("my_session.json"));
  EXPECT_EQ(c.verdict, PathCheck::Verdict::AskOverwrite);
  c = checkSavePath(FileKind::Session, path("old.json"));
  EXPECT_EQ(c.verdict, PathCheck::Verdict::Ok);
  // Foreign content under the right extension: a session renamed .obj is never written over by a mesh.
  fs::copy_file(root / "my_session.json", root / "renamed.obj");
  c = checkSavePath(FileKind::PosedCage, path("renamed.obj"));
  EXPECT_EQ(c.verdict, PathCheck::Verdict::Refuse);
  EXPECT_NE(c.message.find("session"), std::string::npos) << c.message;
  EXPECT_EQ(checkSavePath(FileKind::Session, path("sub")).verdict, PathCheck::Verdict::Refuse);
  EXPECT_EQ(checkSavePath(FileKind::Session, path("missing/x.json")).verdict, PathCheck::Verdict::Refuse);
  EXPECT_EQ(checkSavePath(FileKind::Session, "").verdict, PathCheck::Verdict::Refuse);
  EXPECT_EQ(checkOpenPath(FileKind::Session, path("old.obj")).verdict, PathCheck::Verdict::Refuse);
  EXPECT_EQ(checkOpenPath(FileKind::Session, path("my_session.json")).verdict, PathCheck::Verdict::Ok);
}

TEST_F(Folder, TheBrowserListsFoldersThenFilesOfTheKind) {
  write("b.obj", "v 0 0 0\n");
  write("a.OBJ", "v 0 0 0\n");
  write("c.json", "{}");
  write(".hidden.obj", "v 0 0 0\n");
  std::string error;
  const std::vector<FolderEntry> list = listFolder(root.string(), ".obj", error);
  EXPECT_TRUE(error.empty());
  ASSERT_EQ(list.size(), 3u);
  EXPECT_TRUE(list[0].folder);
  EXPECT_EQ(list[0].name, "sub");
  EXPECT_EQ(list[1].name, "a.OBJ");
  EXPECT_EQ(list[2].name, "b.obj");
  EXPECT_TRUE(listFolder(path("nope"), ".obj", error).empty());
  EXPECT_FALSE(error.empty());
  std::vector<std::string> recent;
  for (const char* f : {"/a", "/b", "/a", "/c"}) noteFolder(recent, f, 2);
  EXPECT_EQ(recent, (std::vector<std::string>{"/c", "/a"}));
}

TEST_F(Folder, ExportAfterSavingASessionLeavesTheSessionIntact) {
  AppState state;
  openDemoScene(state);
  makeAChange(state);
  // Save session to my_session.json through the dialog.
  openFileDialog(state, FileDialogPurpose::SaveSession);
  state.files.dialog.name = path("my_session.json");
  ASSERT_TRUE(submitFileDialog(state));
  const std::string session = readTextFile(path("my_session.json"));
  EXPECT_FALSE(hasUnsavedChanges(state));
  // The export dialog starts with its own name, in the folder the session went to...
  openFileDialog(state, FileDialogPurpose::ExportMesh);
  EXPECT_EQ(state.files.dialog.name, "deformed.obj");
  EXPECT_EQ(state.files.dialog.folder, root.string());
  // ... and typing the session's name is refused: the session stays as it was.
  state.files.dialog.name = "my_session.json";
  EXPECT_FALSE(submitFileDialog(state));
  EXPECT_FALSE(state.files.dialog.message.empty());
  EXPECT_EQ(readTextFile(path("my_session.json")), session);
  // The export's own name works; a second export to it asks first, and only "Replace" writes.
  state.files.dialog.name = "deformed.obj";
  ASSERT_TRUE(submitFileDialog(state)) << state.files.dialog.message;
  waitForOutcome(state.jobs.exporter);  // the export runs on its worker
  ASSERT_TRUE(fs::exists(path("deformed.obj")));
  openFileDialog(state, FileDialogPurpose::ExportMesh);
  EXPECT_EQ(state.files.dialog.name, "deformed.obj");
  fs::remove(path("deformed.obj"));
  write("deformed.obj", "# placeholder\n");
  EXPECT_FALSE(submitFileDialog(state));
  EXPECT_EQ(state.files.dialog.confirmPath, path("deformed.obj"));
  EXPECT_EQ(readTextFile(path("deformed.obj")), "# placeholder\n");
  EXPECT_TRUE(submitFileDialog(state, true));
  waitForOutcome(state.jobs.exporter);
  EXPECT_NE(readTextFile(path("deformed.obj")), "# placeholder\n");
  // The session dialog kept its own name.
  openFileDialog(state, FileDialogPurpose::SaveSession);
  EXPECT_EQ(state.files.dialog.name, "my_session.json");
  cancelFileDialog(state);
}

TEST_F(Folder, QuitOpenAndDemoAskWhenThereAreUnsavedChanges) {
  AppState state;
  openDemoScene(state);
  requestQuit(state);  // nothing changed: quits at once
  EXPECT_TRUE(state.document.quitRequested);
  state.document.quitRequested = false;

  makeAChange(state);
  Autosave autosave(autosavePaths(root.c_str(), nullptr), 0.0);
  autosave.begin();
  ASSERT_TRUE(autosave.tick(makeSession(state), 1.0));
  ASSERT_TRUE(fs::exists(autosave.paths().session));

  requestQuit(state);
  ASSERT_TRUE(state.document.unsaved.asking.has_value());
  EXPECT_FALSE(state.document.quitRequested);
  answerUnsaved(state, UnsavedChoice::Cancel);
  EXPECT_FALSE(state.document.quitRequested);
  EXPECT_FALSE(state.document.unsaved.asking.has_value());
  EXPECT_TRUE(fs::exists(autosave.paths().session));  // Cancel keeps the autosave: the work is not lost

  // Opening the 2D demo: Don't save goes on and drops the changes.
  guardUnsaved(state, "open the 2D demo", [](AppState& s) { requestDemo(s, 2); });
  EXPECT_FALSE(state.loadingScene());
  answerUnsaved(state, UnsavedChoice::DontSave);
  EXPECT_TRUE(state.loadingScene());
  state.jobs.precompute.cancel();
  waitForOutcome(state.jobs.precompute);
  state.jobs.load.reset();

  // Save with no session file yet: the Save session dialog first, then the action once it saved.
  requestQuit(state);
  answerUnsaved(state, UnsavedChoice::Save);
  EXPECT_EQ(state.files.dialog.purpose, FileDialogPurpose::SaveSession);
  EXPECT_FALSE(state.document.quitRequested);
  state.files.dialog.name = path("saved.json");
  ASSERT_TRUE(submitFileDialog(state));
  EXPECT_TRUE(state.document.quitRequested);
  EXPECT_FALSE(hasUnsavedChanges(state));
  EXPECT_TRUE(fs::exists(path("saved.json")));

  // Save with a session file: saved there, then the action. Cancelling the Save dialog cancels the action.
  state.document.quitRequested = false;
  makeAChange(state);
  requestQuit(state);
  answerUnsaved(state, UnsavedChoice::Save);
  EXPECT_TRUE(state.document.quitRequested);
  EXPECT_FALSE(hasUnsavedChanges(state));
  state.document.quitRequested = false;
  state.document.path.clear();
  makeAChange(state);
  requestQuit(state);
  answerUnsaved(state, UnsavedChoice::Save);
  cancelFileDialog(state);
  EXPECT_FALSE(state.document.quitRequested);
  EXPECT_TRUE(fs::exists(autosave.paths().session));
  autosave.finish();
}

// One question at a time: an action guarded while the unsaved-changes question is open (a session dropped on the
// window, another guarded call) or while the Save session dialog its Save opened is, is refused with a status message
// that names it and the open question, and what it leaves to undo runs; the question keeps its own action, which the
// answer carries out. Before, the newer action replaced the open one, which was dropped unseen.
TEST_F(Folder, AnActionGuardedWhileTheQuestionIsOpenIsRefused) {
  AppState state;
  openDemoScene(state);
  makeAChange(state);
  write("s.json", "{}");
  requestQuit(state);
  bool ran = false, dropped = false;
  guardUnsaved(
      state, "open mesh.obj", [&ran](AppState&) { ran = true; }, [&dropped](AppState&) { dropped = true; });
  ASSERT_TRUE(state.document.unsaved.asking);
  EXPECT_EQ(state.document.unsaved.asking->what, "quit") << "the open question was replaced";
  EXPECT_FALSE(ran);
  EXPECT_TRUE(dropped);
  EXPECT_EQ(state.status.message, "not done: open mesh.obj (finish the open question first: quit)");
  openDroppedFiles(state, {path("s.json")});
  EXPECT_EQ(state.document.unsaved.asking->what, "quit");
  EXPECT_FALSE(state.jobs.session.busy()) << "the dropped session is read";
  EXPECT_EQ(state.status.message, "not done: open " + path("s.json") + " (finish the open question first: quit)");
  answerUnsaved(state, UnsavedChoice::DontSave);
  EXPECT_TRUE(state.document.quitRequested);

  state.document.quitRequested = false;
  requestQuit(state);
  answerUnsaved(state, UnsavedChoice::Save);  // no file yet: the Save session dialog
  ASSERT_TRUE(state.document.unsaved.afterSave);
  guardUnsaved(state, "open the 2D demo", [](AppState& s) { requestDemo(s, 2); });
  EXPECT_FALSE(state.loadingScene());
  EXPECT_EQ(state.status.message, "not done: open the 2D demo (finish the open question first: quit)");
  state.files.dialog.name = path("saved.json");
  ASSERT_TRUE(submitFileDialog(state));
  EXPECT_TRUE(state.document.quitRequested);
}

// Issue 24, row 6: Open with a mesh and no cage said "cage: choose a cage file", where the command line makes a cage
// for a mesh opened alone. Now it loads, with the generated cage's notice; a posed cage still needs its cage.
TEST_F(Folder, OpenTakesAMeshAlone) {
  AppState state;
  write("tetra.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  openFileDialog(state, FileDialogPurpose::OpenScene);
  state.files.dialog.mesh = path("tetra.obj");
  state.files.dialog.cage.clear();
  state.files.dialog.posed = path("tetra.obj");
  EXPECT_FALSE(submitFileDialog(state)) << "a posed cage without its cage";
  state.files.dialog.posed.clear();
  ASSERT_TRUE(submitFileDialog(state)) << state.files.dialog.message;
  EXPECT_TRUE(state.loadingScene());
  installNextOutcome(state);
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  ASSERT_TRUE(state.model.scene);
  EXPECT_EQ(state.model.scene->meshPath, path("tetra.obj"));
  EXPECT_GT(state.model.scene->restCage.numFaces(), 0);
  EXPECT_NE(state.status.message.find("cage generated"), std::string::npos) << state.status.message;
}

TEST_F(Folder, OpenFillsTheMeshThenTheCageAndARecentEntryOpensOnlyOnOk) {
  // Issue 24, row 6: a second click on a file replaced the mesh instead of filling the cage slot, and one click on
  // a Recent entry opened it at once.
  AppState state;
  openDemoScene(state);
  openFileDialog(state, FileDialogPurpose::OpenScene);
  state.files.dialog.folder = root.string();
  chooseSceneFile(state.files.dialog, "mesh.obj");
  chooseSceneFile(state.files.dialog, "cage.obj");
  EXPECT_EQ(state.files.dialog.mesh, path("mesh.obj"));
  EXPECT_EQ(state.files.dialog.cage, path("cage.obj"));
  chooseSceneFile(state.files.dialog, "other_cage.obj");  // the cage field stays the target once the mesh is there
  EXPECT_EQ(state.files.dialog.mesh, path("mesh.obj"));
  EXPECT_EQ(state.files.dialog.cage, path("other_cage.obj"));
  cancelFileDialog(state);

  // A saved session is a Recent entry at once; one click on it in Open chooses it and opens nothing ...
  openFileDialog(state, FileDialogPurpose::SaveSession);
  state.files.dialog.name = path("s.json");
  ASSERT_TRUE(submitFileDialog(state)) << state.files.dialog.message;
  ASSERT_FALSE(state.files.recent.entries().empty());
  const RecentEntry entry = state.files.recent.entries().front();
  ASSERT_EQ(entry.kind, RecentEntry::Kind::Session);
  openFileDialog(state, FileDialogPurpose::OpenScene);
  chooseRecent(state.files.dialog, entry);
  EXPECT_EQ(state.files.dialog.purpose, FileDialogPurpose::OpenScene);
  EXPECT_EQ(state.status.message.find("opened session"), std::string::npos) << state.status.message;
  // ... and OK (or a double click, which submits the same way) opens it (the same scene: applied once read).
  ASSERT_TRUE(submitFileDialog(state));
  EXPECT_EQ(state.files.dialog.purpose, FileDialogPurpose::None);
  finishSessionRead(state);  // read on its job, then applied
  EXPECT_NE(state.status.message.find("opened session"), std::string::npos) << state.status.message;
  EXPECT_EQ(fs::path(state.document.path), fs::path(path("s.json")));
}

// Issue 24, row 14: Save and Export started where the scene was opened from, the read-only models folder, and the
// Export animation dialog showed a bare file name. A dialog that writes starts in a writable folder: its kind's
// last one while writable, else the session's folder, else the working folder; Export animation's path is whole.
// (A folder that does not exist stands in for the read-only one: this test may run as root, who can write anywhere.)
TEST_F(Folder, SaveAndExportStartInAWritableFolderWithFullPaths) {
  AppState state;
  openDemoScene(state);
  const std::string readOnly = path("models/firehydrant");  // never created
  state.files.dialog.recentFolders = {readOnly};                  // the scene came from there
  state.files.dialog.places[static_cast<std::size_t>(FileKind::PosedCage)] = {readOnly, "posed.obj"};
  ASSERT_FALSE(folderWritable(readOnly));
  ASSERT_TRUE(folderWritable(root.string()));
  const std::string cwd = fs::current_path().string();
  ASSERT_TRUE(folderWritable(cwd));
  for (FileDialogPurpose purpose : {FileDialogPurpose::SaveSession, FileDialogPurpose::ExportMesh,
                                    FileDialogPurpose::SavePose, FileDialogPurpose::Screenshot}) {
    openFileDialog(state, purpose);
    EXPECT_EQ(state.files.dialog.folder, cwd) << purposeTitle(purpose);
    cancelFileDialog(state);
  }
  // Reading still starts where the last file came from.
  openFileDialog(state, FileDialogPurpose::LoadPose);
  EXPECT_EQ(state.files.dialog.folder, readOnly);
  cancelFileDialog(state);

  // With a session saved in a writable folder, that folder; a writable folder the kind used last wins.
  openFileDialog(state, FileDialogPurpose::SaveSession);
  state.files.dialog.name = path("sub/s.json");
  ASSERT_TRUE(submitFileDialog(state)) << state.files.dialog.message;
  openFileDialog(state, FileDialogPurpose::ExportMesh);
  EXPECT_EQ(state.files.dialog.folder, path("sub"));
  cancelFileDialog(state);
  EXPECT_EQ(defaultWriteFolder(state), path("sub"));
  state.files.dialog.places[static_cast<std::size_t>(FileKind::DeformedMesh)] = {root.string(), "d.obj"};
  openFileDialog(state, FileDialogPurpose::ExportMesh);
  EXPECT_EQ(state.files.dialog.folder, root.string());
  cancelFileDialog(state);

  // Export animation: a bare name becomes a path in the session's folder; a whole path stays as typed.
  EXPECT_EQ(writePath(state, "animation.glb"), path("sub/animation.glb"));
  EXPECT_EQ(writePath(state, "/tmp/x/a.glb"), "/tmp/x/a.glb");
  const AppState fresh;  // no session: the working folder
  EXPECT_TRUE(fs::path(writePath(fresh, "animation.glb")).is_absolute());
}
