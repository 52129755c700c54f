#include "model/file_rules.h"

#include <unistd.h>  // access

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>
#include <utility>

#include "interaction/drop.h"

namespace somicage::editor {

namespace fs = std::filesystem;

namespace {

constexpr FileKindInfo kKinds[kFileKindCount] = {
    {"mesh", ".obj", "mesh.obj", FileContent::Obj},
    {"cage", ".obj", "cage.obj", FileContent::Obj},
    {"posed cage", ".obj", "posed_cage.obj", FileContent::Obj},
    {"deformed mesh", ".obj", "deformed.obj", FileContent::Obj},
    {"session", ".json", "session.json", FileContent::Session},
    {"screenshot", ".png", "screenshot.png", FileContent::Png},
};

// The first bytes of a file, up to `limit`.
std::string head(const std::string& path, std::size_t limit) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(limit, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(limit));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

// OBJ: every non-blank line of the head starts with a known OBJ statement or a comment.
bool looksLikeObj(const std::string& text) {
  static const char* const kStatements[] = {"v ", "vt ", "vn ",     "vp ",     "f ", "l ",  "p ", "o ",
                                            "g ", "s ",  "mtllib ", "usemtl ", "#",  "v\t", "f\t"};
  std::size_t start = 0, recognised = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    const bool complete = end != std::string::npos;
    if (!complete) end = text.size();
    std::string line = text.substr(start, end - start);
    line.erase(0, line.find_first_not_of(" \t\r"));
    start = end + 1;
    if (line.empty() || !complete) continue;  // the last, cut-off line of the head says nothing
    const bool known = std::any_of(std::begin(kStatements), std::end(kStatements),
                                   [&](const char* s) { return line.rfind(s, 0) == 0; });
    if (!known) return false;
    ++recognised;
  }
  return recognised > 0;
}

PathCheck refuse(std::string path, std::string message) {
  return {PathCheck::Verdict::Refuse, std::move(path), std::move(message)};
}

// Appends the kind's extension to a name without one; refuses another known extension.
bool resolveExtension(FileKind kind, std::string& path, std::string& message) {
  const FileKindInfo& info = fileKindInfo(kind);
  const std::string ext = lowerExtension(path);
  if (ext.empty()) {
    path += info.extension;
    return true;
  }
  if (ext == info.extension) return true;
  message = "'" + path + "' ends in " + ext + ", but a " + info.title + " is a " + info.extension +
            " file: choose a name ending in " + info.extension;
  return false;
}

}  // namespace

const char* fileContentName(FileContent content) {
  switch (content) {
    case FileContent::Missing:
      return "nothing";
    case FileContent::Folder:
      return "a folder";
    case FileContent::Session:
      return "a SomiCage session";
    case FileContent::Obj:
      return "an OBJ mesh";
    case FileContent::Png:
      return "a PNG image";
    case FileContent::Other:
      return "data of another kind";
  }
  return "?";
}

FileContent sniffFileContent(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) return FileContent::Missing;
  if (fs::is_directory(status)) return FileContent::Folder;
  const std::string bytes = head(path, 4096);
  if (bytes.rfind("\x89PNG", 0) == 0) return FileContent::Png;
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && bytes[first] == '{') {
    return bytes.find("somicage-session") != std::string::npos ? FileContent::Session : FileContent::Other;
  }
  if (bytes.empty() || looksLikeObj(bytes)) return FileContent::Obj;  // an empty file holds nothing to lose
  return FileContent::Other;
}

const FileKindInfo& fileKindInfo(FileKind kind) { return kKinds[static_cast<int>(kind)]; }

PathCheck checkSavePath(FileKind kind, const std::string& typed) {
  const FileKindInfo& info = fileKindInfo(kind);
  std::string path = typed;
  std::string message;
  if (path.empty() || path.back() == '/') return refuse(path, std::string("type a file name for the ") + info.title);
  std::error_code ec;
  if (fs::is_directory(path, ec)) return refuse(path, "'" + path + "' is a folder: type a file name in it");
  if (!resolveExtension(kind, path, message)) return refuse(path, message);
  const fs::path parent = fs::path(path).parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec))
    return refuse(path, "the folder '" + parent.string() + "' does not exist: create it or choose another one");
  const FileContent there = sniffFileContent(path);
  if (there == FileContent::Missing) return {PathCheck::Verdict::Ok, path, ""};
  if (there != info.content) {
    return refuse(path, "'" + path + "' holds " + fileContentName(there) + ", not " + fileContentName(info.content) +
                            ": it is not overwritten. Choose another name");
  }
  return {PathCheck::Verdict::AskOverwrite, path, "'" + path + "' exists. Replace it?"};
}

PathCheck checkOpenPath(FileKind kind, const std::string& path) {
  const FileKindInfo& info = fileKindInfo(kind);
  if (path.empty()) return refuse(path, std::string("choose a ") + info.title + " file");
  const FileContent there = sniffFileContent(path);
  if (there == FileContent::Missing) return refuse(path, "'" + path + "' does not exist");
  if (there == FileContent::Folder) return refuse(path, "'" + path + "' is a folder: choose a file in it");
  if (lowerExtension(path) != info.extension)
    return refuse(path, "'" + path + "' is not a " + info.extension + " file (a " + info.title + " is)");
  return {PathCheck::Verdict::Ok, path, ""};
}

std::vector<FolderEntry> listFolder(const std::string& folder, const std::string& extension, std::string& error) {
  std::vector<FolderEntry> folders, files;
  error.clear();
  std::error_code ec;
  fs::directory_iterator it(folder.empty() ? "." : folder, fs::directory_options::skip_permission_denied, ec);
  if (ec) {
    error = "cannot read the folder '" + folder + "': " + ec.message();
    return {};
  }
  for (const fs::directory_entry& entry : it) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name[0] == '.') continue;
    std::error_code typeError;
    if (entry.is_directory(typeError)) {
      folders.push_back({name, true});
    } else if (lowerExtension(name) == extension) {
      files.push_back({name, false});
    }
  }
  const auto byName = [](const FolderEntry& a, const FolderEntry& b) { return a.name < b.name; };
  std::sort(folders.begin(), folders.end(), byName);
  std::sort(files.begin(), files.end(), byName);
  folders.insert(folders.end(), files.begin(), files.end());
  return folders;
}

bool folderWritable(const std::string& folder) {
  std::error_code ec;
  return !folder.empty() && fs::is_directory(folder, ec) && ::access(folder.c_str(), W_OK) == 0;
}

std::string firstWritableFolder(const std::vector<std::string>& candidates) {
  for (const std::string& folder : candidates)
    if (folderWritable(folder)) return folder;
  return "";
}

void noteFolder(std::vector<std::string>& folders, const std::string& folder, std::size_t limit) {
  if (folder.empty()) return;
  folders.erase(std::remove(folders.begin(), folders.end(), folder), folders.end());
  folders.insert(folders.begin(), folder);
  if (folders.size() > limit) folders.resize(limit);
}

}  // namespace somicage::editor
