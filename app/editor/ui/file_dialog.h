// The File menu's dialogs: per-kind state (each kind of file keeps its own folder and name, file_rules.h), the
// checks and actions of OK (submitFileDialog, no ImGui: unit-tested), and the modal with the in-app file
// browser (drawFileDialog: folders, files filtered by the kind's extension, parent / home / recent folders, and
// a typed path that always works).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "model/file_rules.h"
#include "model/recent_files.h"

namespace somicage::editor {

struct AppState;

enum class FileDialogPurpose { None, OpenScene, LoadPose, SavePose, ExportMesh, OpenSession, SaveSession, Screenshot };

FileKind purposeKind(FileDialogPurpose purpose);
bool purposeWrites(FileDialogPurpose purpose);
const char* purposeTitle(FileDialogPurpose purpose);  // "Export deformed mesh"

struct FilePlace {
  std::string folder;  // absolute; "" = not used yet (the current folder)
  std::string name;    // file name in it; "" = the kind's default name
};

struct FileDialogState {
  FileDialogPurpose purpose = FileDialogPurpose::None;
  bool justOpened = false;
  std::array<FilePlace, kFileKindCount> places;  // per FileKind
  std::string folder;                            // the folder the browser shows
  std::string name;                              // the file name (or typed path) of the open dialog
  FileKind sceneField = FileKind::Mesh;          // Open mesh + cage: the field the browser fills
  std::string mesh, cage, posed;                 // Open mesh + cage
  std::optional<RecentEntry> recentChoice;       // Open: the Recent entry one click chose (OK or a double click opens)
  std::vector<std::string> recentFolders;        // most recent first
  std::string message;                           // why OK was refused, or the overwrite question
  std::string confirmPath;                       // the path the overwrite question is about
};

// Where a file the editor writes goes by default: the session's folder, else the working folder, else the home
// folder, the first of them that is writable (a scene opened from a read-only models folder must not send Save
// and Export there); "" when none is.
std::string defaultWriteFolder(const AppState& state);
// A path typed for writing, made whole: a relative one lies in defaultWriteFolder (the dialogs show full paths).
std::string writePath(const AppState& state, const std::string& path);

// Opens a dialog in its kind's last folder with its last (or default) name. A dialog that writes starts in its
// kind's last folder only while that is writable, else in defaultWriteFolder.
void openFileDialog(AppState& state, FileDialogPurpose purpose);
// The path OK acts on: `name` when it is absolute (a typed path), else folder / name.
std::string dialogPath(const FileDialogState& dialog, const std::string& name);
// OK: checks the path (file_rules.h) and carries the action out. Returns true when the dialog closed. A refusal
// or the overwrite question (unless `overwriteConfirmed`) leaves it open with dialog.message set.
bool submitFileDialog(AppState& state, bool overwriteConfirmed = false);
void cancelFileDialog(AppState& state);
// Open mesh + cage, a click on a file of the browser: it fills the field the browser targets; after the mesh, the
// next click fills the cage while the cage is empty (a click, then a second click, as in the steps).
void chooseSceneFile(FileDialogState& dialog, const std::string& name);
// Open, a click on a Recent entry: chosen (highlighted, its files in the fields), not opened; OK or a double click
// opens it.
void chooseRecent(FileDialogState& dialog, const RecentEntry& entry);

void drawFileDialog(AppState& state);

}  // namespace somicage::editor
