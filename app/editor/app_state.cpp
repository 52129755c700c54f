#include "app_state.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "cage_tetrahedralization.h"
#include "drop.h"
#include "engine.h"
#include "errors.h"
#include "mesh_formats.h"
#include "obj_io.h"

namespace somicage::editor {

std::vector<ViewSpec> AppState::views() const {
  if (compare && compareViews.size() >= 2) return compareViews;
  return {singleView()};
}

ViewSpec AppState::singleView() const {
  return withMethod(ViewSpec{method, {}, methodOptions}, method);
}

std::vector<DeformerKey> AppState::deformerKeys() const {
  std::vector<DeformerKey> keys;
  for (const ViewSpec& view : views())
    if (std::find(keys.begin(), keys.end(), deformerKey(view)) == keys.end()) keys.push_back(deformerKey(view));
  return keys;
}

std::string viewLabel(const AppState& state, std::size_t v) {
  const ViewSpec view = state.views()[v];
  const Method method = view.method;
  const DeformParams params = view.params(state.params);
  std::string label = method->displayName;
  char buf[160];
  for (const ParameterSpec& spec : parameterSchema()) {  // parameter_schema.h: what each row's LabelShow says
    const double value = parameterValue(spec, params);
    const bool own = view.own.count(spec.key) > 0;
    if (!readsParameter(method, spec.parameter) || spec.labelShow == LabelShow::Never ||
        (spec.labelShow == LabelShow::WhenSet && value == spec.defaultValue && !own))
      continue;
    const std::string text = parameterText(spec, value);
    if (spec.type == ParameterType::Number) {
      std::snprintf(buf, sizeof buf, "%.2f", value);
      label += "  " + std::string(spec.key) + "=" + (std::isinf(value) ? text : buf);
    } else if (spec.type == ParameterType::Switch) {
      label += "  " + std::string(value != 0 ? "" : "no ") + spec.label;
    } else if (spec.labelShow == LabelShow::Always) {  // the variant: "local", or "blend 0.50" between the two
      std::snprintf(buf, sizeof buf, " %.2f", params.blend);
      label += "  " + text + (text == "blend" ? buf : "");
    } else {
      label += "  " + std::string(spec.key) + " " + text;
    }
    if (own) label += " (own)";
  }
  for (const auto& [key, value] : view.options) label += "  " + key + " " + value + " (own)";
  // Which tetrahedra a volume method gets without options of its own (deformer.h: volumeMeshFor): the cage's star.
  if (method->needsVolumeMesh && view.options.count("tets") + view.options.count("tet-level") == 0 && state.scene &&
      starVolumeMesh(state.scene->restCage))
    label += "  star tetrahedra";
  if (!hasDeformer(state, deformerKey(view))) label += "  (precomputing...)";
  return label;
}

std::string viewShortName(const AppState& state, std::size_t v) {
  const ViewSpec view = state.views()[v];
  std::string name = view.method->displayName;
  if (const std::optional<double> nu = view.value("nu")) {
    char buf[48];
    std::snprintf(buf, sizeof buf, " nu=%.2f", *nu);
    name += buf;
  }
  for (const auto& [key, value] : view.options) name += " " + key + " " + value;
  return name;
}

// ---- scene requests ----

namespace {

// A precompute of `methods`' deformers: the J-based quantities' gradients count in its memory check when shown, and
// the active device integrates the coordinates when it can (its row integrator: --device cuda runs the whole
// pipeline on CUDA; the CPU's and the in-place OpenGL device's integrate on the CPU).
PrecomputeRequest deformerRequest(const AppState& state, std::vector<DeformerKey> methods) {
  PrecomputeRequest request;
  request.methods = std::move(methods);
  request.withGradients = state.quantities.show.usesSource(QuantitySource::Jacobian, state.views().size());
  if (const FrameDevice* device = findFrameDevice(state.devices.offered, state.devices.active()))
    request.options.rowIntegrator = device->rowIntegrator;
  request.options.volumeMesher = tetrahedralizeCageWithOptions;  // Phong's tetrahedra (CGAL, default level)
  return request;
}

}  // namespace

void requestScene(AppState& state, std::shared_ptr<const Scene> scene) {
  PrecomputeRequest request = deformerRequest(state, state.deformerKeys());
  request.scene = std::move(scene);
  state.loadingScene = true;
  state.pendingRecent.reset();
  state.worker.start(std::move(request));
}

namespace {

// Starts loading a scene on the worker with `load`, then precomputing the views' deformers.
void requestLoad(AppState& state, std::function<Scene()> load) {
  PrecomputeRequest request = deformerRequest(state, state.deformerKeys());
  request.loadScene = std::move(load);
  state.loadingScene = true;
  state.pendingRecent.reset();
  state.worker.start(std::move(request));
}

}  // namespace

void requestSceneFiles(AppState& state, const std::string& meshPath, const std::string& cagePath,
                       const std::string& posedPath) {
  requestLoad(state, [meshPath, cagePath]() { return loadScene(meshPath, cagePath); });
  state.pendingPosedPath = posedPath;
  state.pendingRecent = RecentEntry::files(meshPath, cagePath, posedPath);
}

void requestDemo(AppState& state, int dim) { requestScene(state, std::make_shared<const Scene>(makeDemoScene(dim))); }

bool hasDeformer(const AppState& state, const DeformerKey& key) { return state.deformers.count(key) > 0; }

void ensureDeformers(AppState& state) {
  if (!state.scene || state.loadingScene) return;
  std::vector<DeformerKey> missing;
  for (const DeformerKey& key : state.deformerKeys()) {
    if (!hasDeformer(state, key)) missing.push_back(key);
  }
  if (missing.empty()) return;
  PrecomputeRequest request = deformerRequest(state, std::move(missing));
  request.scene = state.scene;
  state.worker.start(std::move(request));
}

namespace {

// "mesh warning: 640 of 642 points lie outside the cage ..." when some do (the deformers that tell: Somigliana's and
// Green's regions), as the command line warns.
std::optional<std::string> exteriorNotice(const Scene& scene, const DeformerSet& deformers) {
  const CageDeformer* most = nullptr;
  for (const auto& [method, deformer] : deformers)
    if (!most || deformer->diagnostics().exteriorCount() > most->diagnostics().exteriorCount()) most = deformer.get();
  if (!most) return std::nullopt;
  const std::optional<Notice> notice = exteriorPointsNotice(*most, scene.isDemo() ? scene.name : scene.meshPath);
  if (!notice) return std::nullopt;
  return "mesh warning: " + notice->text;
}

}  // namespace

void installOutcome(AppState& state, PrecomputeOutcome outcome) {
  const bool newScene = outcome.scene && outcome.scene != state.scene;
  if (newScene) state.loadingScene = false;
  if (outcome.cancelled) {
    state.loadingScene = false;
    state.pendingRecent.reset();
    state.statusMessage = "precomputation cancelled";
    return;
  }
  if (!outcome.error.empty()) {
    state.loadingScene = false;
    state.pendingRecent.reset();
    state.errors.push_back(outcome.error);
    return;
  }
  if (!outcome.scene) return;
  state.stats.precomputeSeconds = outcome.seconds;
  std::vector<std::string> notices;  // for the status bar and the log
  if (newScene) {
    const std::shared_ptr<const Scene> previous = state.scene;
    state.scene = outcome.scene;
    ++state.sceneGeneration;
    state.deformers.clear();
    state.deformed.clear();
    state.cpuStale.clear();
    state.quantities.clearSweep();
    state.pose = state.scene->restCage.vertices;
    state.selection.resize(state.scene->restCage.numVertices());
    state.interaction = Interaction{};
    state.camera.setMode2D(state.scene->dim() == 2);
    frameRest(state);
    state.frameRequested = !state.pendingCamera.has_value();
    if (state.pendingCamera) state.camera.setState(*state.pendingCamera);
    state.pendingCamera.reset();
    if (state.pendingPose) {
      if (state.pendingPose->rows() == state.pose.rows() && state.pendingPose->cols() == state.pose.cols()) {
        state.pose = *state.pendingPose;
      } else {
        state.errors.push_back("the saved pose has " + std::to_string(state.pendingPose->rows()) +
                               " vertices but the cage has " + std::to_string(state.pose.rows()) +
                               "; the rest pose is shown instead");
      }
      state.pendingPose.reset();
    }
    // The pose library and the keys belong to the cage they were made on: a session brings its own (they must fit its
    // cage), anything else keeps them only on a cage of the same topology. Part of the opened state, not a step.
    const bool sessionPoses = state.pendingDocumentPath.has_value() || state.pendingRestored;
    const std::string dropped = keepPosesThatFit(state.animation, state.scene->restCage,
                                                 sessionPoses || !previous ? nullptr : &previous->restCage);
    if (!dropped.empty()) notices.push_back(dropped);
    bool posedLoaded = false;
    if (!state.pendingPosedPath.empty()) {
      try {
        state.pose =
            posedVerticesFromMesh(loadAnyMesh(state.pendingPosedPath), state.scene->restCage, state.pendingPosedPath);
        posedLoaded = true;
      } catch (const std::exception& e) {
        state.errors.push_back(e.what());
      }
      state.pendingPosedPath.clear();
    }
    // The new document's history: the state as opened, then the posed cage loaded with it (undoable, like any
    // "Load posed cage"). Opening loses nothing, so it starts clean, except a crashed run's restored autosave,
    // which exists nowhere else.
    const Document opened = currentDocument(state);
    if (posedLoaded) state.pose = state.scene->restCage.vertices;
    state.history.reset(currentDocument(state), "Open " + state.scene->name, !state.pendingRestored);
    if (posedLoaded) {
      state.pose = opened.pose;
      commitEdit(state, "Load posed cage");
      if (!state.pendingRestored) state.history.markSaved();
    }
    state.documentPath = state.pendingDocumentPath.value_or("");
    state.pendingDocumentPath.reset();
    state.pendingRestored = false;
    ++state.poseGeneration;
    notices.insert(notices.begin(), state.scene->notices.begin(), state.scene->notices.end());
    if (const std::optional<std::string> outside = exteriorNotice(*state.scene, outcome.deformers))
      notices.push_back(*outside);
    state.statusMessage = "loaded " + state.scene->name;
    for (const std::string& notice : notices) {
      state.statusMessage += "; " + notice;
      std::fprintf(stderr, "somicage: %s: %s\n", state.scene->name.c_str(), notice.c_str());
    }
    if (state.pendingRecent && state.pendingRecent->mesh == state.scene->meshPath &&
        state.pendingRecent->cage == state.scene->cagePath) {
      if (!posedLoaded) state.pendingRecent->posed.clear();
      noteRecent(state, *state.pendingRecent);
    }
    state.pendingRecent.reset();
  }
  for (auto& [m, d] : outcome.deformers) state.deformers[m] = d;
  for (const std::string& notice : outcome.notices) {  // e.g. Phong's tetrahedral mesh is TetGen's, not Mesh_3's
    state.statusMessage += (state.statusMessage.empty() ? "" : "; ") + notice;
    std::fprintf(stderr, "somicage: %s\n", notice.c_str());
  }
  state.deformDirty = true;
}

void wakeOnFinish(AppState& state, const std::function<void()>& wake) {
  state.worker.setOnFinished(wake);
  state.quantities.worker.setOnFinished(wake);
  state.cageMaker.setOnFinished(wake);
  state.exporter.setOnFinished(wake);
}

bool pollWorker(AppState& state) {
  std::optional<PrecomputeOutcome> outcome = state.worker.poll();
  if (!outcome) return false;
  installOutcome(state, std::move(*outcome));
  if (!state.worker.busy()) ensureDeformers(state);  // e.g. the views changed while loading
  return true;
}

bool updateDeformation(AppState& state) {
  if (!state.deformDirty || !state.scene) return false;
  state.deformDirty = false;
  const std::vector<ViewSpec> views = state.views();
  state.deformed.resize(views.size());
  if (state.devices.inPlace()) {
    state.cpuStale.clear();
    for (std::size_t v = 0; v < views.size(); ++v) state.cpuStale.push_back(v);
    ++state.deformGeneration;  // the Renderer deforms on the GPU and reports the timing (Renderer::sync)
    return true;
  }
  state.cpuStale.clear();
  state.stats.deformThreads = omp_get_max_threads();
  bool changed = false;
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t v = 0; v < views.size(); ++v) {
    auto it = state.deformers.find(deformerKey(views[v]));
    if (it == state.deformers.end()) continue;
    try {
      deformOnDevice(state, it->second, views[v].params(state.params), state.deformed[v]);
      changed = true;
      ++state.stats.frame.deforms;
    } catch (const std::exception& e) {
      state.errors.push_back(std::string("deformation failed: ") + e.what());
    }
  }
  if (changed) {
    state.stats.lastDeformMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    state.stats.frame.deformMs += state.stats.lastDeformMs;
    ++state.deformGeneration;
  }
  return changed;
}

void ensureCpuPoints(AppState& state, std::size_t view) {
  auto stale = std::find(state.cpuStale.begin(), state.cpuStale.end(), view);
  if (stale == state.cpuStale.end()) return;
  state.cpuStale.erase(stale);
  const std::vector<ViewSpec> views = state.views();
  if (view >= views.size()) return;
  auto it = state.deformers.find(deformerKey(views[view]));
  if (it == state.deformers.end()) return;
  state.deformed.resize(views.size());
  const auto t0 = std::chrono::steady_clock::now();
  try {
    deformOnDevice(state, it->second, views[view].params(state.params), state.deformed[view]);
    ++state.stats.frame.deforms;
    state.stats.frame.deformMs +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  } catch (const std::exception& e) {
    state.errors.push_back(std::string("deformation failed: ") + e.what());
  }
}

void setDevice(AppState& state, const std::string& device) {
  if (state.devices.requested == device) return;
  state.devices.requested = device;
  state.devices.evaluators.clear();  // the old device's copies of C go
  state.deformDirty = true;
}

const Eigen::MatrixXd& displayedPoints(const AppState& state, std::size_t view) {
  const std::vector<ViewSpec> views = state.views();
  if (view < views.size() && view < state.deformed.size() && state.scene &&
      state.deformed[view].rows() == state.scene->meshVertices.rows() && hasDeformer(state, deformerKey(views[view]))) {
    return state.deformed[view];
  }
  return state.scene->meshVertices;
}

// ---- edits ----

Document currentDocument(const AppState& state) {
  return {state.pose,
          state.method,
          state.params,
          state.animation.poses,
          state.animation.timeline,
          state.scene ? state.scene->restCage : Cage{},
          state.scene ? state.scene->cagePath : std::string()};
}

void replaceRestCage(AppState& state, const Cage& cage, const std::string& cagePath) {
  if (!state.scene) return;
  auto scene = std::make_shared<Scene>(*state.scene);
  scene->restCage = cage;
  scene->cagePath = cagePath;
  state.scene = std::move(scene);
  ++state.sceneGeneration;
  state.deformers.clear();
  state.deformed.clear();
  state.cpuStale.clear();
  state.quantities.clearSweep();
  state.selection.resize(cage.numVertices());
  state.interaction = Interaction{};
  setPose(state, cage.vertices);
  ensureDeformers(state);
}

void applyDocument(AppState& state, const Document& document) {
  if (state.scene && document.restCage.numVertices() > 0 &&
      (!sameCage(document.restCage, state.scene->restCage) || document.cagePath != state.scene->cagePath))
    replaceRestCage(state, document.restCage, document.cagePath);
  if (document.pose.rows() == state.pose.rows() && document.pose.cols() == state.pose.cols())
    setPose(state, document.pose);
  setParams(state, document.params);
  if (document.method != state.method) setMethod(state, document.method);
  state.animation.poses = document.poses;
  state.animation.timeline = document.timeline;
}

bool commitEdit(AppState& state, const std::string& name) {
  if (!state.scene) return false;
  const bool added = state.history.commit(name, currentDocument(state));
  if (added) logLine(state, "step " + name);
  return added;
}

void logLine(const AppState& state, const std::string& line) {
  if (!state.logActions) return;
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
}

void setPose(AppState& state, const Eigen::MatrixXd& pose) {
  state.pose = pose;
  ++state.poseGeneration;
  state.deformDirty = true;
}

void resetPose(AppState& state) {
  if (!state.scene) return;
  setPose(state, state.scene->restCage.vertices);
  state.statusMessage = commitEdit(state, "Reset pose") ? "reset the pose" : "the pose is at rest already";
}

void setParams(AppState& state, const DeformParams& params) {
  state.params = params;
  state.deformDirty = true;
}

void undo(AppState& state) {
  if (!state.history.canUndo()) {
    state.statusMessage = "nothing to undo";
    return;
  }
  const std::string name = state.history.step(state.history.cursor()).name;
  applyDocument(state, state.history.undo());
  state.statusMessage = "undo " + name;
}

void redo(AppState& state) {
  if (!state.history.canRedo()) {
    state.statusMessage = "nothing to redo";
    return;
  }
  applyDocument(state, state.history.redo());
  state.statusMessage = "redo " + state.history.step(state.history.cursor()).name;
}

void jumpToStep(AppState& state, std::size_t step) {
  if (step >= state.history.size() || step == state.history.cursor()) return;
  applyDocument(state, state.history.jumpTo(step));
  state.statusMessage = "history: back at \"" + state.history.step(step).name + "\"";
}

bool hasUnsavedChanges(const AppState& state) { return state.history.unsaved(); }

std::string documentName(const AppState& state) {
  if (!state.documentPath.empty()) return std::filesystem::path(state.documentPath).stem().string();
  return state.scene ? state.scene->name : "";
}

std::string windowTitle(const AppState& state) {
  const std::string name = documentName(state);
  if (name.empty()) return "SomiCage";
  return name + (hasUnsavedChanges(state) ? "*" : "") + " - SomiCage";
}

void setMethod(AppState& state, Method method) {
  if (state.method == method) return;
  state.method = method;
  state.deformDirty = true;
  ensureDeformers(state);
}

void setMethodOptions(AppState& state, MethodOptions options) {
  if (state.methodOptions == options) return;
  state.methodOptions = std::move(options);
  state.deformDirty = true;
  ensureDeformers(state);
}

void setCompare(AppState& state, bool on) {
  if (on && !state.compare) state.frameRequested = true;  // narrower views: frame everything again
  if (on != state.compare) state.quantities.clearSweep();
  state.compare = on;
  state.deformDirty = true;
  ensureDeformers(state);
}

void setCompareViews(AppState& state, std::vector<ViewSpec> views) {
  if (views.size() < 2 || views.size() > kMaxCompareViews) return;
  state.compareViews = std::move(views);
  setCompare(state, true);
}

void removeCompareView(AppState& state, std::size_t v) {
  if (state.compareViews.size() <= 2 || v >= state.compareViews.size()) return;
  std::vector<ViewShow>& shows = state.quantities.show.views;
  if (shows.size() > 1 && v < shows.size()) shows.erase(shows.begin() + static_cast<std::ptrdiff_t>(v));
  std::vector<ViewSpec> views = state.compareViews;
  views.erase(views.begin() + static_cast<std::ptrdiff_t>(v));
  setCompareViews(state, std::move(views));
}

void frameAll(AppState& state) {
  if (!state.scene) return;
  ensureCpuPoints(state, 0);
  Eigen::Vector3d lo, hi, clo, chi;
  bounds3(displayedPoints(state, 0), lo, hi);
  bounds3(state.pose.rows() > 0 ? state.pose : state.scene->restCage.vertices, clo, chi);
  state.camera.frame(lo.cwiseMin(clo), hi.cwiseMax(chi), state.viewAspect);
}

void frameRest(AppState& state) {
  if (!state.scene) return;
  Eigen::Vector3d lo, hi, clo, chi;
  bounds3(state.scene->meshVertices, lo, hi);
  bounds3(state.scene->restCage.vertices, clo, chi);
  state.camera.frame(lo.cwiseMin(clo), hi.cwiseMax(chi), state.viewAspect);
}

// ---- sessions and files ----

Session makeSession(const AppState& state) {
  Session s;
  if (state.scene) {
    s.meshPath = state.scene->meshPath;
    s.cagePath = state.scene->cagePath;
    s.demoDim = state.scene->dim();
    if (s.cagePath.empty()) s.restCage = state.scene->restCage;  // no file holds it: the session does
  }
  s.pose = state.pose;
  s.method = state.method;
  s.methodOptions = state.singleView().options;
  s.params = state.params;
  s.compare = state.compare;
  s.compareViews = state.compareViews;
  s.camera = state.camera.state();
  s.poses = state.animation.poses;
  s.timeline = state.animation.timeline;
  return s;
}

void applySession(AppState& state, const Session& s) {
  state.animation.poses = s.poses;
  state.animation.timeline = s.timeline;
  if (!s.poses.poses().empty() || !s.timeline.keys.empty()) state.animation.showPanels = true;
  state.method = s.method;
  state.methodOptions = s.methodOptions;
  state.params = s.params;
  state.compare = s.compare;
  if (!s.compareViews.empty()) state.compareViews = s.compareViews;
  const bool inlineCage = s.restCage.numVertices() > 0;
  const bool sameScene = state.scene && !state.loadingScene && state.scene->meshPath == s.meshPath &&
                         state.scene->cagePath == s.cagePath &&
                         (!s.meshPath.empty() || state.scene->dim() == s.demoDim) &&
                         (!inlineCage || sameCage(state.scene->restCage, s.restCage));
  if (sameScene) {
    if (s.pose.rows() == state.pose.rows() && s.pose.cols() == state.pose.cols()) setPose(state, s.pose);
    commitEdit(state, "Load session");
    state.camera.setState(s.camera);
    state.deformDirty = true;
    ensureDeformers(state);
    return;
  }
  if (s.pose.rows() > 0) state.pendingPose = s.pose;
  state.pendingCamera = s.camera;
  if (inlineCage) {
    requestLoad(state, [mesh = s.meshPath, cage = s.restCage, notices = s.cageNotices]() {
      Scene scene = loadSceneWithCage(mesh, cage, "the session's cage");
      for (const Notice& n : notices) scene.notices.push_back(sceneNotice(n));
      return scene;
    });
  } else if (s.meshPath.empty()) {
    requestDemo(state, s.demoDim);
  } else {
    requestSceneFiles(state, s.meshPath, s.cagePath);
    state.pendingRecent.reset();  // the session is the recent entry, not its files
  }
}

void acceptRestoreOffer(AppState& state) {
  if (!state.restoreOffer) return;
  state.pendingRestored = true;
  applySession(state, *state.restoreOffer);
  if (!state.loadingScene) state.pendingRestored = false;
  state.statusMessage = "restored the session from " + state.restoreOfferTime;
  state.restoreOffer.reset();
}

void discardRestoreOffer(AppState& state) { state.restoreOffer.reset(); }

bool savePosedCage(AppState& state, const std::string& path) {
  if (!state.scene) return false;
  try {
    Cage posed = state.scene->restCage;
    posed.vertices = state.pose;
    saveObj(path, state.pose, cageTopology(posed));
    state.statusMessage = "saved posed cage " + path;
    return true;
  } catch (const std::exception& e) {
    state.errors.push_back(e.what());
    return false;
  }
}

bool loadPosedCage(AppState& state, const std::string& path) {
  if (!state.scene) return false;
  try {
    const Eigen::MatrixXd pose = posedVerticesFromMesh(loadAnyMesh(path), state.scene->restCage, path);
    setPose(state, pose);
    commitEdit(state, "Load posed cage");
    state.statusMessage = "loaded pose " + path;
    if (!state.scene->isDemo()) {
      noteRecent(state, RecentEntry::files(state.scene->meshPath, state.scene->cagePath, path));
    }
    return true;
  } catch (const std::exception& e) {
    state.errors.push_back(e.what());
    return false;
  }
}

bool saveSessionFile(AppState& state, const std::string& path) {
  try {
    saveSession(path, makeSession(state));
    state.documentPath = path;
    state.history.markSaved();
    state.statusMessage = "saved session " + path;
    noteRecent(state, RecentEntry::sessionFile(path));  // File > Open Recent lists it at once
    return true;
  } catch (const std::exception& e) {
    state.errors.push_back(e.what());
    return false;
  }
}

bool loadSessionFile(AppState& state, const std::string& path) {
  try {
    const Session session = loadSession(path);
    state.pendingDocumentPath = path;
    applySession(state, session);
    if (state.pendingDocumentPath && !state.loadingScene) {  // the same scene: applied at once, as an edit
      state.documentPath = path;
      state.pendingDocumentPath.reset();
      state.history.markSaved();
    }
    state.statusMessage = "opened session " + path;
    noteRecent(state, RecentEntry::sessionFile(path));
    return true;
  } catch (const std::exception& e) {
    state.pendingDocumentPath.reset();
    state.errors.push_back(e.what());
    return false;
  }
}

// ---- dropped and recent files ----

void openDroppedFiles(AppState& state, const std::vector<std::string>& paths) {
  const bool sceneReady = state.scene && !state.loadingScene;
  const int cageVertices = sceneReady ? state.scene->restCage.numVertices() : -1;
  int singleVertices = -1;
  if (paths.size() == 1 && lowerExtension(paths.front()) == ".obj" && cageVertices > 0) {
    singleVertices = countObjVertices(paths.front(), cageVertices);
  }
  const DropPlan plan = planDrop(paths, cageVertices, singleVertices);
  switch (plan.kind) {
    case DropPlan::Kind::Error:
      if (paths.size() == 1 && state.loadingScene) {
        state.errors.push_back("a scene is still loading: drop a posed cage again once it has arrived, or " +
                               plan.message);
      } else {
        state.errors.push_back(plan.message);
      }
      break;
    case DropPlan::Kind::Scene:
      state.dialog.mesh = plan.mesh;  // the Open panel shows what was dropped
      state.dialog.cage = plan.cage;
      state.dialog.posed = plan.posed;
      guardUnsaved(state, "open " + plan.mesh, [plan](AppState& s) {
        requestSceneFiles(s, plan.mesh, plan.cage, plan.posed);
        s.statusMessage = "opening mesh " + plan.mesh + ", cage " + plan.cage +
                          (plan.posed.empty() ? "" : ", posed cage " + plan.posed);
      });
      break;
    case DropPlan::Kind::Pose:
      loadPosedCage(state, plan.posed);
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
  if (!state.recent.add(entry) || state.recentPath.empty()) return;
  try {
    saveRecentFiles(state.recentPath, state.recent);
  } catch (const std::exception& e) {
    state.statusMessage += "  (recent files not saved: " + std::string(e.what()) + ")";
  }
}

void openRecent(AppState& state, const RecentEntry& entry) {
  guardUnsaved(state, "open " + entry.label(), [entry](AppState& s) {
    if (entry.kind == RecentEntry::Kind::Session) {
      loadSessionFile(s, entry.session);
      return;
    }
    s.dialog.mesh = entry.mesh;
    s.dialog.cage = entry.cage;
    s.dialog.posed = entry.posed;
    requestSceneFiles(s, entry.mesh, entry.cage, entry.posed);
  });
}

}  // namespace somicage::editor
