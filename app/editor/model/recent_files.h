// The Open panel's recent files: the last opened (mesh, cage, posed cage) triples and sessions, most recent first,
// without duplicates. Pure (text in, text out); loadRecentFiles / saveRecentFiles do the file I/O.
//
// File format (recent.txt, UTF-8, one entry a line, fields separated by tabs, most recent first):
//   somicage-recent 1
//   files<TAB>MESH<TAB>CAGE<TAB>POSED      (POSED may be empty)
//   session<TAB>PATH
// Blank lines, '#' comments and malformed lines are ignored.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace somicage::editor {

struct RecentEntry {
  enum class Kind { Files, Session };
  Kind kind = Kind::Files;
  std::string mesh, cage, posed;  // Files (posed may be empty)
  std::string session;            // Session

  static RecentEntry files(std::string mesh, std::string cage, std::string posed = "");
  static RecentEntry sessionFile(std::string path);
  std::vector<std::string> paths() const;  // the non-empty paths
  std::string label() const;               // file names only: "bunny.obj + bunny_cage.obj (+ pose.obj)"
  // Whether it can be stored: required paths present, no tab or line break in any path.
  bool valid() const;
  bool operator==(const RecentEntry& o) const {
    return kind == o.kind && mesh == o.mesh && cage == o.cage && posed == o.posed && session == o.session;
  }
};

class RecentFiles {
 public:
  static constexpr std::size_t kMaxEntries = 10;

  // Puts `entry` first, removing an equal older entry and dropping the oldest beyond kMaxEntries. Invalid entries
  // are ignored (returns false).
  bool add(const RecentEntry& entry);
  const std::vector<RecentEntry>& entries() const { return entries_; }

  std::string toText() const;
  // Never throws: unknown, incomplete or duplicate lines are skipped; at most kMaxEntries are kept.
  static RecentFiles fromText(const std::string& text);

 private:
  std::vector<RecentEntry> entries_;  // most recent first
};

// $XDG_CONFIG_HOME/somicage/recent.txt, else $HOME/.config/somicage/recent.txt; "" (keep the list in memory) when
// neither is set. Arguments may be null (getenv results); empty counts as unset.
std::string recentFilesPath(const char* xdgConfigHome, const char* home);

// The first of the entry's files that does not exist ("" when all do): File > Open Recent and the Open panel grey
// such an entry out and name the file.
std::string missingRecentPath(const RecentEntry& entry);

// An empty list when `path` is empty, missing, unreadable or malformed: never an error.
RecentFiles loadRecentFiles(const std::string& path);
// Creates the folder when needed and writes atomically (file_util.h). Throws InputError on failure.
void saveRecentFiles(const std::string& path, const RecentFiles& recent);

}  // namespace somicage::editor
