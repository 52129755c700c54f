#include "model/autosave.h"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <system_error>
#include <utility>

#include "base/errors.h"
#include "base/file_util.h"

namespace somicage::editor {

namespace {

const char* const kMarkerHeader = "somicage-autosave 1";

// The pid a marker names; nullopt when it cannot be read.
std::optional<long> markerPid(const std::string& path) {
  std::ifstream in(path);
  std::string header, key;
  long pid = 0;
  if (!std::getline(in, header) || header != kMarkerHeader || !(in >> key >> pid) || key != "pid" || pid <= 0)
    return std::nullopt;
  return pid;
}

// Whether another process with this pid exists (EPERM: it exists but belongs to someone else). This process's own
// pid cannot be another editor: a marker naming it was left by an earlier process that had the same pid.
bool otherProcessAlive(long pid) {
  if (pid == static_cast<long>(::getpid())) return false;
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

std::string modificationTime(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return "an unknown time";
  std::tm local{};
  localtime_r(&info.st_mtime, &local);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M", &local);
  return text;
}

}  // namespace

AutosavePaths autosavePaths(const char* xdgConfigHome, const char* home) {
  std::string folder;
  // The XDG base directory spec: a relative $XDG_CONFIG_HOME is invalid and must be ignored.
  if (xdgConfigHome && xdgConfigHome[0] == '/')
    folder = std::string(xdgConfigHome) + "/somicage/";
  else if (home && home[0] != '\0')
    folder = std::string(home) + "/.config/somicage/";
  else
    return {};
  return {folder + "autosave.json", folder + "autosave.running"};
}

Autosave::Autosave(AutosavePaths paths, double intervalSeconds)
    : paths_(std::move(paths)), interval_(intervalSeconds) {}

AutosaveLeftover findAutosaveLeftover(const AutosavePaths& paths) {
  AutosaveLeftover leftover;
  namespace fs = std::filesystem;
  std::error_code ec;
  if (paths.session.empty() || !fs::exists(paths.marker, ec)) return leftover;
  const std::optional<long> pid = markerPid(paths.marker);
  if (pid && otherProcessAlive(*pid)) {
    leftover.otherEditorRunning = true;  // its autosave is its own business
    return leftover;
  }
  // A marker of a process that is gone: that editor crashed. Its autosave, if any, is worth offering.
  if (fs::exists(paths.session, ec)) {
    leftover.savedAt = modificationTime(paths.session);
    try {
      leftover.session = loadSession(paths.session);
    } catch (const std::exception& e) {
      const std::string bad = paths.session + ".bad";
      fs::rename(paths.session, bad, ec);
      leftover.error = std::string("the autosave of the last session cannot be restored: ") + e.what() +
                       (ec ? "" : "; it was set aside as " + bad);
    }
  }
  return leftover;
}

AutosaveLeftover Autosave::begin() {
  AutosaveLeftover leftover = findAutosaveLeftover(paths_);
  if (paths_.session.empty() || leftover.otherEditorRunning) return leftover;
  namespace fs = std::filesystem;
  std::error_code ec;
  try {
    fs::create_directories(fs::path(paths_.marker).parent_path(), ec);
    writeFileAtomic(paths_.marker, std::string(kMarkerHeader) + "\npid " + std::to_string(::getpid()) + "\n");
    enabled_ = true;
  } catch (const InputError& e) {
    leftover.error += std::string(leftover.error.empty() ? "" : "\n") + "autosave is off: " + e.what();
  }
  return leftover;
}

bool Autosave::tick(const Session& session, double nowSeconds) {
  if (!enabled_) return false;
  if (!lastSave_) lastSave_ = nowSeconds;
  if (nowSeconds - *lastSave_ < interval_) return false;
  lastSave_ = nowSeconds;
  std::string json = sessionToJson(session);
  if (json == lastJson_) return false;
  writeFileAtomic(paths_.session, json);
  lastJson_ = std::move(json);
  return true;
}

void Autosave::finish() {
  if (!enabled_) return;
  std::remove(paths_.session.c_str());
  std::remove(paths_.marker.c_str());
  enabled_ = false;
}

}  // namespace somicage::editor
