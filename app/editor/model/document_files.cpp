// Files: sessions, posed cages, dropped and recent files, the crash-recovery offer.
#include <exception>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "base/file_util.h"
#include "engine/engine.h"
#include "interaction/drop.h"
#include "io/obj_io.h"
#include "jobs/session_read.h"
#include "model/app_state.h"

namespace somicage::editor {

Session makeSession(const AppState& state) {
  Session s;
  if (state.model.scene) {
    s.meshPath = state.model.scene->meshPath;
    s.cagePath = state.model.scene->cagePath;
    s.demoDim = state.model.scene->dim();
    if (s.cagePath.empty()) s.restCage = state.model.scene->restCage;  // no file holds it: the session does
  }
  s.pose = state.document.pose;
  s.method = state.document.method;
  s.methodOptions = state.singleView().options;
  s.params = state.document.params;
  s.compare = state.view.compare;
  s.compareViews = state.view.compareViews;
  s.camera = state.view.camera.state();
  s.poses = state.animation.poses;
  s.timeline = state.animation.timeline;
  return s;
}

void applySessionSettings(AppState& state, const Session& s) {
  state.animation.poses = s.poses;
  state.animation.timeline = s.timeline;
  // The frame cursor starts at the session's range, as Blender's at its scene's start (the session keeps no cursor).
  state.animation.playing = false;
  state.animation.frame = s.timeline.firstFrame;
  if (!s.poses.poses().empty() || !s.timeline.keys.empty()) state.animation.showPanels = true;
  state.document.method = s.method;
  state.view.methodOptions = s.methodOptions;
  state.document.params = s.params;
  state.view.compare = s.compare;
  if (!s.compareViews.empty()) state.view.compareViews = s.compareViews;
}

std::vector<ViewSpec> sessionViews(const AppState& state, const Session& s) {
  return shownViews(s.compare, s.compareViews.empty() ? state.view.compareViews : s.compareViews,
                    singleViewOf(s.method, s.methodOptions));
}

void applySession(AppState& state, const Session& s, PendingLoad load) {
  const bool inlineCage = s.restCage.numVertices() > 0;
  const bool sameScene = state.model.scene && !state.loadingScene() &&
                         samePath(state.model.scene->meshPath, s.meshPath) &&
                         samePath(state.model.scene->cagePath, s.cagePath) &&
                         (!s.meshPath.empty() || state.model.scene->dim() == s.demoDim) &&
                         (!inlineCage || sameCage(state.model.scene->restCage, s.restCage));
  if (sameScene) {
    applySessionSettings(state, s);
    if (s.pose.rows() == state.document.pose.rows() && s.pose.cols() == state.document.pose.cols())
      setPose(state, s.pose);
    commitEdit(state, "Load session");
    state.view.camera.setState(s.camera);
    state.model.deformDirty = true;
    ensureDeformers(state);
    return;
  }
  if (s.pose.rows() > 0) load.pose = s.pose;
  load.session = s;  // its settings are applied with its scene (showLoadedScene)
  if (inlineCage) {
    requestLoad(
        state,
        [mesh = s.meshPath, cage = s.restCage, notices = s.cageNotices]() {
          Scene scene = loadSceneWithCage(mesh, cage, "the session's cage");
          for (const Notice& n : notices) scene.notices.push_back(sceneNotice(n));
          return scene;
        },
        std::move(load));
  } else if (s.meshPath.empty()) {
    requestDemo(state, s.demoDim, std::move(load));
  } else {  // the session is the recent entry, not its files
    requestLoad(
        state, [mesh = s.meshPath, cage = s.cagePath]() { return loadScene(mesh, cage); }, std::move(load));
  }
}

void acceptRestoreOffer(AppState& state) {
  if (!state.files.restoreOffer) return;
  PendingLoad load;
  load.restored = true;
  applySession(state, *state.files.restoreOffer, std::move(load));
  state.status.message = "restored the session from " + state.files.restoreOfferTime;
  state.files.restoreOffer.reset();
}

void discardRestoreOffer(AppState& state) { state.files.restoreOffer.reset(); }

bool savePosedCage(AppState& state, const std::string& path) {
  if (!state.model.scene) return false;
  try {
    Cage posed = state.model.scene->restCage;
    posed.vertices = state.document.pose;
    saveObj(path, state.document.pose, cageTopology(posed));
    state.status.message = "saved posed cage " + path;
    return true;
  } catch (const std::exception& e) {
    state.status.errors.push_back(e.what());
    return false;
  }
}

namespace {

// Runs read against the scene shown on the posed-cage job (superseding one running); pollPosedCage applies it.
void startPosedCageRead(AppState& state, std::function<PosedCageRead(const Scene&)> read) {
  state.jobs.posedCage.start(
      [scene = state.model.scene, read = std::move(read)](JobContext&) { return PosedCageLoad{scene, read(*scene)}; },
      1);
}

}  // namespace

bool loadPosedCage(AppState& state, const std::string& path) {
  if (!state.model.scene) return false;
  startPosedCageRead(state, [path](const Scene& scene) { return readPosedCage(path, scene.restCage); });
  state.status.message = "reading posed cage " + path;
  return true;
}

bool pollPosedCage(AppState& state) {
  std::optional<PosedCageLoad> load = state.jobs.posedCage.poll();
  if (!load) return false;
  const std::string& path = load->read.path;
  if (load->scene != state.model.scene || state.loadingScene()) {
    state.status.errors.push_back(path + " was not applied: another scene was opened while it was read; load it again");
    return false;
  }
  if (!load->read.pose) {
    state.status.errors.push_back(load->read.error);
    return false;
  }
  setPose(state, *load->read.pose);
  commitEdit(state, "Load posed cage");
  state.status.message = "loaded pose " + path;
  if (!state.model.scene->isDemo())
    noteRecent(state, RecentEntry::files(state.model.scene->meshPath, state.model.scene->cagePath, path));
  return true;
}

bool saveSessionFile(AppState& state, const std::string& path) {
  try {
    saveSession(path, makeSession(state));
    state.document.path = path;
    state.document.history.markSaved();
    state.status.message = "saved session " + path;
    noteRecent(state, RecentEntry::sessionFile(path));  // File > Open Recent lists it at once
    return true;
  } catch (const std::exception& e) {
    state.status.errors.push_back(e.what());
    return false;
  }
}

void loadSessionFile(AppState& state, const std::string& path, SessionReader read) {
  state.jobs.session.start(
      [path, read = std::move(read)](JobContext& context) { return readSessionOnJob(path, read, context); }, 1);
  state.jobs.sessionFrom = state.document.history.revision();  // what the user agreed to discard
  state.status.message = "reading session " + path;
}

namespace {

// Applies a session read from `path` (applySession): the document becomes the session's, opened clean.
bool openReadSession(AppState& state, const std::string& path, const Session& session) {
  try {
    PendingLoad load;
    load.documentPath = path;
    applySession(state, session, std::move(load));
    if (!state.loadingScene()) {  // the same scene: applied at once, as an edit
      state.document.path = path;
      state.document.history.markSaved();
    }
    state.status.message = "opened session " + path;
    noteRecent(state, RecentEntry::sessionFile(path));
    return true;
  } catch (const std::exception& e) {
    state.status.errors.push_back(e.what());
    return false;
  }
}

}  // namespace

bool pollSessionRead(AppState& state) {
  // A finished read waits while another question is open (it would replace it) and while a live edit is under way
  // (a handle or G / R / S moving the cage, a slider held: committed when it ends, it then counts as a change below).
  if (state.document.unsaved.asking || state.document.unsaved.afterSave || state.input.mouse.transform ||
      state.input.widgetActive)
    return false;
  std::optional<SessionRead> read = state.jobs.session.poll();
  if (!read) return false;
  const std::string& path = read->path;
  if (read->cancelled) {
    state.status.message = "opening session " + path + " cancelled";
    return false;
  }
  if (!read->session) {
    state.status.errors.push_back(read->error);
    return false;
  }
  // The user was asked before the read began; edits, undo or redo since then were not part of that answer.
  if (state.document.history.revision() == state.jobs.sessionFrom || !hasUnsavedChanges(state))
    return openReadSession(state, path, *read->session);
  guardUnsaved(state, "open session " + std::filesystem::path(path).filename().string(),
               [path, session = std::make_shared<const Session>(std::move(*read->session))](AppState& s) {
                 openReadSession(s, path, *session);
               });
  state.status.message = "session " + path + " read: the document changed meanwhile";
  return false;
}

// ---- dropped and recent files ----

void openDroppedFiles(AppState& state, const std::vector<std::string>& paths) {
  const bool sceneReady = state.model.scene && !state.loadingScene();
  const int cageVertices = sceneReady ? state.model.scene->restCage.numVertices() : -1;
  if (paths.size() == 1 && lowerExtension(paths.front()) == ".obj" && cageVertices > 0) {
    // A posed cage of the scene shown, or what to drop: the file is counted and read on the posed-cage job.
    startPosedCageRead(state, [path = paths.front(), cageVertices](const Scene& scene) {
      const DropPlan plan = planDrop({path}, cageVertices, countObjVertices(path, cageVertices));
      return plan.kind == DropPlan::Kind::Pose ? readPosedCage(path, scene.restCage)
                                               : PosedCageRead{path, std::nullopt, plan.message};
    });
    return;
  }
  const DropPlan plan = planDrop(paths, cageVertices, -1);
  switch (plan.kind) {
    case DropPlan::Kind::Error:
      if (paths.size() == 1 && state.loadingScene()) {
        state.status.errors.push_back("a scene is still loading: drop a posed cage again once it has arrived, or " +
                                      plan.message);
      } else {
        state.status.errors.push_back(plan.message);
      }
      break;
    case DropPlan::Kind::Scene:
      state.files.dialog.mesh = plan.mesh;  // the Open panel shows what was dropped
      state.files.dialog.cage = plan.cage;
      state.files.dialog.posed = plan.posed;
      guardUnsaved(state, "open " + plan.mesh, [plan](AppState& s) {
        requestSceneFiles(s, plan.mesh, plan.cage, plan.posed);
        s.status.message = "opening mesh " + plan.mesh + ", cage " + plan.cage +
                           (plan.posed.empty() ? "" : ", posed cage " + plan.posed);
      });
      break;
    case DropPlan::Kind::Pose:  // needs a scene shown: read above
      break;
    case DropPlan::Kind::Session:
      guardUnsaved(state, "open " + plan.session, [plan](AppState& s) { loadSessionFile(s, plan.session); });
      break;
  }
}

void noteRecent(AppState& state, RecentEntry entry) {
  for (std::string* p : {&entry.mesh, &entry.cage, &entry.posed, &entry.session}) {
    if (p->empty()) continue;
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(*p, ec);
    if (!ec) *p = absolute.lexically_normal().string();
  }
  if (!state.files.recent.add(entry) || state.files.recentPath.empty()) return;
  try {
    saveRecentFiles(state.files.recentPath, state.files.recent);
  } catch (const std::exception& e) {
    state.status.message += "  (recent files not saved: " + std::string(e.what()) + ")";
  }
}

void openRecent(AppState& state, const RecentEntry& entry) {
  guardUnsaved(state, "open " + entry.label(), [entry](AppState& s) {
    if (entry.kind == RecentEntry::Kind::Session) {
      loadSessionFile(s, entry.session);
      return;
    }
    s.files.dialog.mesh = entry.mesh;
    s.files.dialog.cage = entry.cage;
    s.files.dialog.posed = entry.posed;
    requestSceneFiles(s, entry.mesh, entry.cage, entry.posed);
  });
}

}  // namespace somicage::editor
