#include "panels.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <system_error>

#include "screenshot.h"

namespace somicage::editor {

namespace {

// std::string-backed text field (ImGui 1.86 has no std::string overload without imgui_stdlib).
bool inputText(const char* label, std::string& text) {
  char buf[1024];
  std::snprintf(buf, sizeof buf, "%s", text.c_str());
  const bool changed = ImGui::InputText(label, buf, sizeof buf);
  if (changed) text = buf;
  return changed;
}

void openDialog(AppState& state, PathDialog::Kind kind, const std::string& suggestion) {
  state.dialog.kind = kind;
  state.dialog.justOpened = true;
  if (state.dialog.path.empty() || kind == PathDialog::Kind::Screenshot) state.dialog.path = suggestion;
  if (kind == PathDialog::Kind::OpenFiles && state.scene && !state.scene->isDemo()) {
    state.dialog.mesh = state.scene->meshPath;
    state.dialog.cage = state.scene->cagePath;
  }
}

// A titled separator (ImGui 1.86 has no SeparatorText).
void sectionHeader(const char* title) {
  ImGui::Spacing();
  ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "%s", title);
  ImGui::Separator();
}

// Records an undo snapshot when a widget starts being edited, so a whole slider drag is one undo step.
void undoOnActivate(AppState& state, const char* label) {
  if (ImGui::IsItemActivated()) recordEdit(state, label);
}

// The recent files of the Open panel, most recent first; entries with a missing file are greyed out (the tooltip
// names it). Returns true when an entry was opened.
bool drawRecentFiles(AppState& state) {
  const std::vector<RecentEntry> entries = state.recent.entries();  // a copy: opening one reorders the list
  if (entries.empty()) return false;
  sectionHeader("Recent");
  bool opened = false;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const RecentEntry& e = entries[i];
    std::string missing;
    for (const std::string& path : e.paths()) {
      std::error_code ec;
      if (!std::filesystem::exists(path, ec)) {
        missing = path;
        break;
      }
    }
    ImGui::PushID(static_cast<int>(i));
    if (!missing.empty()) ImGui::BeginDisabled();
    const bool clicked = ImGui::Selectable(e.label().c_str(), false, ImGuiSelectableFlags_DontClosePopups);
    if (!missing.empty()) ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
      std::string tip;
      for (const std::string& path : e.paths()) tip += path + "\n";
      if (!missing.empty()) tip += "missing: " + missing;
      ImGui::SetTooltip("%s", tip.c_str());
    }
    ImGui::PopID();
    if (clicked && !opened) {
      openRecent(state, e);
      opened = true;
    }
  }
  return opened;
}

}  // namespace

double menuBarHeight() { return ImGui::GetFrameHeight(); }
double statusBarHeight() { return ImGui::GetFrameHeight() + 6.0; }

void drawMainMenu(AppState& state) {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("Open mesh + cage...")) openDialog(state, PathDialog::Kind::OpenFiles, "");
    if (ImGui::MenuItem("3D demo")) requestDemo(state, 3);
    if (ImGui::MenuItem("2D demo")) requestDemo(state, 2);
    ImGui::Separator();
    if (ImGui::MenuItem("Load posed cage...")) openDialog(state, PathDialog::Kind::LoadPose, "posed_cage.obj");
    if (ImGui::MenuItem("Save posed cage...")) openDialog(state, PathDialog::Kind::SavePose, "posed_cage.obj");
    if (ImGui::MenuItem("Export deformed mesh...")) openDialog(state, PathDialog::Kind::ExportMesh, "deformed.obj");
    ImGui::Separator();
    if (ImGui::MenuItem("Open session...")) openDialog(state, PathDialog::Kind::LoadSession, "session.json");
    if (ImGui::MenuItem("Save session...")) openDialog(state, PathDialog::Kind::SaveSession, "session.json");
    ImGui::Separator();
    if (ImGui::MenuItem("Screenshot...", "F12"))
      openDialog(state, PathDialog::Kind::Screenshot, defaultScreenshotName());
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) state.quitRequested = true;
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    if (ImGui::MenuItem("Undo", "Ctrl+Z", false, state.history.canUndo())) undo(state);
    if (ImGui::MenuItem("Redo", "Ctrl+Shift+Z", false, state.history.canRedo())) redo(state);
    ImGui::Separator();
    if (ImGui::MenuItem("Select all", "A")) {
      state.selection.selectAll();
      ++state.poseGeneration;
    }
    if (ImGui::MenuItem("Select none", "Alt+A")) {
      state.selection.clear();
      ++state.poseGeneration;
    }
    if (ImGui::MenuItem("Reset pose")) resetPose(state);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    if (ImGui::MenuItem("Frame all", "F")) frameAll(state);
    bool compare = state.compare;
    if (ImGui::MenuItem("Compare methods", nullptr, &compare)) setCompare(state, compare);
    ImGui::MenuItem("Show cage", nullptr, &state.showCage);
    ImGui::MenuItem("Show mesh", nullptr, &state.showMesh);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    ImGui::TextUnformatted(
        "Camera: middle drag or Alt+left drag orbits, Shift+middle (Alt+Shift+left) pans, wheel zooms, F frames.\n"
        "Select: click a handle, Shift+click toggles, drag on the background for a box (Shift adds).\n"
        "A selects all, Alt+A none. Drag a selected handle to move the selection in the view plane.\n"
        "G / R / S grab, rotate, scale; then X / Y / Z constrain; Enter or left click confirms, Esc or\n"
        "right click cancels. Ctrl+Z undo, Ctrl+Shift+Z redo. F12 screenshot.\n"
        "Drop files on the window: a mesh and its cage (2 .obj; names with \"cage\" are cages, \"pose\",\n"
        "\"posed\" or \"deformed\" posed cages, else the order), + a posed cage (3 .obj), one posed cage for\n"
        "the current cage (1 .obj), or a session .json. File > Open lists the recent files.");
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

void drawControlPanel(AppState& state) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float top = static_cast<float>(menuBarHeight());
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x, vp->Pos.y + top));
  ImGui::SetNextWindowSize(
      ImVec2(static_cast<float>(kPanelWidth), vp->Size.y - top - static_cast<float>(statusBarHeight())));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar;
  ImGui::Begin("Controls", nullptr, flags);

  ImGui::TextUnformatted(state.scene ? state.scene->name.c_str() : "(no scene)");
  if (ImGui::Button("3D demo")) requestDemo(state, 3);
  ImGui::SameLine();
  if (ImGui::Button("2D demo")) requestDemo(state, 2);
  ImGui::SameLine();
  if (ImGui::Button("Open...")) openDialog(state, PathDialog::Kind::OpenFiles, "");

  sectionHeader("Method");
  const std::vector<Method>& all = allMethods();
  if (ImGui::BeginCombo("method", state.method->displayName)) {
    for (Method m : all)
      if (ImGui::Selectable(m->displayName, m == state.method)) setMethod(state, m);
    ImGui::EndCombo();
  }
  bool compare = state.compare;
  if (ImGui::Checkbox("compare side by side", &compare)) setCompare(state, compare);
  if (state.compare) {
    std::vector<bool> use(all.size(), false);
    for (std::size_t i = 0; i < all.size(); ++i)
      use[i] =
          std::find(state.compareMethods.begin(), state.compareMethods.end(), all[i]) != state.compareMethods.end();
    bool changed = false;
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (i > 0) ImGui::SameLine();
      bool on = use[i];
      changed |= ImGui::Checkbox((std::string(all[i]->displayName) + "##c").c_str(), &on);
      use[i] = on;
    }
    if (changed) {
      std::vector<Method> list;
      for (std::size_t i = 0; i < all.size(); ++i) {
        if (use[i]) list.push_back(all[i]);
      }
      if (list.size() >= 2 && list.size() <= kMaxCompareViews) {
        state.compareMethods = list;
        setCompare(state, true);
      }
    }
  }

  sectionHeader("Somigliana parameters");
  DeformParams p = state.params;
  int variant = p.blend <= 0.0 ? 0 : (p.blend >= 1.0 ? 1 : 2);
  if (ImGui::RadioButton("global", variant == 0)) {
    recordEdit(state, "variant");
    p.blend = 0.0;
  }
  ImGui::SameLine();
  if (ImGui::RadioButton("local", variant == 1)) {
    recordEdit(state, "variant");
    p.blend = 1.0;
  }
  float blend = static_cast<float>(p.blend);
  if (ImGui::SliderFloat("blend", &blend, 0.0f, 1.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp)) p.blend = blend;
  undoOnActivate(state, "blend");

  bool infinite = std::isinf(p.nu);
  if (ImGui::Checkbox("nu = infinity", &infinite)) {
    recordEdit(state, "nu");
    p.nu = infinite ? std::numeric_limits<double>::infinity() : 0.0;
  }
  if (!infinite) {
    float nu = static_cast<float>(p.nu);
    // Typed values (Ctrl+click) are clamped too: nu in (-1, 0.5); +-infinity only through the checkbox.
    if (ImGui::SliderFloat("nu", &nu, -0.99f, 0.49f, "%.3f", ImGuiSliderFlags_AlwaysClamp)) p.nu = nu;
    undoOnActivate(state, "nu");
  } else {
    ImGui::TextDisabled("nu = inf (Green-like limit)");
  }
  float gamma = static_cast<float>(p.gamma);
  if (ImGui::SliderFloat("gamma", &gamma, 0.0f, 5.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp)) p.gamma = gamma;
  undoOnActivate(state, "gamma");
  if (ImGui::Checkbox("traction fix (Eq. 15)", &p.tractionCorrection)) {
    DeformParams before = state.params;
    state.params = p;
    state.params.tractionCorrection = !p.tractionCorrection;
    recordEdit(state, "traction fix");
    state.params = before;
  }
  if (p.blend != state.params.blend || p.nu != state.params.nu || p.gamma != state.params.gamma ||
      p.tractionCorrection != state.params.tractionCorrection) {
    setParams(state, p);
  }
  if (!state.method->takesDeformParams && !state.compare) {
    ImGui::TextDisabled("(%s ignores these)", state.method->displayName);
  }

  sectionHeader("Pose");
  if (ImGui::Button("Reset pose")) resetPose(state);
  ImGui::SameLine();
  if (ImGui::Button("Undo")) undo(state);
  ImGui::SameLine();
  if (ImGui::Button("Redo")) redo(state);
  ImGui::SameLine();
  if (ImGui::Button("Frame (F)")) frameAll(state);
  ImGui::Text("%d of %d cage vertices selected", state.selection.count(), state.selection.size());
  ImGui::Checkbox("show cage", &state.showCage);
  ImGui::SameLine();
  ImGui::Checkbox("show mesh", &state.showMesh);
  ImGui::SameLine();
  bool wire = state.wireframe < 0 ? state.dim() == 2 : state.wireframe > 0;
  if (ImGui::Checkbox("wireframe", &wire)) state.wireframe = wire ? 1 : 0;
  ImGui::Checkbox("flat shading", &state.flatShading);

  sectionHeader("Deformation backend");
  {
    int backend = static_cast<int>(state.backend.requested);
    if (ImGui::RadioButton("CPU", backend == static_cast<int>(DeformBackend::Cpu)))
      setBackend(state, DeformBackend::Cpu);
    ImGui::SameLine();
    if (!state.backend.gpuAvailable) ImGui::BeginDisabled();
    if (ImGui::RadioButton("GPU (compute shader)", backend == static_cast<int>(DeformBackend::Gpu)))
      setBackend(state, DeformBackend::Gpu);
    if (!state.backend.gpuAvailable) ImGui::EndDisabled();
    if (!state.backend.gpuNote.empty()) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
      ImGui::TextWrapped("%s%s", state.backend.gpuAvailable ? "" : "GPU unavailable: ", state.backend.gpuNote.c_str());
      ImGui::PopStyleColor();
    }
  }

  sectionHeader("Precompute");
  if (state.worker.busy()) {
    const std::string stage = state.worker.stage();
    ImGui::TextUnformatted(stage.empty() ? "starting..." : stage.c_str());
    ImGui::ProgressBar(static_cast<float>(state.worker.progress()), ImVec2(-1.0f, 0.0f));
    if (ImGui::Button("Cancel")) state.worker.cancel();
  } else {
    ImGui::Text("ready (%.2f s)", state.stats.precomputeSeconds);
  }

  sectionHeader("Help");
  ImGui::TextWrapped(
      "Middle drag / Alt+drag: orbit. Shift+middle: pan. Wheel: zoom. F: frame.\n"
      "Click / Shift+click / box-drag: select handles. A / Alt+A: all / none.\n"
      "Drag a handle, or G R S (+ X Y Z), Enter confirms, Esc cancels.\n"
      "Ctrl+Z / Ctrl+Shift+Z: undo / redo. F12: screenshot.\n"
      "Drop on the window: mesh + cage .obj (+ posed cage), one posed cage, or a session .json. "
      "Open... lists the recent files.");
  ImGui::End();
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
  if (state.scene) {
    char fps[32] = "- FPS";
    if (state.stats.fps > 0) std::snprintf(fps, sizeof fps, "%.0f FPS", state.stats.fps);
    char backend[96];
    if (state.activeBackend() == DeformBackend::Gpu) {
      std::snprintf(backend, sizeof backend, "GPU (compute shader, %.2f ms on the CPU)", state.stats.lastDeformCpuMs);
    } else {
      std::snprintf(backend, sizeof backend, "CPU (OpenMP, %d threads)", state.stats.deformThreads);
    }
    char deform[32] = "deform - ms";  // GPU: until the first timer query has finished
    if (std::isfinite(state.stats.lastDeformMs))
      std::snprintf(deform, sizeof deform, "deform %.2f ms", state.stats.lastDeformMs);
    ImGui::Text("mesh %lld V / %lld F   cage %d V / %d F   precompute %.2f s   %s   %s   %s   %s",
                static_cast<long long>(state.scene->meshVertices.rows()),
                static_cast<long long>(state.scene->meshTriangles.rows()), state.scene->restCage.numVertices(),
                state.scene->restCage.numFaces(), state.stats.precomputeSeconds, deform, fps, backend,
                state.statusMessage.c_str());
  } else {
    ImGui::Text("loading...   %s", state.statusMessage.c_str());
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

void drawViewLabels(const AppState& state, const std::vector<ViewRect>& views) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const std::vector<Method> methods = state.viewMethods();
  for (std::size_t v = 0; v < views.size() && v < methods.size(); ++v) {
    const std::string label = viewLabel(state, methods[v]);
    const ImVec2 pos(static_cast<float>(views[v].x + 10), static_cast<float>(views[v].y + 8));
    const ImVec2 size = ImGui::CalcTextSize(label.c_str());
    draw->AddRectFilled(ImVec2(pos.x - 4, pos.y - 2), ImVec2(pos.x + size.x + 4, pos.y + size.y + 2),
                        IM_COL32(20, 20, 24, 170), 3.0f);
    draw->AddText(pos, IM_COL32(235, 235, 240, 255), label.c_str());
    if (v > 0) {
      draw->AddLine(ImVec2(static_cast<float>(views[v].x), static_cast<float>(views[v].y)),
                    ImVec2(static_cast<float>(views[v].x), static_cast<float>(views[v].y + views[v].height)),
                    IM_COL32(15, 15, 18, 255), 2.0f);
    }
  }
}

void drawPathDialog(AppState& state) {
  PathDialog& d = state.dialog;
  if (d.kind == PathDialog::Kind::None) return;
  const char* title = "File";
  switch (d.kind) {
    case PathDialog::Kind::OpenFiles:
      title = "Open mesh + cage";
      break;
    case PathDialog::Kind::LoadPose:
      title = "Load posed cage";
      break;
    case PathDialog::Kind::SavePose:
      title = "Save posed cage";
      break;
    case PathDialog::Kind::ExportMesh:
      title = "Export deformed mesh";
      break;
    case PathDialog::Kind::SaveSession:
      title = "Save session";
      break;
    case PathDialog::Kind::LoadSession:
      title = "Open session";
      break;
    case PathDialog::Kind::Screenshot:
      title = "Save screenshot";
      break;
    case PathDialog::Kind::None:
      break;
  }
  if (d.justOpened) {
    ImGui::OpenPopup(title);
    d.justOpened = false;
  }
  ImGui::SetNextWindowSize(ImVec2(560, 0), ImGuiCond_Appearing);
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    d.kind = PathDialog::Kind::None;
    return;
  }
  if (d.kind == PathDialog::Kind::OpenFiles) {
    inputText("mesh (.obj)", d.mesh);
    inputText("cage (.obj)", d.cage);
    inputText("posed cage (optional)", d.posed);
    ImGui::TextDisabled("or drop the files on the window");
  } else {
    inputText("path", d.path);
  }
  const bool ok = ImGui::Button("OK") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter));
  ImGui::SameLine();
  bool cancel = ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
  if (!ok && d.kind == PathDialog::Kind::OpenFiles && drawRecentFiles(state)) cancel = true;  // opened: just close
  if (ok) {
    switch (d.kind) {
      case PathDialog::Kind::OpenFiles:
        requestSceneFiles(state, d.mesh, d.cage, d.posed);
        break;
      case PathDialog::Kind::LoadPose:
        loadPosedCage(state, d.path);
        break;
      case PathDialog::Kind::SavePose:
        savePosedCage(state, d.path);
        break;
      case PathDialog::Kind::ExportMesh:
        exportDeformedMesh(state, d.path);
        break;
      case PathDialog::Kind::SaveSession:
        saveSessionFile(state, d.path);
        break;
      case PathDialog::Kind::LoadSession:
        loadSessionFile(state, d.path);
        break;
      case PathDialog::Kind::Screenshot:
        state.screenshotRequest = d.path;
        break;
      case PathDialog::Kind::None:
        break;
    }
  }
  if (ok || cancel) {
    d.kind = PathDialog::Kind::None;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void drawRestoreModal(AppState& state) {
  if (!state.restoreOffer || !state.errors.empty()) return;  // one modal at a time: the errors first
  const char* title = "Restore session";
  if (!ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
  ImGui::SetNextWindowSize(ImVec2(480, 0), ImGuiCond_Appearing);
  if (ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::TextWrapped("SomiCage did not exit cleanly last time. Restore the session from %s?",
                       state.restoreOfferTime.c_str());
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
  if (state.errors.empty()) return;
  if (!ImGui::IsPopupOpen("Error")) ImGui::OpenPopup("Error");
  ImGui::SetNextWindowSize(ImVec2(560, 0), ImGuiCond_Appearing);
  if (ImGui::BeginPopupModal("Error", nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::TextWrapped("%s", state.errors.front().c_str());
    if (state.errors.size() > 1) ImGui::TextDisabled("(%d more)", static_cast<int>(state.errors.size() - 1));
    if (ImGui::Button("OK") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter))) {
      state.errors.erase(state.errors.begin());
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (state.errors.size() > 1 && ImGui::Button("Dismiss all")) {
      state.errors.clear();
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
}

}  // namespace somicage::editor
