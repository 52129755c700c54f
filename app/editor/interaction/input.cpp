#include "interaction/input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <Eigen/Core>
#include <algorithm>
#include <cstdio>
#include <optional>
#include <utility>

#include "interaction/element_pick.h"
#include "interaction/gizmo.h"
#include "interaction/shortcuts.h"
#include "interaction/transform.h"
#include "model/pose_clear.h"
#include "model/selection.h"

namespace somicage::editor {

namespace {

constexpr double kPickRadius = 12.0;    // pixels
constexpr double kDragThreshold = 3.0;  // pixels before a press becomes a drag

Eigen::Vector2d mousePos() {
  const ImVec2 m = ImGui::GetIO().MousePos;
  return {m.x, m.y};
}

void selectionChanged(AppState& state) { ++state.document.poseGeneration; }

// --log-actions: the keyboard commands, one line each, as they run (the GUI tests count them).
void logAction(const AppState& state, const char* id) {
  if (!state.status.logActions) return;
  std::printf("action %s\n", id);
  std::fflush(stdout);
}

double cageSize(const AppState& state) {
  const Eigen::MatrixXd& rest = state.model.scene->restCage.vertices;
  return rest.rows() > 0 ? (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm() : 1.0;
}

void startModal(AppState& state, TransformKind kind, const std::vector<ViewRect>& views, int view) {
  if (views.empty()) return;
  if (state.input.selection.empty()) {
    state.status.message = std::string(transformName(kind)) + ": nothing selected (click a handle, or A for all)";
    return;
  }
  const ViewRect& r = views[static_cast<std::size_t>(view < 0 ? 0 : view)];
  state.input.mouse.mode = Interaction::Mode::Modal;
  state.input.mouse.view = view < 0 ? 0 : view;
  state.input.mouse.transform =
      beginTransform(kind, state.input.selection.indices(), state.document.pose, mousePos() - r.origin(), r.size());
  state.input.mouse.transform->gridStep = gridStepFor(cageSize(state));
}

void clearSelected(AppState& state, ClearKind kind) {
  if (state.input.selection.empty()) {
    state.status.message = std::string(clearKindName(kind)) + ": nothing selected";
    return;
  }
  setPose(state, clearTransform(kind, state.model.scene->restCage.vertices, state.document.pose,
                                state.input.selection.indices()));
  state.status.message = commitEdit(state, clearKindName(kind))
                             ? clearKindName(kind)
                             : std::string(clearKindName(kind)) + ": already at rest";
}

void confirmTransform(AppState& state) {
  if (state.input.mouse.transform) commitEdit(state, transformName(state.input.mouse.transform->kind));
  state.input.mouse.transform.reset();
  state.input.mouse.mode = Interaction::Mode::Idle;
}

void cancelTransform(AppState& state) {
  if (state.input.mouse.transform) setPose(state, state.input.mouse.transform->original);
  state.input.mouse.transform.reset();
  state.input.mouse.mode = Interaction::Mode::Idle;
}

void updateTransform(AppState& state, const std::vector<ViewRect>& views) {
  if (!state.input.mouse.transform) return;
  state.input.mouse.transform->fine = ImGui::GetIO().KeyShift;
  state.input.mouse.transform->snap = ImGui::GetIO().KeyCtrl;
  const ViewRect& r =
      views[static_cast<std::size_t>(std::min<int>(state.input.mouse.view, static_cast<int>(views.size()) - 1))];
  const Eigen::MatrixXd pose = applyTransform(*state.input.mouse.transform, state.view.camera, mousePos() - r.origin());
  if (pose != state.document.pose) setPose(state, pose);
}

}  // namespace

std::string transformHeader(const AppState& state, const std::vector<ViewRect>& views) {
  const Interaction& it = state.input.mouse;
  const bool modal = it.mode == Interaction::Mode::Modal;
  if (!it.transform || views.empty() || (!modal && it.mode != Interaction::Mode::HandleDrag)) return "";
  const ViewRect& r = views[static_cast<std::size_t>(std::min<int>(it.view, static_cast<int>(views.size()) - 1))];
  if (!modal && (mousePos() - it.pressMouse).norm() < kDragThreshold) return "";  // a click, not a drag yet
  const std::string text = describeTransform(*it.transform, state.view.camera, mousePos() - r.origin());
  return modal ? text : text.substr(0, text.find("   ["));  // a drag: no keys to list, the release confirms
}

namespace {

void drawTransformHeader(const AppState& state, const std::vector<ViewRect>& views) {
  const std::string text = transformHeader(state, views);
  if (text.empty()) return;
  const ViewRect& r =
      views[static_cast<std::size_t>(std::min<int>(state.input.mouse.view, static_cast<int>(views.size()) - 1))];
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  const ImVec2 pos(static_cast<float>(r.x + 0.5 * (r.width - size.x)), static_cast<float>(r.y + 34));
  draw->AddRectFilled(ImVec2(pos.x - 6, pos.y - 3), ImVec2(pos.x + size.x + 6, pos.y + size.y + 3),
                      IM_COL32(30, 30, 36, 220), 4.0f);
  draw->AddText(pos, IM_COL32(255, 200, 120, 255), text.c_str());
}

// The active axis as a line through the pivot, in the axis colour (x red, y green, z blue), across the view.
void drawAxisLine(const AppState& state, const std::vector<ViewRect>& views) {
  const std::optional<TransformSession>& t = state.input.mouse.transform;
  if (!t || t->axis == Axis::None || (t->axis == Axis::Z && state.dim() == 2)) return;
  const ViewRect& r =
      views[static_cast<std::size_t>(std::min<int>(state.input.mouse.view, static_cast<int>(views.size()) - 1))];
  Eigen::Vector3d dir = Eigen::Vector3d::Zero();
  dir[static_cast<int>(t->axis) - 1] = 1.0;
  Eigen::Vector2d centre;
  const Eigen::Vector2d screenDir(dir.dot(state.view.camera.right()), -dir.dot(state.view.camera.up()));
  if (!state.view.camera.project(t->pivot, r.width, r.height, centre) || screenDir.norm() < 1e-3) return;
  const Eigen::Vector2d a = centre - 4000.0 * screenDir.normalized(), b = centre + 4000.0 * screenDir.normalized();
  const ImU32 colours[3] = {IM_COL32(235, 70, 70, 220), IM_COL32(90, 210, 90, 220), IM_COL32(80, 140, 255, 220)};
  // The background list: over the 3D picture, under the panels and dialogs.
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  draw->PushClipRect(ImVec2(static_cast<float>(r.x), static_cast<float>(r.y)),
                     ImVec2(static_cast<float>(r.x + r.width), static_cast<float>(r.y + r.height)));
  draw->AddLine(ImVec2(static_cast<float>(r.x + a.x()), static_cast<float>(r.y + a.y())),
                ImVec2(static_cast<float>(r.x + b.x()), static_cast<float>(r.y + b.y())),
                colours[static_cast<int>(t->axis) - 1], 2.0f);
  draw->PopClipRect();
}

// The selection's gizmo (gizmo.h) in view `r`; `hot` is the part under the mouse (drawn brighter).
bool selectionGizmo(const AppState& state, const ViewRect& r, GizmoLayout& g) {
  if (state.input.selection.empty()) return false;
  return layoutGizmo(state.view.camera, selectionPivot(state), state.dim(), r.width, r.height, g);
}

void drawGizmo(const AppState& state, const ViewRect& r, const GizmoPart& hot) {
  GizmoLayout g;
  if (!state.view.showCage || !selectionGizmo(state, r, g)) return;  // the handles' gizmo goes with the cage
  const auto at = [&](const Eigen::Vector2d& p) {
    return ImVec2(static_cast<float>(r.x + p.x()), static_cast<float>(r.y + p.y()));
  };
  const ImU32 colours[3] = {IM_COL32(235, 70, 70, 255), IM_COL32(90, 210, 90, 255), IM_COL32(80, 140, 255, 255)};
  const ImU32 hotColour = IM_COL32(255, 230, 120, 255);
  const Axis axes[3] = {Axis::X, Axis::Y, Axis::Z};
  ImDrawList* draw = ImGui::GetBackgroundDrawList();  // under the panels and dialogs
  draw->PushClipRect(at(Eigen::Vector2d::Zero()), at(r.size()));
  const GizmoPart ring{GizmoPart::Kind::Rotate, Axis::None}, centre{GizmoPart::Kind::Move, Axis::None};
  draw->AddCircle(at(g.centre), static_cast<float>(GizmoLayout::kRingPixels),
                  hot == ring ? hotColour : IM_COL32(230, 230, 235, 160), 64, hot == ring ? 3.0f : 1.5f);
  for (int a = 0; a < 3; ++a) {
    if (!g.shown[a]) continue;
    const bool moveHot = hot == GizmoPart{GizmoPart::Kind::Move, axes[a]};
    const bool scaleHot = hot == GizmoPart{GizmoPart::Kind::Scale, axes[a]};
    draw->AddLine(at(g.centre), at(g.tips[a]), moveHot ? hotColour : colours[a], moveHot ? 4.0f : 2.5f);
    const Eigen::Vector2d dir = (g.tips[a] - g.centre).normalized(), side(-dir.y(), dir.x());
    draw->AddTriangleFilled(at(g.tips[a] + 10.0 * dir), at(g.tips[a] + 5.0 * side), at(g.tips[a] - 5.0 * side),
                            moveHot ? hotColour : colours[a]);
    const float k = static_cast<float>(GizmoLayout::kGrabPixels) - 2.0f;
    const ImVec2 b = at(g.boxes[a]);
    draw->AddRectFilled(ImVec2(b.x - k, b.y - k), ImVec2(b.x + k, b.y + k), scaleHot ? hotColour : colours[a]);
  }
  draw->AddCircleFilled(at(g.centre), static_cast<float>(GizmoLayout::kCentrePixels),
                        hot == centre ? hotColour : IM_COL32(240, 240, 240, 200));
  draw->PopClipRect();
}

// What a click would pick (element_pick.h), outlined under the mouse.
void drawHover(const AppState& state, const ViewRect& r, const Eigen::Vector2d& mouse) {
  const std::vector<ScreenPoint> pts = projectPoints(state.view.camera, state.document.pose, r.width, r.height);
  const std::vector<int> hit =
      pickElement(state.input.elementMode, pts, state.model.scene->restCage.faces, mouse - r.origin(), kPickRadius);
  if (hit.empty()) return;
  const auto at = [&](int v) {
    const Eigen::Vector2d& p = pts[static_cast<std::size_t>(v)].position;
    return ImVec2(static_cast<float>(r.x + p.x()), static_cast<float>(r.y + p.y()));
  };
  const ImU32 colour = IM_COL32(255, 240, 150, 230);
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  if (hit.size() == 1) {
    draw->AddCircle(at(hit[0]), 9.0f, colour, 20, 2.5f);
  } else if (hit.size() == 2) {
    draw->AddLine(at(hit[0]), at(hit[1]), colour, 4.0f);
  } else {
    draw->AddTriangleFilled(at(hit[0]), at(hit[1]), at(hit[2]), IM_COL32(255, 240, 150, 70));
    draw->AddTriangle(at(hit[0]), at(hit[1]), at(hit[2]), colour, 2.5f);
  }
}

// The selected edges (both vertices selected) in the selection's colour, over the cage's own edges.
void drawSelectedEdges(const AppState& state, const ViewRect& r) {
  if (!state.view.showCage || state.input.selection.empty()) return;
  const std::vector<std::pair<int, int>> edges =
      selectedEdges(state.model.scene->restCage.faces, state.input.selection.flags());
  if (edges.empty()) return;
  const std::vector<ScreenPoint> pts = projectPoints(state.view.camera, state.document.pose, r.width, r.height);
  const auto at = [&](int v) {
    const Eigen::Vector2d& p = pts[static_cast<std::size_t>(v)].position;
    return ImVec2(static_cast<float>(r.x + p.x()), static_cast<float>(r.y + p.y()));
  };
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  for (const auto& [a, b] : edges) draw->AddLine(at(a), at(b), IM_COL32(255, 170, 60, 230), 2.5f);
}

void setElementMode(AppState& state, ElementMode mode) {
  state.input.elementMode = mode;
  state.status.message = std::string("a click selects ") + elementModeName(mode) +
                         (mode == ElementMode::Vertex ? "" : " (their vertices)");
}

// Digits, '.', '-' and Backspace during G / R / S (Blender's numeric input).
void typeNumbers(AppState& state, const std::vector<ViewRect>& views) {
  static const std::pair<int, char> kKeys[] = {
      {GLFW_KEY_0, '0'},         {GLFW_KEY_1, '1'},          {GLFW_KEY_2, '2'},     {GLFW_KEY_3, '3'},
      {GLFW_KEY_4, '4'},         {GLFW_KEY_5, '5'},          {GLFW_KEY_6, '6'},     {GLFW_KEY_7, '7'},
      {GLFW_KEY_8, '8'},         {GLFW_KEY_9, '9'},          {GLFW_KEY_KP_0, '0'},  {GLFW_KEY_KP_1, '1'},
      {GLFW_KEY_KP_2, '2'},      {GLFW_KEY_KP_3, '3'},       {GLFW_KEY_KP_4, '4'},  {GLFW_KEY_KP_5, '5'},
      {GLFW_KEY_KP_6, '6'},      {GLFW_KEY_KP_7, '7'},       {GLFW_KEY_KP_8, '8'},  {GLFW_KEY_KP_9, '9'},
      {GLFW_KEY_PERIOD, '.'},    {GLFW_KEY_KP_DECIMAL, '.'}, {GLFW_KEY_MINUS, '-'}, {GLFW_KEY_KP_SUBTRACT, '-'},
      {GLFW_KEY_BACKSPACE, '\b'}};
  for (const auto& [key, c] : kKeys) {
    if (ImGui::IsKeyPressed(key) && typeIntoTransform(*state.input.mouse.transform, c)) updateTransform(state, views);
  }
}

void handleKeys(AppState& state, const std::vector<ViewRect>& views, int hoveredView) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool ctrl = io.KeyCtrl, shift = io.KeyShift, alt = io.KeyAlt;
  Interaction& it = state.input.mouse;

  if (it.mode == Interaction::Mode::Modal) {
    if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) {
      cancelTransform(state);
      return;
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_ENTER, false) || ImGui::IsKeyPressed(GLFW_KEY_KP_ENTER, false)) {
      confirmTransform(state);
      return;
    }
    const int keys[3] = {GLFW_KEY_X, GLFW_KEY_Y, GLFW_KEY_Z};
    const Axis axes[3] = {Axis::X, Axis::Y, Axis::Z};
    for (int k = 0; k < 3; ++k) {
      if (ImGui::IsKeyPressed(keys[k], false)) {
        it.transform->axis = it.transform->axis == axes[k] ? Axis::None : axes[k];
        updateTransform(state, views);
      }
    }
    typeNumbers(state, views);
    const int kinds[3] = {GLFW_KEY_G, GLFW_KEY_R, GLFW_KEY_S};
    const TransformKind kindValues[3] = {TransformKind::Grab, TransformKind::Rotate, TransformKind::Scale};
    for (int k = 0; k < 3; ++k) {
      if (ImGui::IsKeyPressed(kinds[k], false) && it.transform->kind != kindValues[k]) {
        // Switch the kind, starting again from the original positions (as Blender does).
        it.transform->kind = kindValues[k];
        updateTransform(state, views);
      }
    }
    return;
  }
  if (it.mode != Interaction::Mode::Idle) return;

  const int mods = (shift ? kShift : 0) | (ctrl ? kCtrl : 0) | (alt ? kAlt : 0);
  for (const Shortcut& sc : shortcuts()) {
    const bool repeats = sc.run == undo || sc.run == redo;  // holding Ctrl+Z walks back
    if (sc.run && sc.mods == mods && ImGui::IsKeyPressed(sc.key, repeats)) {
      logAction(state, sc.id);
      sc.run(state);
      return;
    }
  }
  struct ViewKey {
    int key, mods;
    const char* id;
    void (*run)(AppState&, const std::vector<ViewRect>&, int);
  };
  static const ViewKey kViewKeys[] = {
      {GLFW_KEY_A, kNoMods, "select_all",
       [](AppState& s, const std::vector<ViewRect>&, int) {
         s.input.selection.selectAll();
         selectionChanged(s);
       }},
      {GLFW_KEY_A, kAlt, "select_none",
       [](AppState& s, const std::vector<ViewRect>&, int) {
         s.input.selection.clear();
         selectionChanged(s);
       }},
      {GLFW_KEY_G, kNoMods, "grab",
       [](AppState& s, const std::vector<ViewRect>& v, int h) { startModal(s, TransformKind::Grab, v, h); }},
      {GLFW_KEY_R, kNoMods, "rotate",
       [](AppState& s, const std::vector<ViewRect>& v, int h) { startModal(s, TransformKind::Rotate, v, h); }},
      {GLFW_KEY_S, kNoMods, "scale",
       [](AppState& s, const std::vector<ViewRect>& v, int h) { startModal(s, TransformKind::Scale, v, h); }},
      {GLFW_KEY_1, kNoMods, "pick_vertices",
       [](AppState& s, const std::vector<ViewRect>&, int) { setElementMode(s, ElementMode::Vertex); }},
      {GLFW_KEY_2, kNoMods, "pick_edges",
       [](AppState& s, const std::vector<ViewRect>&, int) { setElementMode(s, ElementMode::Edge); }},
      {GLFW_KEY_3, kNoMods, "pick_faces",
       [](AppState& s, const std::vector<ViewRect>&, int) { setElementMode(s, ElementMode::Face); }},
      {GLFW_KEY_G, kAlt, "clear_location",
       [](AppState& s, const std::vector<ViewRect>&, int) { clearSelected(s, ClearKind::Location); }},
      {GLFW_KEY_R, kAlt, "clear_rotation",
       [](AppState& s, const std::vector<ViewRect>&, int) { clearSelected(s, ClearKind::Rotation); }},
      {GLFW_KEY_S, kAlt, "clear_scale",
       [](AppState& s, const std::vector<ViewRect>&, int) { clearSelected(s, ClearKind::Scale); }},
  };
  for (const ViewKey& vk : kViewKeys) {
    if (vk.mods == mods && ImGui::IsKeyPressed(vk.key, false)) {
      logAction(state, vk.id);
      vk.run(state, views, hoveredView);
      return;
    }
  }
}

}  // namespace

void handleInput(AppState& state, const std::vector<ViewRect>& views) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!state.model.scene || views.empty()) return;

  Interaction& it = state.input.mouse;
  const Eigen::Vector2d mouse = mousePos();
  const int hovered = viewAt(views, mouse);
  if (!io.WantCaptureKeyboard) handleKeys(state, views, hovered);

  // ---- modal transform: follows the mouse until confirmed or cancelled ----
  if (it.mode == Interaction::Mode::Modal) {
    updateTransform(state, views);
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) confirmTransform(state);
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) cancelTransform(state);
    drawTransformHeader(state, views);
    drawAxisLine(state, views);
    return;
  }

  const Eigen::Vector2d delta = mouse - it.lastMouse;
  it.lastMouse = mouse;

  // ---- drags in progress ----
  switch (it.mode) {
    case Interaction::Mode::Orbit:
      if (ImGui::IsMouseDown(ImGuiMouseButton_Middle) || ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        state.view.camera.orbit(delta.x(), delta.y());
      } else {
        it.mode = Interaction::Mode::Idle;
      }
      return;
    case Interaction::Mode::Pan:
      if (ImGui::IsMouseDown(ImGuiMouseButton_Middle) || ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        state.view.camera.pan(delta.x(), delta.y(), views[static_cast<std::size_t>(it.view)].height);
      } else {
        it.mode = Interaction::Mode::Idle;
      }
      return;
    case Interaction::Mode::HandleDrag: {
      drawAxisLine(state, views);
      if (it.transform) {
        const GizmoPart dragged{it.transform->kind == TransformKind::Grab    ? GizmoPart::Kind::Move
                                : it.transform->kind == TransformKind::Scale ? GizmoPart::Kind::Scale
                                                                             : GizmoPart::Kind::Rotate,
                                it.transform->axis};
        drawGizmo(state, views[static_cast<std::size_t>(it.view)], dragged);
      }
      if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) {
          cancelTransform(state);
        } else if (it.transform && (mouse - it.pressMouse).norm() >= kDragThreshold) {
          updateTransform(state, views);
          drawTransformHeader(state, views);  // the numbers G / R / S show, for the gizmo and handle drags too
        }
      } else {
        confirmTransform(state);
      }
      return;
    }
    case Interaction::Mode::Box: {
      ImDrawList* draw = ImGui::GetForegroundDrawList();
      const ImVec2 a(static_cast<float>(it.pressMouse.x()), static_cast<float>(it.pressMouse.y()));
      const ImVec2 b(static_cast<float>(mouse.x()), static_cast<float>(mouse.y()));
      if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        if ((mouse - it.pressMouse).norm() >= kDragThreshold) {
          draw->AddRectFilled(a, b, IM_COL32(120, 170, 255, 40));
          draw->AddRect(a, b, IM_COL32(150, 190, 255, 220));
        }
        return;
      }
      const ViewRect& r = views[static_cast<std::size_t>(it.view)];
      if ((mouse - it.pressMouse).norm() < kDragThreshold) {
        if (!it.boxAdditive) state.input.selection.clear();  // click on the background
      } else {
        const std::vector<ScreenPoint> pts = projectPoints(state.view.camera, state.document.pose, r.width, r.height);
        state.input.selection.apply(pointsInRect(pts, it.pressMouse - r.origin(), mouse - r.origin()),
                                    it.boxAdditive ? Selection::Mode::Add : Selection::Mode::Replace);
      }
      selectionChanged(state);
      it.mode = Interaction::Mode::Idle;
      return;
    }
    default:
      break;
  }

  // ---- idle: the gizmo, and new presses (only over a viewport ImGui does not claim) ----
  GizmoPart hot;
  GizmoLayout gizmo;
  const bool overView = !io.WantCaptureMouse && hovered >= 0;
  if (overView && selectionGizmo(state, views[static_cast<std::size_t>(hovered)], gizmo))
    hot = pickGizmo(gizmo, mouse - views[static_cast<std::size_t>(hovered)].origin());
  for (std::size_t v = 0; v < views.size(); ++v) {
    drawSelectedEdges(state, views[v]);
    drawGizmo(state, views[v], static_cast<int>(v) == hovered ? hot : GizmoPart{});
  }
  if (!overView) return;
  const ViewRect& r = views[static_cast<std::size_t>(hovered)];
  if (hot.kind == GizmoPart::Kind::None) drawHover(state, r, mouse);
  if (io.MouseWheel != 0.0f) state.view.camera.zoom(io.MouseWheel);

  const bool middle = ImGui::IsMouseClicked(ImGuiMouseButton_Middle);
  const bool left = ImGui::IsMouseClicked(ImGuiMouseButton_Left);
  if (middle || (left && io.KeyAlt)) {
    it.view = hovered;
    it.pressMouse = mouse;
    const bool pan = io.KeyShift || state.view.camera.mode2D();
    it.mode = pan ? Interaction::Mode::Pan : Interaction::Mode::Orbit;
    return;
  }
  if (left && hot.kind != GizmoPart::Kind::None) {  // drag a gizmo part: G / R / S with its axis
    const TransformKind kinds[] = {TransformKind::Grab, TransformKind::Grab, TransformKind::Scale,
                                   TransformKind::Rotate};
    it.view = hovered;
    it.pressMouse = mouse;
    it.mode = Interaction::Mode::HandleDrag;
    it.transform = beginTransform(kinds[static_cast<int>(hot.kind)], state.input.selection.indices(),
                                  state.document.pose, mouse - r.origin(), r.size());
    it.transform->axis = hot.axis;
    it.transform->gridStep = gridStepFor(cageSize(state));
    if (hot.kind == GizmoPart::Kind::Scale) it.transform->scalePixels = GizmoLayout::kArrowPixels;
    return;
  }
  if (left) {
    it.view = hovered;
    it.pressMouse = mouse;
    const std::vector<ScreenPoint> pts = projectPoints(state.view.camera, state.document.pose, r.width, r.height);
    const std::vector<int> hit =
        pickElement(state.input.elementMode, pts, state.model.scene->restCage.faces, mouse - r.origin(), kPickRadius);
    if (!hit.empty()) {
      if (io.KeyShift) {
        state.input.selection.apply(hit, Selection::Mode::Toggle);
        selectionChanged(state);
        return;
      }
      if (!std::all_of(hit.begin(), hit.end(), [&](int v) { return state.input.selection.isSelected(v); })) {
        state.input.selection.apply(hit, Selection::Mode::Replace);
        selectionChanged(state);
      }
      it.mode = Interaction::Mode::HandleDrag;
      it.transform = beginTransform(TransformKind::Grab, state.input.selection.indices(), state.document.pose,
                                    mouse - r.origin(), r.size());
    } else {
      it.mode = Interaction::Mode::Box;
      it.boxAdditive = io.KeyShift;
    }
  }
}

}  // namespace somicage::editor
