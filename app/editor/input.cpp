#include "input.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "screenshot.h"

namespace somicage::editor {

namespace {

constexpr double kPickRadius = 12.0;     // pixels
constexpr double kDragThreshold = 3.0;   // pixels before a press becomes a drag

Eigen::Vector2d mousePos() {
  const ImVec2 m = ImGui::GetIO().MousePos;
  return {m.x, m.y};
}

void selectionChanged(AppState& state) { ++state.poseGeneration; }

void startModal(AppState& state, TransformKind kind, const std::vector<ViewRect>& views, int view) {
  if (state.selection.empty() || views.empty()) return;
  const ViewRect& r = views[static_cast<std::size_t>(view < 0 ? 0 : view)];
  state.interaction.mode = Interaction::Mode::Modal;
  state.interaction.view = view < 0 ? 0 : view;
  state.interaction.transform =
      beginTransform(kind, state.selection.indices(), state.pose, mousePos() - r.origin(), r.size());
}

void confirmTransform(AppState& state) {
  if (state.interaction.transform) {
    const TransformSession& t = *state.interaction.transform;
    if (t.original != state.pose) {
      EditSnapshot before = snapshot(state, transformName(t.kind));
      before.pose = t.original;
      state.history.record(std::move(before));
    }
  }
  state.interaction.transform.reset();
  state.interaction.mode = Interaction::Mode::Idle;
}

void cancelTransform(AppState& state) {
  if (state.interaction.transform) setPose(state, state.interaction.transform->original);
  state.interaction.transform.reset();
  state.interaction.mode = Interaction::Mode::Idle;
}

void updateTransform(AppState& state, const std::vector<ViewRect>& views) {
  if (!state.interaction.transform) return;
  const ViewRect& r = views[static_cast<std::size_t>(std::min<int>(state.interaction.view, static_cast<int>(views.size()) - 1))];
  const Eigen::MatrixXd pose = applyTransform(*state.interaction.transform, state.camera, mousePos() - r.origin());
  if (pose != state.pose) setPose(state, pose);
}

void drawTransformHeader(const AppState& state, const std::vector<ViewRect>& views) {
  if (!state.interaction.transform || state.interaction.mode != Interaction::Mode::Modal) return;
  const ViewRect& r = views[static_cast<std::size_t>(std::min<int>(state.interaction.view, static_cast<int>(views.size()) - 1))];
  const std::string text = describeTransform(*state.interaction.transform, state.camera, mousePos() - r.origin());
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImVec2 size = ImGui::CalcTextSize(text.c_str());
  const ImVec2 pos(static_cast<float>(r.x + 0.5 * (r.width - size.x)), static_cast<float>(r.y + 34));
  draw->AddRectFilled(ImVec2(pos.x - 6, pos.y - 3), ImVec2(pos.x + size.x + 6, pos.y + size.y + 3),
                      IM_COL32(30, 30, 36, 220), 4.0f);
  draw->AddText(pos, IM_COL32(255, 200, 120, 255), text.c_str());
}

void handleKeys(AppState& state, const std::vector<ViewRect>& views, int hoveredView) {
  const ImGuiIO& io = ImGui::GetIO();
  const bool ctrl = io.KeyCtrl, shift = io.KeyShift, alt = io.KeyAlt;
  Interaction& it = state.interaction;

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

  if (ctrl && ImGui::IsKeyPressed(GLFW_KEY_Z)) {
    shift ? redo(state) : undo(state);
  } else if (ctrl && ImGui::IsKeyPressed(GLFW_KEY_Y)) {
    redo(state);
  } else if (ctrl && ImGui::IsKeyPressed(GLFW_KEY_Q, false)) {
    state.quitRequested = true;
  } else if (!ctrl && ImGui::IsKeyPressed(GLFW_KEY_A, false)) {
    alt ? state.selection.clear() : state.selection.selectAll();
    selectionChanged(state);
  } else if (!ctrl && !alt && ImGui::IsKeyPressed(GLFW_KEY_F, false)) {
    frameAll(state);
  } else if (!ctrl && !alt && ImGui::IsKeyPressed(GLFW_KEY_G, false)) {
    startModal(state, TransformKind::Grab, views, hoveredView);
  } else if (!ctrl && !alt && ImGui::IsKeyPressed(GLFW_KEY_R, false)) {
    startModal(state, TransformKind::Rotate, views, hoveredView);
  } else if (!ctrl && !alt && ImGui::IsKeyPressed(GLFW_KEY_S, false)) {
    startModal(state, TransformKind::Scale, views, hoveredView);
  }
}

}  // namespace

void handleInput(AppState& state, const std::vector<ViewRect>& views) {
  const ImGuiIO& io = ImGui::GetIO();
  if (!state.scene || views.empty()) return;
  if (ImGui::IsKeyPressed(GLFW_KEY_F12, false)) state.screenshotRequest = defaultScreenshotName();

  Interaction& it = state.interaction;
  const Eigen::Vector2d mouse = mousePos();
  const int hovered = viewAt(views, mouse);
  if (!io.WantCaptureKeyboard) handleKeys(state, views, hovered);

  // ---- modal transform: follows the mouse until confirmed or cancelled ----
  if (it.mode == Interaction::Mode::Modal) {
    updateTransform(state, views);
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) confirmTransform(state);
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) cancelTransform(state);
    drawTransformHeader(state, views);
    return;
  }

  const Eigen::Vector2d delta = mouse - it.lastMouse;
  it.lastMouse = mouse;

  // ---- drags in progress ----
  switch (it.mode) {
    case Interaction::Mode::Orbit:
      if (ImGui::IsMouseDown(ImGuiMouseButton_Middle) || ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        state.camera.orbit(delta.x(), delta.y());
      } else {
        it.mode = Interaction::Mode::Idle;
      }
      return;
    case Interaction::Mode::Pan:
      if (ImGui::IsMouseDown(ImGuiMouseButton_Middle) || ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        state.camera.pan(delta.x(), delta.y(), views[static_cast<std::size_t>(it.view)].height);
      } else {
        it.mode = Interaction::Mode::Idle;
      }
      return;
    case Interaction::Mode::HandleDrag: {
      if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) {
          cancelTransform(state);
        } else if (it.transform && (mouse - it.pressMouse).norm() >= kDragThreshold) {
          updateTransform(state, views);
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
        if (!it.boxAdditive) state.selection.clear();  // click on the background
      } else {
        const std::vector<ScreenPoint> pts = projectPoints(state.camera, state.pose, r.width, r.height);
        state.selection.apply(pointsInRect(pts, it.pressMouse - r.origin(), mouse - r.origin()),
                              it.boxAdditive ? Selection::Mode::Add : Selection::Mode::Replace);
      }
      selectionChanged(state);
      it.mode = Interaction::Mode::Idle;
      return;
    }
    default:
      break;
  }

  // ---- idle: new presses (only over a viewport ImGui does not claim) ----
  if (io.WantCaptureMouse || hovered < 0) return;
  const ViewRect& r = views[static_cast<std::size_t>(hovered)];
  if (io.MouseWheel != 0.0f) state.camera.zoom(io.MouseWheel);

  const bool middle = ImGui::IsMouseClicked(ImGuiMouseButton_Middle);
  const bool left = ImGui::IsMouseClicked(ImGuiMouseButton_Left);
  if (middle || (left && io.KeyAlt)) {
    it.view = hovered;
    it.pressMouse = mouse;
    const bool pan = io.KeyShift || state.camera.mode2D();
    it.mode = pan ? Interaction::Mode::Pan : Interaction::Mode::Orbit;
    return;
  }
  if (left) {
    it.view = hovered;
    it.pressMouse = mouse;
    const std::vector<ScreenPoint> pts = projectPoints(state.camera, state.pose, r.width, r.height);
    const int hit = pickPoint(pts, mouse - r.origin(), kPickRadius);
    if (hit >= 0) {
      if (io.KeyShift) {
        state.selection.click(hit, Selection::Mode::Toggle);
        selectionChanged(state);
        return;
      }
      if (!state.selection.isSelected(hit)) {
        state.selection.click(hit, Selection::Mode::Replace);
        selectionChanged(state);
      }
      it.mode = Interaction::Mode::HandleDrag;
      it.transform = beginTransform(TransformKind::Grab, state.selection.indices(), state.pose, mouse - r.origin(), r.size());
    } else {
      it.mode = Interaction::Mode::Box;
      it.boxAdditive = io.KeyShift;
    }
  }
}

}  // namespace somicage::editor
