#include "model/recent_files.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <utility>

#include "base/errors.h"
#include "base/file_util.h"

namespace somicage::editor {

namespace {

constexpr const char* kHeader = "somicage-recent 1";

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

bool storable(const std::string& path) { return path.find_first_of("\t\r\n") == std::string::npos; }

std::vector<std::string> splitTabs(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t tab = line.find('\t', start);
    fields.push_back(line.substr(start, tab == std::string::npos ? std::string::npos : tab - start));
    if (tab == std::string::npos) return fields;
    start = tab + 1;
  }
}

}  // namespace

RecentEntry RecentEntry::files(std::string mesh, std::string cage, std::string posed) {
  RecentEntry e;
  e.kind = Kind::Files;
  e.mesh = std::move(mesh);
  e.cage = std::move(cage);
  e.posed = std::move(posed);
  return e;
}

RecentEntry RecentEntry::sessionFile(std::string path) {
  RecentEntry e;
  e.kind = Kind::Session;
  e.session = std::move(path);
  return e;
}

std::vector<std::string> RecentEntry::paths() const {
  std::vector<std::string> out;
  for (const std::string* p : {&mesh, &cage, &posed, &session}) {
    if (!p->empty()) out.push_back(*p);
  }
  return out;
}

std::string RecentEntry::label() const {
  if (kind == Kind::Session) return "session " + fileName(session);
  std::string text = fileName(mesh) + " + " + fileName(cage);
  if (!posed.empty()) text += " (+ " + fileName(posed) + ")";
  return text;
}

bool RecentEntry::valid() const {
  if (kind == Kind::Session) {
    return !session.empty() && mesh.empty() && cage.empty() && posed.empty() && storable(session);
  }
  return !mesh.empty() && !cage.empty() && session.empty() && storable(mesh) && storable(cage) && storable(posed);
}

bool RecentFiles::add(const RecentEntry& entry) {
  if (!entry.valid()) return false;
  entries_.erase(std::remove(entries_.begin(), entries_.end(), entry), entries_.end());
  entries_.insert(entries_.begin(), entry);
  if (entries_.size() > kMaxEntries) entries_.resize(kMaxEntries);
  return true;
}

std::string RecentFiles::toText() const {
  std::ostringstream out;
  out << kHeader << '\n';
  for (const RecentEntry& e : entries_) {
    if (e.kind == RecentEntry::Kind::Session) {
      out << "session\t" << e.session << '\n';
    } else {
      out << "files\t" << e.mesh << '\t' << e.cage << '\t' << e.posed << '\n';
    }
  }
  return out.str();
}

RecentFiles RecentFiles::fromText(const std::string& text) {
  RecentFiles recent;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line) && recent.entries_.size() < kMaxEntries) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#' || line == kHeader) continue;
    const std::vector<std::string> f = splitTabs(line);
    RecentEntry e;
    if (f[0] == "session" && f.size() == 2) {
      e = RecentEntry::sessionFile(f[1]);
    } else if (f[0] == "files" && (f.size() == 3 || f.size() == 4)) {
      e = RecentEntry::files(f[1], f[2], f.size() == 4 ? f[3] : "");
    } else {
      continue;
    }
    // The file is most recent first: a later duplicate is an older copy.
    if (!e.valid() || std::find(recent.entries_.begin(), recent.entries_.end(), e) != recent.entries_.end()) continue;
    recent.entries_.push_back(std::move(e));
  }
  return recent;
}

std::string recentFilesPath(const char* xdgConfigHome, const char* home) {
  // The XDG base directory spec: a relative $XDG_CONFIG_HOME is invalid and must be ignored.
  if (xdgConfigHome && xdgConfigHome[0] == '/') return std::string(xdgConfigHome) + "/somicage/recent.txt";
  if (home && home[0] != '\0') return std::string(home) + "/.config/somicage/recent.txt";
  return "";
}

std::string missingRecentPath(const RecentEntry& entry) {
  for (const std::string& path : entry.paths()) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return path;
  }
  return "";
}

RecentFiles loadRecentFiles(const std::string& path) {
  if (path.empty()) return {};
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream ss;
  ss << in.rdbuf();
  return RecentFiles::fromText(ss.str());
}

void saveRecentFiles(const std::string& path, const RecentFiles& recent) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (!folder.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw InputError(path, -1, "cannot create the folder: " + ec.message(), "check the permissions");
  }
  writeFileAtomic(path, recent.toText());
}

}  // namespace somicage::editor
