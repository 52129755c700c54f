#include "ui/panels.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "deform/method.h"
#include "engine/view_spec.h"
#include "generation/cage_generation.h"
#include "geometry/volume_mesh.h"
#include "interaction/element_pick.h"
#include "interaction/shortcuts.h"
#include "jobs/cage_maker.h"
#include "jobs/thread_budget.h"
#include "model/fig8_demo.h"
#include "model/frame_device_evaluators.h"
#include "model/history.h"
#include "model/recent_files.h"
#include "ui/compare_views_panel.h"
#include "ui/file_dialog.h"
#include "ui/pane_overlays.h"
#include "ui/parameter_panel.h"
#include "ui/quantity_overlay.h"
#include "ui/unsaved_changes.h"

namespace somicage::editor {

namespace {

// A titled separator (ImGui 1.86 has no SeparatorText).
void sectionHeader(const char* title) {
  ImGui::Spacing();
  ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "%s", title);
  ImGui::Separator();
}

void openDemo(AppState& state, int dim) {
  guardUnsaved(state, dim == 2 ? "open the 2D demo" : "open the 3D demo", [dim](AppState& s) { requestDemo(s, dim); });
}

}  // namespace

void tooltip(const char* text) {
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", text);
}

double panelWidth(double windowWidth) { return std::clamp(0.42 * windowWidth, 220.0, 340.0); }

double menuBarHeight() { return ImGui::GetFrameHeight(); }
double statusBarHeight() { return ImGui::GetFrameHeight() + 6.0; }

namespace {

// File > Open Recent: the recent scenes and sessions (the Open panel's list), most recent first; an entry whose file
// is gone is greyed out and its tooltip names the file.
void drawOpenRecentMenu(AppState& state) {
  const std::vector<RecentEntry> entries = state.files.recent.entries();  // a copy: opening one reorders the list
  if (!ImGui::BeginMenu("Open Recent", !entries.empty())) return;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const RecentEntry& e = entries[i];
    const std::string missing = missingRecentPath(e);
    ImGui::PushID(static_cast<int>(i));
    const bool clicked = ImGui::MenuItem(e.label().c_str(), nullptr, false, missing.empty());
    std::string tip;
    for (const std::string& path : e.paths()) tip += path + "\n";
    tooltip((missing.empty() ? tip : tip + "missing: " + missing).c_str());
    ImGui::PopID();
    if (clicked) openRecent(state, e);
  }
  ImGui::EndMenu();
}

}  // namespace

// A menu item for a command of the shortcut table (shortcuts.h): its key label comes from there.
void commandItem(AppState& state, const char* label, const char* id, bool enabled = true) {
  if (ImGui::MenuItem(label, shortcutLabel(id), false, enabled)) runCommand(state, id);
}

void drawMainMenu(AppState& state) {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    commandItem(state, "New (3D demo)", "new");
    commandItem(state, "Open mesh + cage...", "open");
    drawOpenRecentMenu(state);
    if (ImGui::MenuItem("2D demo")) openDemo(state, 2);
    if (ImGui::MenuItem("Fig. 8 demo")) guardUnsaved(state, "open the Fig. 8 demo", [](AppState& s) { requestFig8Demo(s); });
    tooltip("The paper's Fig. 8: the bar twisted, Phong (James 2020) over a coarse and a finer tetrahedral mesh\n"
            "of the cage beside Somigliana local nu = 0. Phong creases where the mesh crosses tetrahedra.");
    ImGui::Separator();
    if (ImGui::MenuItem("Load posed cage...")) openFileDialog(state, FileDialogPurpose::LoadPose);
    if (ImGui::MenuItem("Save posed cage...")) openFileDialog(state, FileDialogPurpose::SavePose);
    commandItem(state, "Export deformed mesh...", "export");
    const bool meshReady = state.model.scene && !state.loadingScene() && state.dim() == 3;
    if (ImGui::MenuItem("Make cage...", nullptr, false, meshReady)) {  // cage_maker.h
      openCageMaker(state, std::clamp(state.model.scene->restCage.numFaces(), CageGenerationOptions::kMinFaces, 2000));
      if (state.status.logActions) std::printf("dialog Make cage\n"), std::fflush(stdout);
    }
    if (ImGui::MenuItem("Export animation...")) {
      state.animation.exportDialogRequested = true;
      state.animation.showPanels = true;  // the dialog is drawn with the panels' code
    }
    ImGui::Separator();
    commandItem(state, "Open session...", "open_session");
    commandItem(state, "Save session", "save");
    commandItem(state, "Save session as...", "save_as");
    ImGui::Separator();
    if (ImGui::MenuItem("Screenshot...", shortcutLabel("screenshot")))
      openFileDialog(state, FileDialogPurpose::Screenshot);
    ImGui::Separator();
    commandItem(state, "Quit", "quit");
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    commandItem(state, "Undo", "undo", state.document.history.canUndo());
    commandItem(state, "Redo", "redo", state.document.history.canRedo());
    ImGui::MenuItem("Undo History", shortcutLabel("history"), &state.view.showHistoryPanel);
    ImGui::Separator();
    if (ImGui::MenuItem("Select all", shortcutLabel("select_all"))) {
      state.input.selection.selectAll();
      ++state.document.poseGeneration;
    }
    if (ImGui::MenuItem("Select none", shortcutLabel("select_none"))) {
      state.input.selection.clear();
      ++state.document.poseGeneration;
    }
    commandItem(state, "Reset pose", "reset_pose");
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    commandItem(state, "Frame all", "frame");
    bool compare = state.view.compare;
    if (ImGui::MenuItem("Compare methods", nullptr, &compare)) setCompare(state, compare);
    ImGui::MenuItem("Show cage", nullptr, &state.view.showCage);
    ImGui::MenuItem("Show mesh", nullptr, &state.view.showMesh);
    ImGui::MenuItem("Show tetrahedra", nullptr, &state.view.showTets);
    tooltip("Draw the tetrahedral mesh of each Phong view as a wireframe, posed (its Steiner vertices follow the\n"
            "cage as the frame moves them).");
    ImGui::MenuItem("Timeline and pose library", nullptr, &state.animation.showPanels);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    ImGui::MenuItem("Shortcuts", shortcutLabel("shortcuts"), &state.view.showShortcuts);
    ImGui::MenuItem("Frame timings", nullptr, &state.view.showFrameTimings);
    tooltip("Where each frame's time goes: deformation, normals, uploads, each pane's draw, the UI\n"
            "(the latest frame and the mean of the last 60). --log-frames prints it per frame.");
    ImGui::Separator();
    ImGui::TextUnformatted(
        "Camera: middle drag or Alt+left drag orbits, Shift+middle (Alt+Shift+left) pans, wheel zooms, F frames.\n"
        "Select: click a handle, Shift+click toggles, drag on the background for a box (Shift adds).\n"
        "Drop files on the window: a mesh and its cage (2 .obj; names with \"cage\" are cages, \"pose\",\n"
        "\"posed\" or \"deformed\" posed cages, else the order), + a posed cage (3 .obj), one posed cage for\n"
        "the current cage (1 .obj), or a session .json. File > Open lists the recent files.");
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

namespace {

// The single view's tetrahedra for a volume method (Phong): the default (the cage's star when it is star-shaped,
// else level 1) or a level (docs/engine.md, "Phong deformation"). Sessions keep it ("methodOptions").
void drawTetrahedraChoice(AppState& state) {
  const auto level = state.view.methodOptions.find("tet-level");
  const std::string current = level == state.view.methodOptions.end() ? "default" : "level " + level->second;
  if (ImGui::BeginCombo("tetrahedra", current.c_str())) {
    if (ImGui::Selectable("default", level == state.view.methodOptions.end())) {
      MethodOptions options = state.view.methodOptions;
      options.erase("tet-level");
      setMethodOptions(state, options);
    }
    for (int l = 0; l < kTetLevels; ++l) {
      const std::string name = "level " + std::to_string(l);
      if (ImGui::Selectable(name.c_str(), name == current)) {
        MethodOptions options = state.view.methodOptions;
        options["tet-level"] = std::to_string(l);
        setMethodOptions(state, options);
      }
    }
    ImGui::EndCombo();
  }
  tooltip(
      "The tetrahedra Phong interpolates over. default: the cage's star when it is star-shaped from its\n"
      "centroid, else level 1. Level 0: the constrained tetrahedralization (about the cage's vertices);\n"
      "1 to 4: CGAL's, finer with each level. Esc stops a long tetrahedralization.");
}

// A job's stage, its progress bar and Cancel (with `cancelTip`); true when Cancel was clicked.
bool jobProgress(const std::string& stage, double progress, const char* cancelTip) {
  ImGui::TextUnformatted(stage.empty() ? "starting..." : stage.c_str());
  ImGui::ProgressBar(static_cast<float>(progress), ImVec2(-1.0f, 0.0f));
  const bool cancel = ImGui::Button("Cancel");
  tooltip(cancelTip);
  return cancel;
}

}  // namespace

void drawControlPanel(AppState& state) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float top = static_cast<float>(menuBarHeight());
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x, vp->Pos.y + top));
  ImGui::SetNextWindowSize(
      ImVec2(static_cast<float>(panelWidth(vp->Size.x)), vp->Size.y - top - static_cast<float>(statusBarHeight())));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar;
  ImGui::Begin("Controls", nullptr, flags);

  ImGui::TextUnformatted(state.model.scene ? state.model.scene->name.c_str() : "(no scene)");
  if (ImGui::Button("3D demo")) openDemo(state, 3);
  tooltip("Open the built-in 3D demo: a bar in a box cage (Ctrl+N). Asks first when there are unsaved changes.");
  ImGui::SameLine();
  if (ImGui::Button("2D demo")) openDemo(state, 2);
  tooltip("Open the built-in 2D demo: a polygon in a polygon cage.");
  ImGui::SameLine();
  if (ImGui::Button("Open...")) openFileDialog(state, FileDialogPurpose::OpenScene);
  tooltip("Open a mesh and its cage (.obj), with an optional posed cage (Ctrl+O)");

  sectionHeader("Method");
  const std::vector<Method>& all = allMethods();
  if (ImGui::BeginCombo("method", state.document.method->displayName)) {
    for (Method m : all) {
      if (ImGui::Selectable(m->displayName, m == state.document.method)) {
        setMethod(state, m);
        commitEdit(state, "Method");
      }
    }
    ImGui::EndCombo();
  }
  tooltip(
      "The cage coordinates that deform the mesh. Somigliana: x~ = T(x)^-1 [sum R_i T_i R_i^T v~_i +\n"
      "sum s_j R_j K_j n_j] (Eq. 11); Green: Lipman et al. 2008; MVC: mean value coordinates;\n"
      "BEM: the linear-elastic solution of the pose (boundary elements, the same nu), a reference.");
  if (state.document.method->needsVolumeMesh && !state.view.compare) drawTetrahedraChoice(state);
  bool compare = state.view.compare;
  if (ImGui::Checkbox("compare side by side", &compare)) setCompare(state, compare);
  tooltip(
      "Show two or three views side by side with the same pose (View > Compare methods): each a method, with\n"
      "its own nu or the panel's. A view setting: not an edit, not undone.");
  if (state.view.compare) drawCompareViews(state);

  sectionHeader("Parameters");
  // One widget per row of the parameter table (parameter_panel.h); a row no shown view reads is greyed out.
  bool parametersUsed = false;
  for (const DeformerKey& key : state.deformerKeys()) parametersUsed |= key.method->parameters != 0;
  drawParameterWidgets(state);
  if (!parametersUsed) ImGui::TextDisabled("(%s ignores these)", state.document.method->displayName);
  drawNuPlot(state);

  sectionHeader("Pose");
  if (ImGui::Button("Reset pose")) resetPose(state);
  tooltip("Every handle back to its rest position (Alt+Shift+R). One undo step.");
  ImGui::SameLine();
  if (!state.document.history.canUndo()) ImGui::BeginDisabled();
  if (ImGui::Button("Undo")) undo(state);
  if (!state.document.history.canUndo()) ImGui::EndDisabled();
  tooltip("Undo the last change (Ctrl+Z). Edit > Undo History lists every step.");
  ImGui::SameLine();
  if (!state.document.history.canRedo()) ImGui::BeginDisabled();
  if (ImGui::Button("Redo")) redo(state);
  if (!state.document.history.canRedo()) ImGui::EndDisabled();
  tooltip("Redo (Ctrl+Shift+Z or Ctrl+Y)");
  ImGui::SameLine();
  if (ImGui::Button("Frame (F)")) frameAll(state);
  tooltip("Frame the mesh and the posed cage in the views (F)");
  ImGui::Text("%d of %d cage vertices selected", state.input.selection.count(), state.input.selection.size());
  int pickMode = static_cast<int>(state.input.elementMode);
  const char* pickNames[] = {"vertex", "edge", "face"};
  const char* pickTips[] = {"A click selects one cage vertex (1)", "A click selects an edge: its two vertices (2)",
                            "A click selects a face: its vertices (3)"};
  for (int m = 0; m < 3; ++m) {
    if (m > 0) ImGui::SameLine();
    if (ImGui::RadioButton(pickNames[m], pickMode == m)) state.input.elementMode = static_cast<ElementMode>(m);
    tooltip(pickTips[m]);
  }
  ImGui::Checkbox("show cage", &state.view.showCage);
  tooltip("Draw the cage and its handles");
  ImGui::SameLine();
  ImGui::Checkbox("show mesh", &state.view.showMesh);
  tooltip("Draw the deformed mesh");
  ImGui::SameLine();
  bool wire = state.view.wireframe < 0 ? state.dim() == 2 : state.view.wireframe > 0;
  if (ImGui::Checkbox("wireframe", &wire)) state.view.wireframe = wire ? 1 : 0;
  tooltip("Draw the mesh's edges");
  ImGui::Checkbox("flat shading", &state.view.flatShading);
  tooltip("Faceted shading (one normal per triangle) instead of smooth");
  drawShowChoice(state);
  tooltip("Colour the meshes by a quantity of the pose (measured when the pose settles; one range for all views)");

  sectionHeader("Deformation device");
  {
    const DeviceState& devices = state.model.devices;
    const std::string active = devices.active();
    for (std::size_t i = 0; i < devices.offered.size(); ++i) {
      const std::string& name = devices.offered[i].name;
      if (i > 0) ImGui::SameLine();
      ImGui::BeginDisabled(!devices.usable(name));
      if (ImGui::RadioButton(name.c_str(), name == active)) setDevice(state, name);
      ImGui::EndDisabled();
      tooltip(
          "Where every frame is deformed (--device): cpu = OpenMP, opengl = a compute shader writing the vertex "
          "buffers, cuda = an NVIDIA GPU");
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    for (const auto& [name, why] : devices.unavailable) ImGui::TextWrapped("%s: %s", name.c_str(), why.c_str());
    if (!devices.note.empty()) ImGui::TextWrapped("%s", devices.note.c_str());
    ImGui::PopStyleColor();
  }

  sectionHeader("Precompute");
  if (state.jobs.session.busy()) {  // a session being read (session_read.h); its scene loads next
    if (jobProgress(state.jobs.session.stage(), state.jobs.session.progress(),
                    "Stop opening the session; the open document stays (Esc)"))
      state.jobs.session.cancel();
  } else if (state.jobs.precompute.busy()) {
    if (jobProgress(state.jobs.precompute.stage(), state.jobs.precompute.progress(),
                    "Stop the precomputation; the previous scene stays (Esc)"))
      state.jobs.precompute.cancel();
  } else {
    ImGui::Text("ready (%.2f s)", state.status.stats.precomputeSeconds);
  }

  sectionHeader("Help");
  ImGui::TextWrapped(
      "Middle drag / Alt+drag: orbit. Shift+middle: pan. Wheel: zoom. F: frame.\n"
      "Click / Shift+click / box-drag: select handles. A / Alt+A: all / none.\n"
      "Drag a handle or the gizmo, or G R S (+ X Y Z, a typed value), Enter confirms, Esc cancels.\n"
      "F1: every shortcut.");
  ImGui::End();
}

std::string statusBarText(const AppState& state) {
  if (!state.model.scene) return "loading...   " + state.status.message;
  char fps[32] = "- FPS";
  if (state.status.stats.fps > 0) std::snprintf(fps, sizeof fps, "%.0f FPS", state.status.stats.fps);
  char device[96];
  const std::string active = state.model.devices.active();
  if (state.model.devices.inPlace()) {
    std::snprintf(device, sizeof device, "%s (compute shader, %.2f ms on the CPU)", active.c_str(),
                  state.status.stats.lastDeformCpuMs);
  } else if (active == kCpuDevice) {
    // The UI's share of the cores at its last deformation (thread_budget.h): "1 of 2 threads" while a job holds one.
    const int threads = state.status.stats.deformThreads, cores = ThreadBudget::machine().cores();
    if (threads < cores) {
      std::snprintf(device, sizeof device, "%s (OpenMP, %d of %d threads)", active.c_str(), threads, cores);
    } else {
      std::snprintf(device, sizeof device, "%s (OpenMP, %d thread%s)", active.c_str(), threads,
                    threads == 1 ? "" : "s");
    }
  } else {
    std::snprintf(device, sizeof device, "%s", active.c_str());
  }
  char deform[32] = "deform - ms";  // GPU: until the first timer query has finished
  if (std::isfinite(state.status.stats.lastDeformMs))
    std::snprintf(deform, sizeof deform, "deform %.2f ms", state.status.stats.lastDeformMs);
  char stats[320];
  std::snprintf(
      stats, sizeof stats, "%s   mesh %lld V / %lld F   cage %d V / %d F   precompute %.2f s   %s   %s   %s",
      hasUnsavedChanges(state) ? "  unsaved" : "", static_cast<long long>(state.model.scene->meshVertices.rows()),
      static_cast<long long>(state.model.scene->meshTriangles.rows()), state.model.scene->restCage.numVertices(),
      state.model.scene->restCage.numFaces(), state.status.stats.precomputeSeconds, deform, fps, device);
  // The last action first: in a narrow window the statistics are what gets cut off.
  return state.status.message + (state.status.message.empty() ? "" : "   |") + stats;
}

void drawStatusBar(AppState& state) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float h = static_cast<float>(statusBarHeight());
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x, vp->Pos.y + vp->Size.y - h));
  ImGui::SetNextWindowSize(ImVec2(vp->Size.x, h));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollWithMouse |
                                 ImGuiWindowFlags_NoBringToFrontOnFocus;
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8.0f, 3.0f));
  ImGui::Begin("##status", nullptr, flags);
  const std::string text = statusBarText(state);
  ImGui::TextUnformatted(text.c_str());
  // A long message (a notice naming both files) runs off the bar: the whole of it on hover, wrapped.
  if (!state.status.message.empty() && ImGui::IsWindowHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(std::min(vp->Size.x * 0.8f, 900.0f));
    ImGui::TextUnformatted(state.status.message.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

void drawViewLabels(const AppState& state, const std::vector<ViewRect>& views) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const std::size_t viewCount = state.views().size();
  for (std::size_t v = 0; v < views.size() && v < viewCount; ++v) {
    const std::string label = viewLabel(state, v);
    const ImVec2 pos(static_cast<float>(views[v].x + kLabelLeft), static_cast<float>(views[v].y + kLabelTop));
    const ImVec2 size = ImGui::CalcTextSize(label.c_str());
    // Clipped to the pane: a view with several own parameters in a narrow pane must not run into the next one.
    draw->PushClipRect(
        ImVec2(static_cast<float>(views[v].x), static_cast<float>(views[v].y)),
        ImVec2(static_cast<float>(views[v].x + views[v].width - 4), static_cast<float>(views[v].y + views[v].height)),
        true);
    draw->AddRectFilled(ImVec2(pos.x - 4, pos.y - 2), ImVec2(pos.x + size.x + 4, pos.y + size.y + 2),
                        IM_COL32(20, 20, 24, 170), 3.0f);
    draw->AddText(pos, IM_COL32(235, 235, 240, 255), label.c_str());
    draw->PopClipRect();
    if (v > 0) {
      draw->AddLine(ImVec2(static_cast<float>(views[v].x), static_cast<float>(views[v].y)),
                    ImVec2(static_cast<float>(views[v].x), static_cast<float>(views[v].y + views[v].height)),
                    IM_COL32(15, 15, 18, 255), 2.0f);
    }
  }
}

void drawHistoryPanel(AppState& state) {
  if (!state.view.showHistoryPanel) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x - 270.0f, vp->Pos.y + 40.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(250.0f, 300.0f), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("Undo History", &state.view.showHistoryPanel, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::End();
    return;
  }
  const History& h = state.document.history;
  std::size_t jump = h.cursor();
  for (std::size_t i = 0; i < h.size(); ++i) {
    ImGui::PushID(static_cast<int>(i));
    std::string label = h.step(i).name;
    if (i > h.cursor()) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    if (ImGui::Selectable(label.c_str(), i == h.cursor())) jump = i;
    if (i > h.cursor()) ImGui::PopStyleColor();
    if (i == h.cursor() && ImGui::IsWindowAppearing()) ImGui::SetScrollHereY();
    ImGui::PopID();
  }
  ImGui::End();
  if (jump != h.cursor()) jumpToStep(state, jump);
}

void drawUnsavedModal(AppState& state) {
  if (!state.document.unsaved.asking) return;
  const char* title = "Unsaved changes";
  if (!ImGui::IsPopupOpen(title)) {
    ImGui::OpenPopup(title);
    if (state.status.logActions) std::printf("dialog %s\n", title), std::fflush(stdout);
  }
  ImGui::SetNextWindowSize(ImVec2(440, 0), ImGuiCond_Appearing);
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoSavedSettings)) return;
  ImGui::TextWrapped("\"%s\" has unsaved changes. Save them before you %s?", documentName(state).c_str(),
                     state.document.unsaved.asking->what.c_str());
  // Keys as in most desktop dialogs: S or Enter saves, D does not, Esc cancels.
  std::optional<UnsavedChoice> choice;
  const bool enter = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false);
  if (ImGui::Button("Save (S)") || ImGui::IsKeyPressed(GLFW_KEY_S, false) || enter) choice = UnsavedChoice::Save;
  tooltip(state.document.path.empty() ? "Choose a session file, save, then go on (S or Enter)"
                                      : "Save the session, then go on (S or Enter)");
  ImGui::SameLine();
  if (ImGui::Button("Don't save (D)") || ImGui::IsKeyPressed(GLFW_KEY_D, false)) choice = UnsavedChoice::DontSave;
  tooltip("Go on and lose the changes (D)");
  ImGui::SameLine();
  if (ImGui::Button("Cancel (Esc)") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false))
    choice = UnsavedChoice::Cancel;
  tooltip("Keep working (Esc)");
  if (choice) {
    ImGui::CloseCurrentPopup();
    answerUnsaved(state, *choice);
  }
  ImGui::EndPopup();
}

void drawShortcutSheet(AppState& state) {
  if (!state.view.showShortcuts) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x * 0.5f, vp->Pos.y + vp->Size.y * 0.5f), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(200, 100), ImVec2(vp->Size.x - 20, vp->Size.y - 40));
  if (!ImGui::Begin("Shortcuts (F1)", &state.view.showShortcuts,
                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    return;
  }
  if (ImGui::BeginTable("##keys", 2, ImGuiTableFlags_RowBg)) {
    for (const Shortcut& s : shortcuts()) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(s.keys);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(s.what);
    }
    ImGui::EndTable();
  }
  ImGui::TextDisabled("While transforming: X / Y / Z axis, digits type a value, Shift fine, Ctrl snaps.");
  ImGui::End();
}

void drawRestoreModal(AppState& state) {
  if (!state.files.restoreOffer || !state.status.errors.empty()) return;  // one modal at a time: the errors first
  const char* title = "Restore session";
  if (!ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
  ImGui::SetNextWindowSize(ImVec2(480, 0), ImGuiCond_Appearing);
  if (ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::TextWrapped("SomiCage did not exit cleanly last time. Restore the session from %s?",
                       state.files.restoreOfferTime.c_str());
    if (ImGui::Button("Restore") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter))) {
      acceptRestoreOffer(state);
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
      discardRestoreOffer(state);
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
}

void drawErrorModal(AppState& state) {
  if (state.status.errors.empty()) return;
  if (!ImGui::IsPopupOpen("Error")) ImGui::OpenPopup("Error");
  ImGui::SetNextWindowSize(ImVec2(560, 0), ImGuiCond_Appearing);
  if (ImGui::BeginPopupModal("Error", nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::TextWrapped("%s", state.status.errors.front().c_str());
    if (state.status.errors.size() > 1)
      ImGui::TextDisabled("(%d more)", static_cast<int>(state.status.errors.size() - 1));
    if (ImGui::Button("OK") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter))) {
      state.status.errors.erase(state.status.errors.begin());
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (state.status.errors.size() > 1 && ImGui::Button("Dismiss all")) {
      state.status.errors.clear();
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
}

}  // namespace somicage::editor
