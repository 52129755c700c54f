// Crash safety: the editor writes its session (session.h) to an autosave file every few seconds when something
// changed, next to a marker that says "an editor is running (pid)". A clean exit removes both; a crash leaves
// them, and the next start finds an autosave whose marker names a process that is gone, and offers to restore it.
// Pure file logic, no GL (the Restore / Discard modal is in panels.cpp).
//
// Files, in $XDG_CONFIG_HOME/somicage/ (else $HOME/.config/somicage/):
//   autosave.json      the session, written atomically (file_util.h)
//   autosave.running   "somicage-autosave 1\npid N\n" while an editor runs
//   autosave.json.bad  a malformed autosave, set aside so that it is reported once and never blocks a start
#pragma once

#include <optional>
#include <string>

#include "engine/session.h"

namespace somicage::editor {

struct AutosavePaths {
  std::string session;  // autosave.json
  std::string marker;   // autosave.running
};

// The paths in $XDG_CONFIG_HOME/somicage (an absolute XDG_CONFIG_HOME only), else $HOME/.config/somicage; empty
// paths (autosave off) when neither is set. Arguments may be null (getenv results).
AutosavePaths autosavePaths(const char* xdgConfigHome, const char* home);

// What the previous run left behind, found at start.
struct AutosaveLeftover {
  std::optional<Session> session;   // a crashed run's session, ready to restore
  std::string savedAt;              // its local time, "2026-11-23 19:40"
  std::string error;                // a malformed autosave (now renamed .bad), or a file problem; "" when none
  bool otherEditorRunning = false;  // the marker names a live process: this editor does not autosave
};

// Reads what the previous run left, without writing anything but the .bad rename. Never throws.
AutosaveLeftover findAutosaveLeftover(const AutosavePaths& paths);

class Autosave {
 public:
  static constexpr double kDefaultIntervalSeconds = 30.0;

  explicit Autosave(AutosavePaths paths, double intervalSeconds = kDefaultIntervalSeconds);

  // At start: findAutosaveLeftover, then writes this process's marker, unless another live editor holds it. Never
  // throws: problems go to `error`.
  AutosaveLeftover begin();

  // Every frame, with a steady clock: once intervalSeconds have passed since the last save (or the first tick),
  // writes the session when its JSON differs from the last one written. Returns true when it wrote. Throws InputError
  // when the write fails (it tries again one interval later). No-op when disabled (no paths, or another editor
  // running).
  bool tick(const Session& session, double nowSeconds);

  // Clean exit: removes the autosave and the marker.
  void finish();

  bool enabled() const { return enabled_; }
  const AutosavePaths& paths() const { return paths_; }

 private:
  AutosavePaths paths_;
  double interval_;
  bool enabled_ = false;
  std::optional<double> lastSave_;  // the time of the last save, or of the first tick
  std::string lastJson_;
};

}  // namespace somicage::editor
