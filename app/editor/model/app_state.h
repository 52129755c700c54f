// AppState: everything the editor knows, in parts of one concern each (the document and its history, the scene and
// its deformers, the views, the selection and interaction, the animation, the background jobs, the files, the
// status), and the controller functions that change it. No globals, no GL, no ImGui: the panels (panels.h) and the
// input handler (input.h) are functions of AppState&, and the Renderer (editor_renderer.h) reads it. The functions
// are defined by concern: app_state.cpp, scene_loading.cpp, deformation.cpp, edits.cpp, document_files.cpp.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "deform/deform_params.h"
#include "deform/method.h"
#include "engine/session.h"
#include "engine/view_spec.h"
#include "geometry/cage.h"
#include "geometry/volume_mesh.h"
#include "interaction/camera.h"
#include "interaction/element_pick.h"
#include "interaction/transform.h"
#include "jobs/background_job.h"
#include "jobs/cage_maker.h"
#include "jobs/export_worker.h"
#include "jobs/measure_worker.h"
#include "jobs/precompute_worker.h"
#include "jobs/session_read.h"
#include "jobs/thread_budget.h"
#include "model/document.h"
#include "model/frame_device_evaluators.h"
#include "model/history.h"
#include "model/pose_keys.h"
#include "model/recent_files.h"
#include "model/scene.h"
#include "model/selection.h"
#include "model/view_quantities.h"
#include "ui/file_dialog.h"
#include "ui/frame_timings.h"
#include "ui/unsaved_changes.h"

namespace somicage::editor {

// Mouse interaction in the viewports.
struct Interaction {
  enum class Mode { Idle, Orbit, Pan, Box, HandleDrag, Modal };
  Mode mode = Mode::Idle;
  Eigen::Vector2d pressMouse = Eigen::Vector2d::Zero();  // window pixels
  Eigen::Vector2d lastMouse = Eigen::Vector2d::Zero();
  int view = 0;                               // viewport the interaction started in
  std::optional<TransformSession> transform;  // Modal (G/R/S) and HandleDrag
  bool boxAdditive = false;
};

struct Stats {
  double precomputeSeconds = 0.0;
  // Wall time of the last deformation (all views); in place on OpenGL: the GPU time of the latest frame whose timer
  // query finished (all views; NaN until one has), read without stalling.
  double lastDeformMs = 0.0;
  double lastDeformCpuMs = 0.0;  // in place on OpenGL: the CPU part (frameWeights, the W upload, the dispatches)
  double fps = 0.0;
  int deformThreads = availableCores();  // the UI's team for the last CPU deformation (thread_budget.h)
  FrameTimings frame;          // the frame being drawn: each stage adds its time (frame_timings.h)
  FrameTimingsHistory frames;  // the frames drawn, for Help > Frame timings
  bool timeFrames = false;     // time each stage (each pane's draw finished): the overlay or --log-frames is on
};

// The state's parts, one concern each (docs/editor.md, "The state's parts", says who may change which).

// Document and history: what the user edits and undo restores (document.h), changed through the edit functions below
// (setPose / setParams / setMethod, then commitEdit; applyDocument, undo, redo) and never directly by a panel.
struct DocumentState {
  Eigen::MatrixXd pose;              // #V by d posed cage
  std::uint64_t poseGeneration = 0;  // bumps when pose or selection changes (cage upload)
  Method method;                     // the registry's first (method.h)
  DeformParams params;
  History history;
  std::string path;            // the session file the document was opened from or saved to; "" none
  UnsavedPrompt unsaved;       // the Save / Don't save / Cancel question (unsaved_changes.h)
  bool quitRequested = false;  // set by the (guarded) quit command; the frame loop ends, then the autosave goes
};

// Scene and deformers: the scene shown, its precomputed deformers and the deformed points. Replaced only by
// installOutcome (a finished precompute) and replaceRestCage; the points by updateDeformation / ensureCpuPoints.
struct SceneState {
  std::shared_ptr<const Scene> scene;
  std::uint64_t sceneGeneration = 0;      // bumps when the scene (topology) changes
  DeformerSet deformers;                  // for `scene`, one per method (views of one method share it)
  std::vector<Eigen::MatrixXd> deformed;  // latest deformed points per view (views())
  std::uint64_t deformGeneration = 0;     // bumps when `deformed` changes (position upload)
  bool deformDirty = true;
  DeviceState devices;  // where each frame is deformed (frame_device_evaluators.h; chosen once the GL context exists)
  // In place on OpenGL: views whose `deformed` entry is stale (the Renderer deformed them on the GPU);
  // ensureCpuPoints() computes them on the CPU when something needs the numbers (framing, export).
  std::vector<std::size_t> cpuStale;
  // The shown scene's precompute was cancelled (Esc, Cancel) with deformers missing: the scene stays at rest, and
  // the next edit of the pose or the parameters starts the precompute again (setPose / setParams; docs/editor.md).
  bool precomputeCancelled = false;
};

// Views and quantities: what is shown and how (view state: no edit, not undone). Panels and input change it freely;
// a change that needs deformers goes through setCompare / setCompareViews / setMethodOptions (they precompute).
struct ViewState {
  // The single view's method options (sessions' "methodOptions"; the panel's tetrahedra for Phong); those the
  // method has apply (withMethod), e.g. Phong's {"tet-level": "2"}.
  MethodOptions methodOptions;
  bool compare = false;
  std::vector<ViewSpec> compareViews = viewsOf(defaultCompareMethods());  // the panes while `compare` is on
  ViewQuantities quantities;  // what each view shows and its installed measurements (view_quantities.h)
  OrbitCamera camera;
  std::vector<ViewRect> panes = {ViewRect{0, 0, 1000, 625}};  // the views' panes (layout.h), set by the frame loop
  bool frameRequested = false;  // frame the rest scene once the viewports are known
  bool showCage = true;
  bool showMesh = true;
  bool showTets = false;  // the posed tetrahedra of views with a volume mesh (Phong), as a wireframe
  int wireframe = -1;     // -1: automatic (on in 2D), 0 off, 1 on
  bool flatShading = false;
  bool hideUi = false;
  bool showHistoryPanel = false;
  bool showShortcuts = false;     // F1
  bool showFrameTimings = false;  // Help > Frame timings
  std::string screenshotRequest;  // non-empty: write the next frame to this PNG
};

// Selection and interaction: what is selected and the mouse interaction under way (input.cpp, gizmo.cpp).
struct InputState {
  Selection selection;
  ElementMode elementMode = ElementMode::Vertex;  // what a click picks (1 / 2 / 3)
  Interaction mouse;
  // A panel's widget is held (a slider dragged, a field typed in; the frame loop sets it from ImGui before it polls
  // the jobs): its live edit is committed only when it lets go.
  bool widgetActive = false;
};

// A scene load in flight: what to apply when its scene arrives (showLoadedScene). Present from the request until its
// deformers arrive (installOutcome); its scene is shown as soon as the mesh has loaded.
struct PendingLoad {
  std::optional<std::string> documentPath;  // the session being opened
  bool restored = false;                    // a crashed run's autosave: unsaved from the start
  std::optional<Eigen::MatrixXd> pose;      // the pose to show on the new cage
  // A session's method, parameters, views, animation and camera: set when its scene is shown (applySessionSettings),
  // not when it is asked for, so that a load that fails or is cancelled leaves the open document as it was.
  std::optional<Session> session;
  PosedCageRead posed;                // a posed cage read on the load job against the new cage (path "": none)
  std::optional<RecentEntry> recent;  // the files being loaded; recorded when they arrive
  bool sceneShown = false;            // the loaded scene is shown (undeformed) while its deformers are computed
};

// Background work. Only the controller functions start or take jobs; the frame loop polls them.
struct JobsState {
  PrecomputeWorker precompute;  // scene loading and the deformers' precompute
  CageMaker cageMaker;          // File > Make cage... (its dialog and the preview)
  MeasureWorker measure;        // the views' quantities and the nu sweep (measure_worker.h, quantity_overlay.h)
  ExportWorker exporter;        // File > Export deformed mesh / animation (export_jobs.h)
  BackgroundJob<PosedCageLoad> posedCage;  // File > Load posed cage, a dropped posed cage: read here, never on the UI
  BackgroundJob<SessionRead> session;      // a session file being opened: read and parsed here (session_read.h)
  std::uint64_t sessionFrom = 0;           // the document's History::revision() when that read began
  std::optional<PendingLoad> load;
};

// Files and recent: the file dialog, recent files, dropped files, the crash-recovery offer (autosave.h).
struct FilesState {
  FileDialogState dialog;
  RecentFiles recent;
  std::string recentPath;  // where `recent` is saved after each change; "" keeps it in memory (tests, --screenshot)
  std::vector<std::string> droppedPaths;  // files dropped on the window (GLFW callback), opened by the frame loop
  std::optional<Session> restoreOffer;    // a crashed run's session: the Restore / Discard modal asks about it
  std::string restoreOfferTime;           // when it was saved, "2026-11-23 19:40"
};

// Status: statistics, the status line, errors, logs. Anyone may add a message or an error.
struct StatusState {
  Stats stats;
  std::vector<std::string> errors;  // shown one at a time in a modal
  std::string message;              // last action ("saved ...")
  std::string glRenderer;           // for the status bar
  bool logActions = false;          // --log-actions: keyboard commands are printed to stdout
  bool logFrames = false;           // --log-frames: each frame's timings on stdout (frame_timings.h)
  std::string hoverLogged;          // --log-actions: the hover readout line printed last (quantity_overlay.h)
};

struct AppState {
  DocumentState document;
  SceneState model;
  ViewState view;
  InputState input;
  AnimationState animation;  // pose library, timeline, playback (pose_keys.h)
  JobsState jobs;
  FilesState files;
  StatusState status;

  // The views shown, one per viewport: the compare view's list, or the current method with the shared parameters.
  std::vector<ViewSpec> views() const;
  // The view without compare: the current method with the shared parameters and its methodOptions.
  ViewSpec singleView() const;
  // The distinct deformers of the views (method and method options), one deformer each.
  std::vector<DeformerKey> deformerKeys() const;
  // The parameters view v deforms with (its own, else the panel's).
  DeformParams viewParams(std::size_t v) const { return views()[v].params(document.params); }
  int dim() const { return model.scene ? model.scene->dim() : 3; }
  bool loadingScene() const { return jobs.load.has_value(); }  // the running precompute replaces the scene
};

// The views shown with `compare` on or off (AppState::views), the single view of a method and its options
// (AppState::singleView), and the distinct deformers of `views` (AppState::deformerKeys).
std::vector<ViewSpec> shownViews(bool compare, const std::vector<ViewSpec>& compareViews, const ViewSpec& single);
ViewSpec singleViewOf(Method method, const MethodOptions& options);
std::vector<DeformerKey> deformerKeysOf(const std::vector<ViewSpec>& views);

// ---- controller functions (pure logic, used by the panels, the input handler and tests) ----

// Starts loading/precomputing a new scene on the worker; `load` is applied when it arrives (state.jobs.load holds it
// meanwhile), and its deformers are those of the views it will show (a session's). The current scene and document stay
// usable until then. A session still being read is cancelled: the newer request wins.
void requestScene(AppState& state, std::shared_ptr<const Scene> scene, PendingLoad load = {});
// The same with a loader run on the worker (the files read there).
void requestLoad(AppState& state, std::function<Scene()> loader, PendingLoad load = {});
void requestSceneFiles(AppState& state, const std::string& meshPath, const std::string& cagePath,
                       const std::string& posedPath = "");
void requestDemo(AppState& state, int dim, PendingLoad load = {});

// Starts precomputing the deformers the views need but do not have yet (no-op when nothing is missing or a
// scene is loading).
void ensureDeformers(AppState& state);

// Makes every background worker of the state (precompute, measurement and nu sweep, cage generation, export) call
// `wake` from its thread once it has finished: the frame loop's wake-up (editor.cpp: a flag and glfwPostEmptyEvent),
// without which a finished job would wait for the next mouse move to be drawn. Call it before starting any work.
void wakeOnFinish(AppState& state, const std::function<void()>& wake);

// Shows a load's scene as soon as its mesh has loaded (showLoadedScene), then takes a finished precompute outcome,
// if any, and installs it. Errors go to state.status.errors. Returns true when an outcome was installed.
bool pollWorker(AppState& state);
// Installs an outcome (also used by the screenshot path after waiting).
void installOutcome(AppState& state, PrecomputeOutcome outcome);
// Makes a loaded scene the one shown, at rest and undeformed, with what state.jobs.load says (pose, camera, posed
// cage, session, recent entry) as the new document's first step; its deformers come with installOutcome.
void showLoadedScene(AppState& state, std::shared_ptr<const Scene> scene);
// Makes `scene` the one shown with nothing derived from the previous one: no deformers, deformed points or nu sweep,
// a selection of its cage's size, no interaction in progress (showLoadedScene, replaceRestCage).
void installScene(AppState& state, std::shared_ptr<const Scene> scene);

// Deforms every view whose result is stale on the active device (deformOnDevice). Returns true when positions
// changed. In place on OpenGL it only marks the views for the Renderer (bumps deformGeneration) and leaves
// `deformed` stale (cpuStale).
bool updateDeformation(AppState& state);

// Brings `deformed[view]` up to date on the CPU when the in-place OpenGL path left it stale (framing, export).
void ensureCpuPoints(AppState& state, std::size_t view);

// Switches the device (recorded nowhere: not an edit). It takes effect only when usable (devices.usable).
void setDevice(AppState& state, const std::string& device);

// The points shown in view `view` (views()): deformed when available, else the rest mesh.
const Eigen::MatrixXd& displayedPoints(const AppState& state, std::size_t view);
bool hasDeformer(const AppState& state, const DeformerKey& key);

// ---- edits (history.h) ----
// A command changes the document (setPose / setParams / setMethod, which record nothing) and then commits it:
// commitEdit names the new state as one undo step (none when nothing changed). Live edits (a drag, a slider)
// commit once, when they end.
Document currentDocument(const AppState& state);
void applyDocument(AppState& state, const Document& document);  // restores exactly; no history
// Makes `cage` (read from cagePath; empty: from no file) the scene's rest cage, at rest, and precomputes its deformers
// (no history; Make cage commits).
void replaceRestCage(AppState& state, const Cage& cage, const std::string& cagePath = "");
bool commitEdit(AppState& state, const std::string& name);
// --log-actions: prints the line to stdout (the GUI tests wait for such lines: "step Grab", "job precompute").
void logLine(const AppState& state, const std::string& line);
void setPose(AppState& state, const Eigen::MatrixXd& pose);   // no history; marks dirty
void setParams(AppState& state, const DeformParams& params);  // no history; marks dirty
void setMethod(AppState& state, Method method);               // no history
void setMethodOptions(AppState& state, MethodOptions options);  // the single view's; no history (a view setting)
void resetPose(AppState& state);                              // committed: "Reset pose"
void undo(AppState& state);
void redo(AppState& state);
void jumpToStep(AppState& state, std::size_t step);  // the Undo History panel
// Unsaved changes: the document differs from its saved (or freshly opened) state.
bool hasUnsavedChanges(const AppState& state);
// "my_session" (the session file's name) or the scene's name; the window title adds "*" when unsaved.
std::string documentName(const AppState& state);
std::string windowTitle(const AppState& state);
void setCompare(AppState& state, bool on);
// The compare view's panes (2 to kMaxCompareViews; others are ignored): shown at once, their missing deformers
// precomputed. removeCompareView drops pane v (and its own Show choice), keeping two at least.
void setCompareViews(AppState& state, std::vector<ViewSpec> views);
void removeCompareView(AppState& state, std::size_t v);

// The selection's centroid on the posed cage, in 3D (z = 0 in 2D): the gizmo's pivot.
Eigen::Vector3d selectionPivot(const AppState& state);
// Frames the current pose and the displayed mesh (F), clear of the panes' overlays and with the selection's gizmo
// inside the pane ("Framing" in docs/editor.md); frameRest frames the rest cage and mesh.
void frameAll(AppState& state);
void frameRest(AppState& state);

// Sessions and files (errors go to state.errors, never thrown).
Session makeSession(const AppState& state);
// A session of another scene loads it on the worker (what `load` says is applied when it arrives, with the session's
// settings, pose and camera); one of the scene shown is applied at once as the edit "Load session".
void applySession(AppState& state, const Session& session, PendingLoad load = {});
// The session's method, parameters, views and animation (not its scene, pose or camera).
void applySessionSettings(AppState& state, const Session& session);
// The views the session shows once applied: its panes, or the editor's when it names none.
std::vector<ViewSpec> sessionViews(const AppState& state, const Session& session);
// Each returns true on success. They write where they are told: the dialogs check the paths (file_dialog.h).
bool savePosedCage(AppState& state, const std::string& path);
// Starts reading the posed cage on JobsState::posedCage (false without a scene); pollPosedCage applies it when it
// arrives, as the edit "Load posed cage", if its scene is still shown (else, or when it cannot be read, an error).
bool loadPosedCage(AppState& state, const std::string& path);
bool pollPosedCage(AppState& state);  // the frame loop's: true when a pose was applied
// Starts the export on state.exporter (export_jobs.cpp); false when another export runs.
bool exportDeformedMesh(AppState& state, const std::string& path);
bool saveSessionFile(AppState& state, const std::string& path);  // marks the document saved
// Starts reading the session file on JobsState::session (superseding one being read; `read`: a test's reader) and
// returns; pollSessionRead applies it on the UI thread once read (as applySession), or reports why it could not be read
// (the InputError: file, line, what is wrong). A cancel (Esc, the panel's Cancel) or an error leaves the document as
// it was. The caller has asked about unsaved changes (guardUnsaved); if the document changed while the file was read
// (a commit, undo, redo or jump) and is unsaved, the read session waits for the same question again (Save / Don't
// save apply it, Cancel drops it), and a finished read is not taken while a question is shown or a live edit (a
// handle, G / R / S, a held widget) is under way.
void loadSessionFile(AppState& state, const std::string& path, SessionReader read = readSessionFile);
bool pollSessionRead(AppState& state);  // the frame loop's: true when a read session was applied

// Crash recovery: applies state.restoreOffer (the Restore button, --restore-autosave) or drops it (Discard).
void acceptRestoreOffer(AppState& state);
void discardRestoreOffer(AppState& state);

// Opens files dropped on the window (see planDrop in drop.h): mesh + cage (+ posed cage) load on the worker like
// the Open panel, one posed cage poses the current scene (counted and read on JobsState::posedCage, as
// loadPosedCage), a .json loads a session; anything else puts what to drop
// in state.errors.
void openDroppedFiles(AppState& state, const std::vector<std::string>& paths);

// Recent files: records an opened entry (paths made absolute) and saves the list to state.recentPath when set (a
// failure to save is reported in the status bar only); openRecent opens an entry like the Open panel.
void noteRecent(AppState& state, RecentEntry entry);
void openRecent(AppState& state, const RecentEntry& entry);

// "Somigliana  nu=0.30 gamma=1.00 global" etc. for view v; a parameter of the view's own is marked "(own)".
std::string viewLabel(const AppState& state, std::size_t v);
// "Somigliana", or "Somigliana nu=0.45" for a view with its own nu: tells panes of one method apart in menus.
std::string viewShortName(const AppState& state, std::size_t v);

}  // namespace somicage::editor
