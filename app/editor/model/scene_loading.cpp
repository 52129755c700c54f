// The scene's loading and precompute: requests to the precompute worker and the installation of its outcomes.
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "deform/frame_evaluator.h"
#include "engine/engine.h"
#include "model/app_state.h"
#include "model/view_quantity.h"
#include "tetrahedralization/cage_tetrahedralization.h"

namespace somicage::editor {

namespace {

// A precompute of `methods`' deformers: the J-based quantities' gradients count in its memory check when shown, and
// the active device integrates the coordinates when it can (its row integrator: --device cuda runs the whole
// pipeline on CUDA; the CPU's and the in-place OpenGL device's integrate on the CPU).
PrecomputeRequest deformerRequest(const AppState& state, std::vector<DeformerKey> methods) {
  PrecomputeRequest request;
  request.methods = std::move(methods);
  request.withGradients = state.view.quantities.show.usesSource(QuantitySource::Jacobian, state.views().size());
  if (const FrameDevice* device = findFrameDevice(state.model.devices.offered, state.model.devices.active()))
    request.options.rowIntegrator = device->rowIntegrator;
  request.options.volumeMesher = tetrahedralizeCageWithOptions;  // Phong's tetrahedra (CGAL, default level)
  return request;
}

// The views' deformers the scene does not have yet.
std::vector<DeformerKey> missingDeformers(const AppState& state) {
  std::vector<DeformerKey> missing;
  for (const DeformerKey& key : state.deformerKeys())
    if (!hasDeformer(state, key)) missing.push_back(key);
  return missing;
}

// A scene's load takes every core (thread_budget.h): until its mesh arrives the UI has nothing to deform, and then
// only draws it at rest. Its deformers are those of the views it will show: a session's are set only when its scene
// is shown (applySessionSettings). A session still being read is cancelled: this newer request wins.
void startLoad(AppState& state, std::shared_ptr<const Scene> scene, std::function<Scene()> loader, PendingLoad load) {
  state.jobs.session.cancel();
  PrecomputeRequest request =
      deformerRequest(state, load.session ? deformerKeysOf(sessionViews(state, *load.session)) : state.deformerKeys());
  request.threads = ThreadBudget::machine().cores();
  request.scene = std::move(scene);  // or, when null, the loader runs on the job
  request.loadScene = std::move(loader);
  request.posedPath = load.posed.path;  // read on the job, with the scene
  load.from = state.document.history.revision();  // the caller asked about unsaved changes (guardUnsaved)
  load.request = state.jobs.precompute.start(std::move(request));
  state.jobs.load = std::move(load);
}

}  // namespace

void requestScene(AppState& state, std::shared_ptr<const Scene> scene, PendingLoad load) {
  startLoad(state, std::move(scene), {}, std::move(load));
}

void requestLoad(AppState& state, std::function<Scene()> loader, PendingLoad load) {
  startLoad(state, nullptr, std::move(loader), std::move(load));
}

void requestSceneFiles(AppState& state, const std::string& meshPath, const std::string& cagePath,
                       const std::string& posedPath) {
  PendingLoad load;
  load.posed.path = posedPath;
  load.recent = RecentEntry::files(meshPath, cagePath, posedPath);
  requestLoad(
      state, [meshPath, cagePath]() { return loadScene(meshPath, cagePath); }, std::move(load));
}

void requestDemo(AppState& state, int dim, PendingLoad load) {
  requestScene(state, std::make_shared<const Scene>(makeDemoScene(dim)), std::move(load));
}

bool hasDeformer(const AppState& state, const DeformerKey& key) { return state.model.deformers.count(key) > 0; }

void ensureDeformers(AppState& state) {
  if (!state.model.scene || state.loadingScene()) return;
  std::vector<DeformerKey> missing = missingDeformers(state);
  state.model.precomputeCancelled = false;  // asked for again, or nothing is missing any more
  if (missing.empty()) return;
  PrecomputeRequest request = deformerRequest(state, std::move(missing));
  request.threads = ThreadBudget::machine().cores() - 1;  // the UI keeps a core: it deforms the views it has
  request.scene = state.model.scene;
  state.jobs.precompute.start(std::move(request));
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

void installScene(AppState& state, std::shared_ptr<const Scene> scene) {
  state.model.scene = std::move(scene);
  ++state.model.sceneGeneration;
  state.model.deformers.clear();
  state.model.deformed.clear();
  state.model.cpuStale.clear();
  state.model.precomputeCancelled = false;
  state.view.quantities.clearSweep();
  state.input.selection.resize(state.model.scene->restCage.numVertices());
  state.input.mouse = Interaction{};
}

void showLoadedScene(AppState& state, std::shared_ptr<const Scene> scene) {
  std::vector<std::string> notices;                            // for the status bar and the log
  PendingLoad load = state.jobs.load.value_or(PendingLoad{});  // none: a scene installed directly (tests)
  if (state.jobs.load) state.jobs.load->sceneShown = true;
  if (load.session) applySessionSettings(state, *load.session);  // the open document changes only now
  const std::shared_ptr<const Scene> previous = state.model.scene;
  installScene(state, std::move(scene));
  state.document.pose = state.model.scene->restCage.vertices;
  state.view.camera.setMode2D(state.model.scene->dim() == 2);
  frameRest(state);
  state.view.frameRequested = !load.session.has_value();
  if (load.session) state.view.camera.setState(load.session->camera);
  if (load.pose) {
    if (load.pose->rows() == state.document.pose.rows() && load.pose->cols() == state.document.pose.cols()) {
      state.document.pose = *load.pose;
    } else {
      state.status.errors.push_back("the saved pose has " + std::to_string(load.pose->rows()) +
                                    " vertices but the cage has " + std::to_string(state.document.pose.rows()) +
                                    "; the rest pose is shown instead");
    }
  }
  // The pose library and the keys belong to the cage they were made on: a session brings its own (they must fit its
  // cage), anything else keeps them only on a cage of the same topology. Part of the opened state, not a step.
  const bool sessionPoses = load.documentPath.has_value() || load.restored;
  const std::string dropped = keepPosesThatFit(state.animation, state.model.scene->restCage,
                                               sessionPoses || !previous ? nullptr : &previous->restCage);
  if (!dropped.empty()) notices.push_back(dropped);
  // A posed cage given with the scene was read on the load job (PendingLoad::posed), never here on the UI thread.
  const bool posedLoaded = load.posed.pose.has_value();
  if (posedLoaded) state.document.pose = *load.posed.pose;
  if (!load.posed.error.empty()) state.status.errors.push_back(load.posed.error);
  // The new document's history: the state as opened, then the posed cage loaded with it (undoable, like any
  // "Load posed cage"). Opening loses nothing, so it starts clean, except a crashed run's restored autosave,
  // which exists nowhere else.
  const Document opened = currentDocument(state);
  if (posedLoaded) state.document.pose = state.model.scene->restCage.vertices;
  state.document.history.reset(currentDocument(state), "Open " + state.model.scene->name, !load.restored);
  if (posedLoaded) {
    state.document.pose = opened.pose;
    commitEdit(state, "Load posed cage");
    if (!load.restored) state.document.history.markSaved();
  }
  state.document.path = load.documentPath.value_or("");
  ++state.document.poseGeneration;
  notices.insert(notices.begin(), state.model.scene->notices.begin(), state.model.scene->notices.end());
  state.status.message = "loaded " + state.model.scene->name;
  for (const std::string& notice : notices) {
    state.status.message += "; " + notice;
    std::fprintf(stderr, "somicage: %s: %s\n", state.model.scene->name.c_str(), notice.c_str());
  }
  if (load.recent && load.recent->mesh == state.model.scene->meshPath &&
      load.recent->cage == state.model.scene->cagePath) {
    if (!posedLoaded) load.recent->posed.clear();
    noteRecent(state, *load.recent);
  }
}

void installOutcome(AppState& state, PrecomputeOutcome outcome) {
  if (outcome.cancelled) {
    state.jobs.load.reset();
    state.status.message = "precomputation cancelled";
    // A scene shown while its deformers were computed stays, at rest; the next edit asks for them again (an artist
    // who moves a handle expects the mesh to follow), not this frame (Esc gives the cores back now).
    state.model.precomputeCancelled = state.model.scene && !missingDeformers(state).empty();
    if (state.model.precomputeCancelled)
      state.status.message += ": the next edit of the pose or parameters restarts it";
    return;
  }
  if (!outcome.error.empty()) {
    state.jobs.load.reset();
    state.status.errors.push_back(outcome.error);
    return;
  }
  if (!outcome.scene) return;
  state.status.stats.precomputeSeconds = outcome.seconds;
  const bool newScene = outcome.scene != state.model.scene;  // not shown while its deformers were computed
  if (newScene && state.jobs.load) state.jobs.load->posed = std::move(outcome.posed);
  if (newScene) showLoadedScene(state, outcome.scene);
  const bool completesLoad = state.jobs.load && state.jobs.load->sceneShown;
  for (auto& [m, d] : outcome.deformers) state.model.deformers[m] = d;
  for (const std::string& notice : outcome.notices) {  // e.g. Phong's tetrahedral mesh is TetGen's, not Mesh_3's
    state.status.message += (state.status.message.empty() ? "" : "; ") + notice;
    std::fprintf(stderr, "somicage: %s\n", notice.c_str());
  }
  state.model.deformDirty = true;
  if (newScene || completesLoad) {  // what only the deformers tell: points outside the cage
    if (const std::optional<std::string> outside = exteriorNotice(*state.model.scene, outcome.deformers)) {
      state.status.message += "; " + *outside;
      std::fprintf(stderr, "somicage: %s: %s\n", state.model.scene->name.c_str(), outside->c_str());
    }
  }
  if (completesLoad) state.jobs.load.reset();
}

void wakeOnFinish(AppState& state, const std::function<void()>& wake) {
  state.jobs.precompute.setOnFinished(wake);
  state.jobs.measure.setOnFinished(wake);
  state.jobs.cageMaker.setOnFinished(wake);
  state.jobs.exporter.setOnFinished(wake);
  state.jobs.posedCage.setOnFinished(wake);
  state.jobs.session.setOnFinished(wake);
}

namespace {

// Installs a finished precompute, then the deformers the views still miss (e.g. the views changed while loading); not
// after a cancel (a scene shown early would start again at once).
void takeOutcome(AppState& state, PrecomputeOutcome outcome) {
  const bool cancelled = outcome.cancelled;
  installOutcome(state, std::move(outcome));
  if (!cancelled && !state.jobs.precompute.busy()) ensureDeformers(state);
}

// What the load opens, for the question: "open session s.json", "open bunny.obj".
std::string loadWhat(const PendingLoad& load, const Scene& scene) {
  if (load.restored) return "restore the autosave";
  if (load.documentPath) return "open session " + std::filesystem::path(*load.documentPath).filename().string();
  return "open " + scene.name;
}

// The load's `scene` has arrived: `show` shows it now, unless the document changed since the load was asked for and
// is unsaved (changedSince): then the same question again, with `show` as its action (run only if the load is still
// the one asked about); Cancel drops the load, its precompute and, with the action, its scene. Returns whether shown.
bool showWhenAgreed(AppState& state, const Scene& scene, std::function<void(AppState&)> show) {
  if (!changedSince(state, state.jobs.load->from)) {
    show(state);
    return true;
  }
  const std::string what = loadWhat(*state.jobs.load, scene);
  const std::string message = scene.name + " loaded: the document changed meanwhile";  // `show` may hold the scene
  const std::uint64_t request = state.jobs.load->request;
  const auto asked = [request](const AppState& s) { return s.jobs.load && s.jobs.load->request == request; };
  guardUnsaved(
      state, what,
      [asked, show = std::move(show)](AppState& s) {
        if (asked(s)) show(s);
      },
      [asked](AppState& s) {
        if (!asked(s)) return;
        s.jobs.precompute.discard();
        s.jobs.load.reset();  // a session's settings (PendingLoad::session) go with it, unapplied
        s.status.message += "; the loaded scene was dropped";
      });
  if (state.document.unsaved.asking) state.status.message = message;
  return false;
}

}  // namespace

bool pollWorker(AppState& state) {
  const bool awaitingScene = state.jobs.load && !state.jobs.load->sceneShown;
  if (awaitingScene && documentBusy(state)) return false;  // the scene would replace the document under the user
  if (awaitingScene) {  // the mesh has loaded: show it while the precompute runs
    if (std::optional<PrecomputeWorker::LoadedScene> loaded = state.jobs.precompute.takeLoadedScene()) {
      const Scene& scene = *loaded->scene;
      if (!showWhenAgreed(state, scene, [loaded = std::move(*loaded)](AppState& s) {
            s.jobs.load->posed = loaded.posed;
            showLoadedScene(s, loaded.scene);
            logLine(s, "scene shown");  // --log-actions: the GUI tests look for the mesh drawn from here on
          }))
        return false;
    }
  }
  std::optional<PrecomputeOutcome> outcome = state.jobs.precompute.poll();
  if (!outcome) return false;
  // Its scene not shown yet (it finished before the frame took the loaded scene): the same question first.
  if (state.jobs.load && !state.jobs.load->sceneShown && outcome->scene && !outcome->cancelled &&
      outcome->error.empty()) {
    const Scene& scene = *outcome->scene;
    return showWhenAgreed(state, scene, [outcome = std::move(*outcome)](AppState& s) { takeOutcome(s, outcome); });
  }
  takeOutcome(state, std::move(*outcome));
  return true;
}

}  // namespace somicage::editor
