#include "ui/cage_maker_panel.h"

#include <imgui.h>

#include <cmath>

#include "generation/cage_generation.h"
#include "jobs/cage_maker.h"
#include "ui/panels.h"

namespace somicage::editor {

namespace {

void drawNumbers(const CageCandidate& candidate) {
  const GeneratedCage& g = candidate.generated;
  ImGui::Text("%d faces (at most %d), %d vertices", g.cage.numFaces(), candidate.options.maxFaces,
              g.cage.numVertices());
  ImGui::Text("smallest angle %.1f deg", g.minAngleDegrees);
  if (std::isnan(g.tightness.volumeRatio)) {
    ImGui::TextUnformatted("volume cage / mesh: - (open mesh)");
  } else {
    ImGui::Text("volume cage / mesh %.2f", g.tightness.volumeRatio);
  }
  ImGui::Text("Hausdorff cage -> mesh %.3f diagonals", g.tightness.hausdorff);
  ImGui::Text("margin %.3f diagonals, %.1f s", g.margin, candidate.seconds);
}

}  // namespace

void drawCageMakerDialog(AppState& state) {
  CageMaker& maker = state.jobs.cageMaker;
  if (!maker.isOpen()) return;
  ImGui::SetNextWindowSize(ImVec2(330, 0), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x - 350, 40), ImGuiCond_FirstUseEver);
  bool open = true;
  if (!ImGui::Begin("Make cage", &open, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::End();
    if (!open) maker.close();
    return;
  }
  CageGenerationOptions options = maker.options();
  bool changed = ImGui::SliderInt("faces", &options.maxFaces, CageGenerationOptions::kMinFaces, 2000, "%d",
                                  ImGuiSliderFlags_Logarithmic);
  tooltip("The cage gets at most this many triangles; fewer are coarser and looser.");
  float margin = static_cast<float>(options.margin);
  if (ImGui::SliderFloat("margin", &margin, 0.0f, 0.1f, margin > 0 ? "%.3f diag." : "automatic")) {
    options.margin = margin;
    changed = true;
  }
  tooltip("Distance from the mesh in bounding-box diagonals; 0: automatic (about two voxels).");
  if (changed) maker.request(options);

  ImGui::Separator();
  switch (maker.status()) {
    case CageMaker::Status::Generating:
      ImGui::ProgressBar(static_cast<float>(maker.progress()), ImVec2(-70.0f, 0.0f), "generating...");
      ImGui::SameLine();
      if (ImGui::Button("Stop")) maker.cancel();
      break;
    case CageMaker::Status::Failed:
      ImGui::PushTextWrapPos(320);
      ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", maker.error().c_str());
      ImGui::PopTextWrapPos();
      break;
    case CageMaker::Status::Cancelled:
      ImGui::TextUnformatted("stopped; move a slider to generate again");
      break;
    default:
      break;
  }
  if (maker.candidate()) {
    if (maker.status() != CageMaker::Status::Ready) ImGui::TextDisabled("shown: the previous candidate");
    drawNumbers(*maker.candidate());
  }
  ImGui::Separator();
  const bool ready = maker.status() == CageMaker::Status::Ready;
  if (!ready) ImGui::BeginDisabled();
  if (ImGui::Button("Accept")) acceptGeneratedCage(state);
  if (!ready) ImGui::EndDisabled();
  tooltip("Make it the scene's cage, at rest (one undo step; the pose library and keys are cleared).");
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) maker.close();
  ImGui::End();
  if (!open) maker.close();
}

}  // namespace somicage::editor
