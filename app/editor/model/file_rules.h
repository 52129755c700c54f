// The rules of the editor's file dialogs, apart from any window: which kinds of file there are (each with its
// own extension and default name), what a path may be saved over, what may be opened, and the folder listing
// of the in-app file browser. Pure file-system logic, unit-tested without a window (file_dialog.h draws it).
//
// A write is refused when the path ends in another kind's extension or when the file already there holds
// another kind of content (a mesh is never written over a session JSON, whatever its name); writing over a file
// of the same kind asks first.
#pragma once

#include <string>
#include <vector>

namespace somicage::editor {

// What a file holds, judged from its first bytes (not its name).
enum class FileContent { Missing, Folder, Session, Obj, Png, Other };
FileContent sniffFileContent(const std::string& path);
const char* fileContentName(FileContent content);  // "a session", "an OBJ mesh", ...

// The kinds of file the editor reads or writes; each dialog keeps its own folder and name per kind.
enum class FileKind { Mesh, Cage, PosedCage, DeformedMesh, Session, Screenshot };
constexpr int kFileKindCount = 6;

struct FileKindInfo {
  const char* title;        // "posed cage"
  const char* extension;    // ".obj", lower case
  const char* defaultName;  // "posed_cage.obj"
  FileContent content;      // what such a file holds
};
const FileKindInfo& fileKindInfo(FileKind kind);

struct PathCheck {
  enum class Verdict { Ok, AskOverwrite, Refuse };
  Verdict verdict = Verdict::Refuse;
  std::string path;     // the path to use (the kind's extension appended when the name had none)
  std::string message;  // why it is refused, or the overwrite question
};

// May `path` be written as `kind`? Ok (new file), AskOverwrite (a file of the same kind is there), or Refuse
// (empty name, a folder, a missing parent folder, a foreign extension, or foreign content already there).
PathCheck checkSavePath(FileKind kind, const std::string& path);
// May `path` be opened as `kind`? Ok, or Refuse (missing, a folder, a foreign extension).
PathCheck checkOpenPath(FileKind kind, const std::string& path);

// One folder of the file browser: sub-folders first, then the files ending in `extension` (case-insensitive),
// each group sorted by name; hidden entries (".name") left out. `error` is set (and the list empty) when the
// folder cannot be read.
struct FolderEntry {
  std::string name;
  bool folder = false;
};
std::vector<FolderEntry> listFolder(const std::string& folder, const std::string& extension, std::string& error);

// Whether files can be created in `folder` (an existing folder this process may write: not the read-only models
// folder, not a read-only file system).
bool folderWritable(const std::string& folder);
// The first of `candidates` that is writable ("" when none is).
std::string firstWritableFolder(const std::vector<std::string>& candidates);

// Remembers a folder at the front of a most-recent-first list of at most `limit` entries.
void noteFolder(std::vector<std::string>& folders, const std::string& folder, std::size_t limit = 8);

}  // namespace somicage::editor
