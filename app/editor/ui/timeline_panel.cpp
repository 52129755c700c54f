#include "ui/timeline_panel.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "animation/pose_timeline.h"
#include "jobs/animation_export_job.h"
#include "model/pose_keys.h"
#include "ui/file_dialog.h"  // writePath
#include "ui/panels.h"       // tooltip

namespace somicage::editor {

namespace {

// The frame slider with a tick under each key (gold) and the cursor's frame.
void drawFrameSlider(AppState& state) {
  AnimationState& a = state.animation;
  Timeline& timeline = a.timeline;
  ImGui::SetNextItemWidth(-1);
  int frame = static_cast<int>(std::lround(a.frame));
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  if (ImGui::SliderInt("##frame", &frame, timeline.firstFrame, std::max(timeline.lastFrame, timeline.firstFrame + 1),
                       "frame %d")) {
    stopPlayback(state);
    scrubTo(state, frame);
  }
  const ImVec2 size = ImGui::GetItemRectSize();
  const float grab = ImGui::GetStyle().GrabMinSize;
  const double span = std::max(1, timeline.lastFrame - timeline.firstFrame);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (const Keyframe& key : timeline.keys) {
    if (key.frame < timeline.firstFrame || key.frame > timeline.lastFrame) continue;
    const float x =
        origin.x + grab * 0.5f + static_cast<float>((key.frame - timeline.firstFrame) / span) * (size.x - grab);
    draw->AddTriangleFilled(ImVec2(x - 5, origin.y + size.y + 7), ImVec2(x + 5, origin.y + size.y + 7),
                            ImVec2(x, origin.y + size.y), IM_COL32(240, 190, 60, 255));
  }
  ImGui::Dummy(ImVec2(0, 8));
}

}  // namespace

double timelinePanelHeight() { return 4 * ImGui::GetFrameHeightWithSpacing() + 14.0; }

void drawTimelinePanel(AppState& state, double left, double bottom) {
  AnimationState& a = state.animation;
  Timeline& timeline = a.timeline;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float height = static_cast<float>(timelinePanelHeight());
  ImGui::SetNextWindowPos(
      ImVec2(vp->Pos.x + static_cast<float>(left), vp->Pos.y + vp->Size.y - static_cast<float>(bottom) - height));
  ImGui::SetNextWindowSize(ImVec2(vp->Size.x - static_cast<float>(left), height));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollbar;
  ImGui::Begin("Timeline", nullptr, flags);
  const bool hasKeys = !timeline.keys.empty();
  if (!hasKeys) ImGui::BeginDisabled();
  if (ImGui::Button(a.playing ? "Stop" : "Play", ImVec2(60, 0))) togglePlayback(state);
  if (!hasKeys) ImGui::EndDisabled();
  tooltip(hasKeys ? "Play from the cursor, or stop (Space)" : "Key a pose first (Key pose), then play (Space)");
  ImGui::SameLine();
  if (ImGui::Checkbox("Loop", &timeline.loop)) commitEdit(state, "Loop");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90);
  float fps = static_cast<float>(timeline.fps);
  if (ImGui::DragFloat("fps", &fps, 0.25f, 1.0f, 240.0f, "%.1f")) timeline.fps = std::clamp<double>(fps, 1.0, 240.0);
  if (ImGui::IsItemDeactivatedAfterEdit()) commitEdit(state, "fps");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(150);
  int range[2] = {timeline.firstFrame, timeline.lastFrame};
  if (ImGui::DragInt2("range", range, 0.25f, 0, 100000)) {
    timeline.firstFrame = std::max(0, range[0]);
    timeline.lastFrame = std::max(timeline.firstFrame, range[1]);
  }
  if (ImGui::IsItemDeactivatedAfterEdit()) commitEdit(state, "Frame range");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(130);
  int interpolation = timeline.interpolation == Interpolation::Linear ? 0 : 1;
  if (ImGui::Combo("##interpolation", &interpolation, "linear\0Catmull-Rom\0")) {
    setInterpolation(state, interpolation == 0 ? Interpolation::Linear : Interpolation::CatmullRom);
  }
  ImGui::SameLine();
  if (ImGui::Button("Key pose")) keyCurrentPose(state);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("store the cage as a new pose and key it at this frame");
  ImGui::SameLine();
  const double here = std::round(a.frame);
  const bool onKey =
      std::any_of(timeline.keys.begin(), timeline.keys.end(), [&](const Keyframe& k) { return k.frame == here; });
  if (!onKey) ImGui::BeginDisabled();
  if (ImGui::Button("Delete key")) deleteKeyAtFrame(state);
  if (!onKey) ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::Checkbox("key nu, gamma", &a.keyParams);
  drawFrameSlider(state);
  std::string keys = std::to_string(timeline.keys.size()) + (timeline.keys.size() == 1 ? " key" : " keys");
  for (const Keyframe& key : timeline.keys) {
    if (key.frame == here) keys += "  |  frame " + std::to_string(static_cast<int>(here)) + ": " + key.pose;
  }
  ImGui::TextDisabled("%s", keys.c_str());
  ImGui::End();
}

void drawPoseLibraryPanel(AppState& state, double top) {
  AnimationState& a = state.animation;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float width = 300;
  // At the right, below the last view's label and the numbers under it, which it would cover at the top.
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x - width - 8, vp->Pos.y + static_cast<float>(top) + 96),
                          ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(width, 260), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.85f);
  if (!ImGui::Begin("Pose library", nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::End();
    return;
  }
  if (a.newPoseName.empty()) a.newPoseName = a.poses.freshName();
  ImGui::SetNextItemWidth(130);
  ImGui::InputText("##name", &a.newPoseName);
  ImGui::SameLine();
  if (ImGui::Button("Store current")) {
    storeCurrentPose(state, a.newPoseName);
    a.newPoseName.clear();
  }
  ImGui::Separator();
  const std::vector<NamedPose> poses = a.poses.poses();  // a copy: the buttons edit the library
  for (const NamedPose& pose : poses) {
    ImGui::PushID(pose.name.c_str());
    if (a.renaming == pose.name) {
      ImGui::SetNextItemWidth(120);
      const bool done =
          ImGui::InputText("##rename", &a.renameTo) && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter));
      ImGui::SameLine();
      if (done || ImGui::Button("OK")) {
        renameNamedPose(state, pose.name, a.renameTo);
        a.renaming.clear();
      }
    } else {
      ImGui::TextUnformatted(pose.name.c_str());
      ImGui::SameLine(120);
      if (ImGui::SmallButton("Apply")) applyNamedPose(state, pose.name);
      ImGui::SameLine();
      if (ImGui::SmallButton("Rename")) a.renaming = a.renameTo = pose.name;
      ImGui::SameLine();
      if (ImGui::SmallButton("Delete")) deleteNamedPose(state, pose.name);
    }
    ImGui::PopID();
  }
  if (poses.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("no poses yet: pose the cage, then Store current (or Key pose on the timeline)");
    ImGui::PopStyleColor();
  }
  ImGui::End();
}

void drawAnimationExportDialogs(AppState& state) {
  AnimationState& a = state.animation;
  int& kind = a.exportKind;
  std::string& path = a.exportPath;
  if (a.exportDialogRequested) {
    ImGui::OpenPopup("Export animation");
    a.exportDialogRequested = false;
    path = writePath(state, path);  // a full path in a writable folder, not a bare name
  }
  ImGui::SetNextWindowSize(ImVec2(560, 0), ImGuiCond_Appearing);
  if (ImGui::BeginPopupModal("Export animation", nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::RadioButton("GLB (morph targets)", &kind, 0);
    ImGui::SameLine();
    ImGui::RadioButton("OBJ sequence", &kind, 1);
    ImGui::SameLine();
    ImGui::RadioButton("PNG images of the views", &kind, 2);
    ImGui::InputText(kind == 0 ? "file (.glb)" : "new folder", &path);
    std::error_code ec;  // where a bare name goes: the editor's working folder
    const std::filesystem::path where = std::filesystem::absolute(path, ec);
    ImGui::TextDisabled("writes %s", ec ? path.c_str() : where.lexically_normal().c_str());
    ImGui::TextDisabled("frames %d..%d at %.1f fps (Timeline panel)", a.timeline.firstFrame, a.timeline.lastFrame,
                        a.timeline.fps);
    if (ImGui::Button("Export")) {
      startAnimationExport(state, static_cast<AnimationExportJob::Kind>(kind), path);
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  if (!a.exportJob) return;
  ImGui::OpenPopup("Exporting animation");
  if (ImGui::BeginPopupModal("Exporting animation", nullptr,
                             ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
    const AnimationExportJob& job = *a.exportJob;
    const float done = static_cast<float>(job.next - job.first) / static_cast<float>(job.last - job.first + 1);
    ImGui::Text("%s: frame %d of %d..%d", job.out.c_str(), job.next, job.first, job.last);
    ImGui::ProgressBar(done, ImVec2(400, 0));
    if (ImGui::Button("Cancel")) a.exportJob->cancelRequested = true;
    ImGui::EndPopup();
  }
}

}  // namespace somicage::editor
