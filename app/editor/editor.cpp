#include "editor.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "base/errors.h"
#include "deform/parameter_schema.h"
#include "editor_options.h"
#include "editor_renderer.h"
#include "frame_pacing.h"
#include "generation/cage_generation.h"
#include "gl_context.h"
#include "gpu_deformer.h"
#include "interaction/event_queue.h"
#include "interaction/input.h"
#include "jobs/animation_export_job.h"
#include "jobs/cage_maker.h"
#include "jobs/export_jobs.h"
#include "model/app_state.h"
#include "model/autosave.h"
#include "model/fig8_demo.h"
#include "model/frame_device_evaluators.h"
#include "model/pose_keys.h"
#include "model/recent_files.h"
#include "model/view_quantity.h"
#include "ui/cage_maker_panel.h"
#include "ui/export_panel.h"
#include "ui/file_dialog.h"
#include "ui/frame_timings.h"
#include "ui/layout.h"
#include "ui/panels.h"
#include "ui/quantity_overlay.h"
#include "ui/screenshot.h"
#include "ui/timeline_panel.h"
#include "ui/unsaved_changes.h"

namespace somicage {

namespace {

using namespace editor;

void glfwErrorCallback(int code, const char* description) {
  std::fprintf(stderr, "somicage: GLFW error %d: %s\n", code, description);
}

// Applies the command-line choices that do not depend on the scene.
void applyOptions(AppState& state, const EditorOptions& o) {
  if (o.method) state.document.method = *o.method;
  if (!o.methodOptions.empty()) state.view.methodOptions = o.methodOptions;
  for (const ParameterSpec& spec : parameterSchema())  // variant before blend
    if (const auto it = o.parameters.find(spec.key); it != o.parameters.end())
      setParameter(spec, state.document.params, it->second);
  if (!o.views.empty()) {
    state.view.compare = true;
    state.view.compareViews = o.views;
  }
  state.view.hideUi = o.hideUi;
  state.view.flatShading = o.flatShading;
  state.view.quantities.show = o.show;
  for (const ViewShow& view : o.show.views)
    if (o.range && view.quantity > 0) state.view.quantities.show.ranges[view.quantity] = RangeSetting{true, *o.range};
  state.view.showCage = !o.hideCage;
  state.view.showTets = o.showTets;
}

// The devices the editor offers, whether the in-place OpenGL one can run in this context, and the default: opengl on
// a hardware GPU; cpu on a software renderer (Mesa llvmpipe runs compute shaders on the CPU, an order of magnitude
// slower than core's evaluateFrame: see render/gpu_deformer.cpp), unless --device says otherwise.
void chooseDevices(AppState& state, const EditorOptions& options, const FrameDevices& devices) {
  std::string glProblem;
  const bool gl = render::GpuDeformer::available(&glProblem);
  const bool software = gl && render::GpuDeformer::softwareRenderer();
  state.model.devices.note = software ? "this OpenGL renders on the CPU (" + state.status.glRenderer +
                                            "): opengl works but is slower than cpu here"
                                      : "";
  const std::string refused = chooseDevice(state.model.devices, devices, options.device,
                                           gl && !software ? kInPlaceDevice : kCpuDevice, glProblem);
  if (!refused.empty())
    std::fprintf(stderr, "somicage: --device %s: %s; deforming on the CPU\n", options.device->c_str(), refused.c_str());
}

// What the GLFW callbacks reach through the window user pointer: the state (drops), the input queue, and whether
// anything happened since the last frame. Lives inside runWindow's state block; the callbacks are removed before
// it goes.
struct WindowLink {
  AppState* state = nullptr;
  InputEventQueue queue;
  bool activity = true;
};

WindowLink* link(GLFWwindow* window) { return static_cast<WindowLink*>(glfwGetWindowUserPointer(window)); }

// ImGui's backend is initialised without its callbacks: these queue the input (event_queue.h) and forward the
// rest at once, chained the way ImGui_ImplGlfw_InitForOpenGL(window, true) would.
void keyCallback(GLFWwindow* w, int key, int scancode, int action, int mods) {
  if (WindowLink* l = link(w)) l->queue.push(InputEvent::key(key, scancode, action, mods));
}
void charCallback(GLFWwindow* w, unsigned codepoint) {
  if (WindowLink* l = link(w)) l->queue.push(InputEvent::character(codepoint));
}
void mouseButtonCallback(GLFWwindow* w, int button, int action, int mods) {
  if (WindowLink* l = link(w)) l->queue.push(InputEvent::mouseButton(button, action, mods));
}
void scrollCallback(GLFWwindow* w, double dx, double dy) {
  if (WindowLink* l = link(w)) l->queue.push(InputEvent::scroll(dx, dy));
}
void noteActivity(GLFWwindow* w) {
  if (WindowLink* l = link(w)) l->activity = true;
}
void focusCallback(GLFWwindow* w, int focused) {
  ImGui_ImplGlfw_WindowFocusCallback(w, focused);
  noteActivity(w);
}
void cursorEnterCallback(GLFWwindow* w, int entered) {
  ImGui_ImplGlfw_CursorEnterCallback(w, entered);
  noteActivity(w);
}
void cursorPosCallback(GLFWwindow* w, double, double) { noteActivity(w); }  // ImGui 1.86 polls the position
void sizeCallback(GLFWwindow* w, int, int) { noteActivity(w); }
void refreshCallback(GLFWwindow* w) { noteActivity(w); }

// GLFW 3.3 drop callback: queues the paths; the frame loop opens them.
void dropCallback(GLFWwindow* window, int count, const char** paths) {
  WindowLink* l = link(window);
  if (!l || !l->state) return;
  std::vector<std::string> dropped;
  for (int i = 0; i < count; ++i) dropped.emplace_back(paths[i]);
  l->state->files.droppedPaths = std::move(dropped);  // one drop per event; a newer one replaces an unhandled one
  l->activity = true;
}

void installCallbacks(GLFWwindow* window, WindowLink* windowLink) {
  glfwSetWindowUserPointer(window, windowLink);
  glfwSetKeyCallback(window, windowLink ? keyCallback : nullptr);
  glfwSetCharCallback(window, windowLink ? charCallback : nullptr);
  glfwSetMouseButtonCallback(window, windowLink ? mouseButtonCallback : nullptr);
  glfwSetScrollCallback(window, windowLink ? scrollCallback : nullptr);
  glfwSetWindowFocusCallback(window, windowLink ? focusCallback : nullptr);
  glfwSetCursorEnterCallback(window, windowLink ? cursorEnterCallback : nullptr);
  glfwSetCursorPosCallback(window, windowLink ? cursorPosCallback : nullptr);
  glfwSetWindowSizeCallback(window, windowLink ? sizeCallback : nullptr);
  glfwSetWindowRefreshCallback(window, windowLink ? refreshCallback : nullptr);
  glfwSetDropCallback(window, windowLink ? dropCallback : nullptr);
}

// Hands this frame's share of the queued input to ImGui's backend, in order.
void feedInput(GLFWwindow* window, InputEventQueue& queue) {
  for (const InputEvent& e : queue.takeFrame(ImGui::GetIO().WantTextInput)) {
    switch (e.type) {
      case InputEvent::Type::Key:
        ImGui_ImplGlfw_KeyCallback(window, e.code, e.scancode, e.action, e.mods);
        break;
      case InputEvent::Type::Char:
        ImGui_ImplGlfw_CharCallback(window, static_cast<unsigned>(e.code));
        break;
      case InputEvent::Type::MouseButton:
        ImGui_ImplGlfw_MouseButtonCallback(window, e.code, e.action, e.mods);
        break;
      case InputEvent::Type::Scroll:
        ImGui_ImplGlfw_ScrollCallback(window, e.dx, e.dy);
        break;
    }
  }
}

void updateTitle(GLFWwindow* window, const AppState& state, std::string& shown) {
  const std::string title = windowTitle(state);
  if (title != shown) {
    glfwSetWindowTitle(window, title.c_str());
    shown = title;
  }
}

// One frame: queued input, worker results, UI, deformation, drawing, optional screenshot, swap. Events are
// polled (or waited for) by the caller.
void frame(GLFWwindow* window, AppState& state, Renderer& renderer, std::string& title, InputEventQueue& queue) {
  using Clock = std::chrono::steady_clock;
  const auto msSince = [](Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
  };
  const auto frameStart = Clock::now();
  FrameTimings& timings = state.status.stats.frame;
  timings = FrameTimings{};
  timings.frame = state.status.stats.frames.last().frame + 1;
  state.status.stats.timeFrames = state.view.showFrameTimings || state.status.logFrames;
  feedInput(window, queue);
  if (pollWorker(state)) {  // --log-actions: the GUI tests wait for it; the benchmarks read the seconds
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, " %.3f", state.status.stats.precomputeSeconds);
    logLine(state, "job precompute" + std::string(seconds));
  }
  const std::uint64_t candidateShown = state.jobs.cageMaker.candidateGeneration();
  state.jobs.cageMaker.poll();
  if (state.status.logActions && state.jobs.cageMaker.candidateGeneration() != candidateShown &&
      state.jobs.cageMaker.candidate()) {
    std::printf("cage candidate %d faces\n", state.jobs.cageMaker.candidate()->generated.cage.numFaces());  // GUI tests
    std::fflush(stdout);
  }
  pollExport(state);
  pollPosedCage(state);
  state.input.widgetActive = ImGui::IsAnyItemActive();  // as the last frame left it: a slider still held
  pollSessionRead(state);
  if (!state.files.droppedPaths.empty()) {
    std::vector<std::string> dropped;
    dropped.swap(state.files.droppedPaths);
    openDroppedFiles(state, dropped);
  }

  auto uiStart = Clock::now();  // the UI's time: the windows built, then their draw data rendered
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const ImGuiIO& io = ImGui::GetIO();

  const double top = state.view.hideUi ? 0.0 : menuBarHeight();
  const double left = state.view.hideUi ? 0.0 : panelWidth(io.DisplaySize.x);
  const double bottom =
      state.view.hideUi ? 0.0 : statusBarHeight() + (state.animation.showPanels ? timelinePanelHeight() : 0.0);
  const std::vector<ViewRect> views =
      layoutViews(io.DisplaySize.x, io.DisplaySize.y, left, top, bottom, static_cast<int>(state.views().size()));
  state.view.panes = views;
  if (!state.view.hideUi) {
    drawMainMenu(state);
    drawControlPanel(state);
    drawStatusBar(state);
    drawViewLabels(state, views);
    drawHistoryPanel(state);
    drawShortcutSheet(state);
    drawFileDialog(state);
    if (state.animation.showPanels) {
      drawTimelinePanel(state, left, statusBarHeight());
      drawPoseLibraryPanel(state, top);
    }
    drawAnimationExportDialogs(state);
    drawCageMakerDialog(state);
    drawExportProgress(state);
    drawFrameTimingsWindow(state.status.stats.frames, &state.view.showFrameTimings);
  }
  drawErrorModal(state);
  drawRestoreModal(state);
  drawUnsavedModal(state);
  handleInput(state, views);
  tickPlayback(state, glfwGetTime());
  showNextExportFrame(state);
  timings.uiMs += msSince(uiStart);
  updateDeformation(state);
  if (state.view.frameRequested) {  // after the deformation: the deformed mesh and the posed cage are both framed
    frameAll(state);
    state.view.frameRequested = false;
  }
  const auto measureStart = Clock::now();
  measureViews(state);
  logHoverReadout(state, drawQuantityOverlay(state, views));
  timings.measureMs = msSince(measureStart);
  renderer.sync(state);
  uiStart = Clock::now();
  ImGui::Render();
  timings.uiMs += msSince(uiStart);

  int fbWidth = 0, fbHeight = 0;
  glfwGetFramebufferSize(window, &fbWidth, &fbHeight);
  const double scale = io.DisplaySize.x > 0 ? fbWidth / static_cast<double>(io.DisplaySize.x) : 1.0;
  renderer.draw(state, views, fbWidth, fbHeight, scale, state.status.stats.timeFrames ? &timings : nullptr);
  captureExportFrame(state, fbWidth, fbHeight);  // the views without the panels
  uiStart = Clock::now();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (state.status.stats.timeFrames) render::finishGl();
  timings.uiMs += msSince(uiStart);

  if (!state.view.screenshotRequest.empty()) {
    const std::string path = state.view.screenshotRequest;
    state.view.screenshotRequest.clear();
    try {
      writePng(path, fbWidth, fbHeight, render::readPixelsRgba(fbWidth, fbHeight));
      state.status.message = "saved screenshot " + path;
    } catch (const std::exception& e) {
      state.status.errors.push_back(e.what());
    }
  }
  const auto swapStart = Clock::now();
  glfwSwapBuffers(window);
  timings.swapMs = msSince(swapStart);
  updateTitle(window, state, title);
  timings.totalMs = msSince(frameStart);
  state.status.stats.frames.add(timings);
  if (state.status.logFrames) {  // --log-frames: tests and benchmarks read these lines
    std::printf("%s\n", frameLogLine(timings).c_str());
    std::fflush(stdout);
  }
}

// "legend ID: LO HI" per shown quantity (full precision), for scripts and tests.
void printLegends(const AppState& state) {
  std::vector<int> printed;
  for (std::size_t v = 0; v < state.views().size(); ++v) {
    const int quantity = state.view.quantities.show.view(v).quantity;
    if (quantity == 0 || std::find(printed.begin(), printed.end(), quantity) != printed.end()) continue;
    printed.push_back(quantity);
    const ColorRange range = shownRange(state, quantity);
    std::printf("legend %s: %.17g %.17g\n", quantityDescriptor(quantity).id, range.lo, range.hi);
  }
}

// Anything that needs frames without new input.
bool changing(const AppState& state) {
  return state.model.deformDirty || !state.view.screenshotRequest.empty() || !state.files.droppedPaths.empty() ||
         state.view.frameRequested || state.input.mouse.mode != Interaction::Mode::Idle;
}

// Writes the session when the interval has passed and it changed; not while a scene loads (the pose would not match
// the files) or while a crashed session waits for Restore / Discard (it would be overwritten).
void autosaveTick(Autosave& autosave, AppState& state) {
  if (!state.model.scene || state.loadingScene() || state.files.restoreOffer) return;
  try {
    autosave.tick(makeSession(state), glfwGetTime());
  } catch (const std::exception& e) {
    state.status.message = std::string("autosave failed: ") + e.what();
  }
}

// A --screenshot run: the scene and its deformers, Make cage's candidate (--make-cage), the measurements and the nu
// sweep (--nu-plot), then the picture, each step taken once the jobs it needs have finished. Nothing here waits for
// a job: the loop sleeps until a job's wake-up (glfwPostEmptyEvent, wakeOnFinish) and polls them, as the interactive
// loop does. Returns the exit code.
int runScripted(GLFWwindow* window, AppState& state, Renderer& renderer, InputEventQueue& queue,
                const EditorOptions& options) {
  const auto sleepUntilWoken = [] { glfwWaitEventsTimeout(0.25); };  // a wake-up posted before it ends it at once
  const auto fail = [&state](int rc) {
    for (const std::string& e : state.status.errors) std::fprintf(stderr, "somicage: %s\n", e.c_str());
    return rc;
  };
  for (;;) {  // the session (--session), the scene, then every deformer the views need (or an error)
    pollSessionRead(state);
    pollWorker(state);
    if (!state.status.errors.empty()) return fail(2);
    const bool reading = state.jobs.session.busy() || state.jobs.session.ready();  // ready: read since the poll
    if (!reading && !state.loadingScene() && !state.jobs.precompute.busy()) {
      if (!state.model.scene) return fail(2);
      ensureDeformers(state);
      if (!state.jobs.precompute.busy()) break;
    }
    sleepUntilWoken();
  }
  const int cageVertices = state.model.scene->restCage.numVertices();
  if (options.showFieldVertex >= cageVertices) {
    std::fprintf(stderr, "somicage: --show field:%d: the cage has %d vertices (0 .. %d)\n", options.showFieldVertex,
                 cageVertices, cageVertices - 1);
    return 2;
  }
  if (options.showFieldVertex >= 0) state.input.selection.setIndices({options.showFieldVertex});
  if (options.makeCageFaces > 0) {  // the dialog and its preview, once generated
    openCageMaker(state, options.makeCageFaces);
    for (state.jobs.cageMaker.poll(); state.jobs.cageMaker.status() == CageMaker::Status::Generating;
         state.jobs.cageMaker.poll())
      sleepUntilWoken();
    if (const auto& candidate = state.jobs.cageMaker.candidate()) {
      const GeneratedCage& g = candidate->generated;
      std::printf("make-cage: %d faces, min angle %.2f deg, volume ratio %.4g, Hausdorff %.4g diagonals\n",
                  g.cage.numFaces(), g.minAngleDegrees, g.tightness.volumeRatio, g.tightness.hausdorff);
    } else if (state.status.errors.empty()) {
      state.status.errors.push_back("make cage: " + state.jobs.cageMaker.error());
    }
  }
  if (options.exportDialog) {  // as File > Export animation... does, with the given file
    state.animation.exportPath = *options.exportDialog;
    state.animation.exportDialogRequested = true;
    state.animation.showPanels = true;
  }
  // A few frames let ImGui settle its layout before the capture; the measurements are polled for.
  std::string title;
  for (int i = 0; i < 4; ++i) {
    if (i == 1 && options.nuPlot) sweepNuNow(state);  // after the first deformation
    if (i >= 1)
      while (!measurementsSettled(state)) sleepUntilWoken();
    if (i == 3) state.view.screenshotRequest = options.screenshotPath;
    frame(window, state, renderer, title, queue);
  }
  if (!state.status.errors.empty()) return fail(1);
  std::printf("wrote %s (deformation device: %s)\n", options.screenshotPath.c_str(),
              state.model.devices.active().c_str());
  printLegends(state);
  return 0;
}

// Opens the window with its OpenGL context, or says why it cannot and returns null. `glRenderer` names the driver.
GLFWwindow* openWindow(const EditorOptions& options, std::string& glRenderer) {
  // OpenGL 4.3 core when the driver has it (compute shaders: the GPU deformation backend), else 3.3 core.
  int major = 4;
  auto createWindow = [&](int samples) {
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, major);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, samples);
    return glfwCreateWindow(options.width, options.height, "SomiCage", nullptr, nullptr);
  };
  glfwSetErrorCallback(nullptr);  // a refused 4.3 context is not an error worth printing
  GLFWwindow* window = createWindow(4);
  glfwSetErrorCallback(glfwErrorCallback);
  if (!window) {
    major = 3;
    window = createWindow(4);
  }
  if (!window) {
    std::fprintf(stderr,
                 "somicage: could not create an OpenGL 3.3 core window (update the graphics driver, or use\n"
                 "Mesa: LIBGL_ALWAYS_SOFTWARE=1)\n");
    return nullptr;
  }
  glfwMakeContextCurrent(window);
  const bool headless = !options.screenshotPath.empty();
  try {
    render::GlInfo info = render::initOpenGl(glfwGetProcAddress);
    // A software renderer (llvmpipe) shades every sample: 4x multisampling made FIREHYDRANT's pane 6x slower to draw
    // (docs/editor.md, "Frame timings"). Interactive windows there go without it; pictures (--screenshot) keep it.
    if (!headless && render::GpuDeformer::softwareRenderer()) {
      glfwDestroyWindow(window);
      window = createWindow(0);
      if (!window) throw std::runtime_error("could not create the OpenGL window again without multisampling");
      glfwMakeContextCurrent(window);
      info = render::initOpenGl(glfwGetProcAddress);
    }
    glRenderer = info.renderer + " (OpenGL " + info.version + ")";
  } catch (const std::exception& e) {
    std::fprintf(stderr, "somicage: %s\n", e.what());
    if (window) glfwDestroyWindow(window);
    return nullptr;
  }
  glfwSwapInterval(headless ? 0 : 1);
  return window;
}

// The scene the editor opens with when no session or crashed run's session gives one: the files on the command line,
// or a demo.
void requestStartScene(AppState& state, const EditorOptions& options) {
  if (!options.meshPath.empty()) {
    requestSceneFiles(state, options.meshPath, options.cagePath, options.posedPath);
  } else {
    options.demoFig8 ? requestFig8Demo(state, !options.views.empty()) : requestDemo(state, options.demoDim);
  }
}

// Whether the start scene can be requested before the window exists: its files then load and its coordinates are
// computed while the window and its OpenGL context open (0.26 s on llvmpipe; docs/editor.md, "Time to the first
// frame"). Not for a session or a restore (their scene comes with the document), nor when the chosen device
// integrates the coordinates itself (CUDA), which is known only once the devices are chosen.
bool sceneBeforeWindow(const EditorOptions& options, const FrameDevices& devices) {
  if (options.restoreAutosave || !options.sessionPath.empty()) return false;
  const FrameDevice* device = options.device ? findFrameDevice(devices, *options.device) : nullptr;
  return !device || !device->rowIntegrator;
}

// The editor from its state on: the state (which holds no OpenGL object: the Renderer does) comes before the window,
// so the start scene can load meanwhile, and goes after it.
int runWithState(const EditorOptions& options, const FrameDevices& devices) {
  AppState state;
  // A worker that finishes wakes the loop (glfwPostEmptyEvent may be called from any thread) and counts as input:
  // the next frames install its outcome and let ImGui settle the windows it resizes (docs/editor.md, "Idle").
  auto jobFinished = std::make_shared<std::atomic<bool>>(false);
  wakeOnFinish(state, [jobFinished] {
    jobFinished->store(true);
    glfwPostEmptyEvent();
  });
  applyOptions(state, options);
  const bool sceneRequested = sceneBeforeWindow(options, devices);
  if (sceneRequested) requestStartScene(state, options);

  std::string glRenderer;
  GLFWwindow* window = openWindow(options, glRenderer);
  if (!window) return 1;
  const bool headless = !options.screenshotPath.empty();

  int rc = 0;
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
  ImGui::StyleColorsDark();
  ImGui::GetStyle().WindowRounding = 0.0f;
  ImGui_ImplGlfw_InitForOpenGL(window, false);  // our callbacks queue the input (installCallbacks)
  ImGui_ImplOpenGL3_Init("#version 330 core");

  try {
    Renderer renderer;  // its GL objects go before the context
    state.status.glRenderer = glRenderer;
    chooseDevices(state, options, devices);
    // Recent files persist only in interactive use: a --screenshot run must not touch the user's list.
    if (!headless) {
      state.files.recentPath = recentFilesPath(std::getenv("XDG_CONFIG_HOME"), std::getenv("HOME"));
      state.files.recent = loadRecentFiles(state.files.recentPath);
    }
    state.status.logActions = options.logActions;
    state.status.logFrames = options.logFrames;
    // Events are polled only inside this block, so the pointer never outlives `state`.
    WindowLink windowLink;
    windowLink.state = &state;
    installCallbacks(window, &windowLink);
    // Crash safety (autosave.h): interactive runs autosave and offer a crashed run's session; a --screenshot run
    // only reads one when asked to restore it, and never writes the user's files.
    std::optional<Autosave> autosave;
    const AutosavePaths autosaveFiles = autosavePaths(std::getenv("XDG_CONFIG_HOME"), std::getenv("HOME"));
    AutosaveLeftover leftover;
    if (!headless) {
      autosave.emplace(autosaveFiles);
      leftover = autosave->begin();
    } else if (options.restoreAutosave) {
      leftover = findAutosaveLeftover(autosaveFiles);
    }
    if (!leftover.error.empty()) state.status.errors.push_back(leftover.error);
    if (leftover.otherEditorRunning)
      state.status.message = "another SomiCage editor is running: this one does not autosave";
    state.files.restoreOffer = leftover.session;
    state.files.restoreOfferTime = leftover.savedAt;
    if (options.restoreAutosave && !state.files.restoreOffer)
      std::fprintf(stderr, "somicage: --restore-autosave: no session of a crashed run to restore\n");

    if (options.restoreAutosave && state.files.restoreOffer) {
      acceptRestoreOffer(state);
    } else if (!options.sessionPath.empty()) {
      loadSessionFile(state, options.sessionPath);
    } else if (!sceneRequested) {
      requestStartScene(state, options);
    }
    if (headless) {
      rc = runScripted(window, state, renderer, windowLink.queue, options);
    } else {
      std::string title;
      FramePacer pacer;
      auto last = std::chrono::steady_clock::now();
      while (!state.document.quitRequested) {
        FrameDemand demand;
        demand.queued = !windowLink.queue.empty();
        demand.busy = state.jobs.precompute.busy() || state.jobs.exporter.busy() || state.jobs.posedCage.busy() ||
                      state.jobs.session.busy() || state.jobs.measure.busy() || state.jobs.measure.ready() ||
                      state.view.quantities.sweepRequested || state.loadingScene() || state.animation.playing ||
                      state.jobs.cageMaker.status() == CageMaker::Status::Generating ||
                      state.animation.exportJob.has_value();  // playback and export draw every frame
        demand.changing = changing(state);
        const double wait = pacer.waitSeconds(demand);
        wait > 0 ? glfwWaitEventsTimeout(wait) : glfwPollEvents();
        if (glfwWindowShouldClose(window)) {  // the window's close button asks like Ctrl+Q
          glfwSetWindowShouldClose(window, GLFW_FALSE);
          requestQuit(state);
          windowLink.activity = true;
        }
        demand.input = windowLink.activity || jobFinished->exchange(false);
        demand.queued = !windowLink.queue.empty();
        windowLink.activity = false;
        if (pacer.shouldDraw(demand)) {
          frame(window, state, renderer, title, windowLink.queue);
          if (options.frameDelayMs > 0) std::this_thread::sleep_for(std::chrono::milliseconds(options.frameDelayMs));
          const auto now = std::chrono::steady_clock::now();
          const double dt = std::chrono::duration<double>(now - last).count();
          last = now;
          if (dt > 0 && dt < 1.0)
            state.status.stats.fps = state.status.stats.fps > 0 ? 0.9 * state.status.stats.fps + 0.1 / dt : 1.0 / dt;
        }
        if (autosave) autosaveTick(*autosave, state);
      }
      state.jobs.precompute.cancel();
      // The user chose to quit (and answered the unsaved-changes question): only now the autosave goes.
      if (autosave) autosave->finish();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "somicage: %s\n", e.what());
    rc = 1;
  }
  installCallbacks(window, nullptr);  // `state` and the queue are gone

  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  return rc;
}

int runWindow(const EditorOptions& options, const FrameDevices& devices) {
  glfwSetErrorCallback(glfwErrorCallback);
  if (!glfwInit()) {
    std::fprintf(stderr,
                 "somicage: cannot open a window (no display?). Run it on a desktop, or headless with\n"
                 "  xvfb-run -a -s \"-screen 0 1600x900x24\" somicage ...\n"
                 "For batch work without a window see 'somicage help'.\n");
    return 1;
  }
  const int rc = runWithState(options, devices);
  glfwTerminate();  // after the state: its jobs may wake the loop (glfwPostEmptyEvent) until they are gone
  return rc;
}

}  // namespace

int runEditor(int argc, char** argv, const FrameDevices& devices) {
  EditorOptions options;
  try {
    options = parseEditorArgs(std::vector<std::string>(argv + 1, argv + argc));
    checkDeviceOption(options, devices);
  } catch (const InputError& e) {
    std::fprintf(stderr, "somicage: %s\n", e.what());
    return 2;
  }
  if (options.help) {
    std::fputs(editorUsage().c_str(), stdout);
    return 0;
  }
  return runWindow(options, devices);
}

}  // namespace somicage
