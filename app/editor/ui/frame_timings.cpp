#include "ui/frame_timings.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace somicage::editor {

std::string frameLogLine(const FrameTimings& t) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer,
                "frame %llu total_ms=%.2f deform_ms=%.2f deforms=%d upload_ms=%.2f uploads=%d normals_ms=%.2f "
                "measure_ms=%.2f ui_ms=%.2f draw_ms=",
                static_cast<unsigned long long>(t.frame), t.totalMs, t.deformMs, t.deforms, t.uploadMs, t.uploads,
                t.normalsMs, t.measureMs, t.uiMs);
  std::string line = buffer;
  for (std::size_t v = 0; v < t.drawMs.size(); ++v) {
    std::snprintf(buffer, sizeof buffer, "%s%.2f", v ? "," : "", t.drawMs[v]);
    line += buffer;
  }
  if (t.drawMs.empty()) line += "-";
  std::snprintf(buffer, sizeof buffer, " mesh_draws=%d swap_ms=%.2f", t.meshDraws, t.swapMs);
  return line + buffer;
}

void FrameTimingsHistory::add(const FrameTimings& t) {
  last_ = t;
  constexpr std::size_t kKept = 60;
  if (recent_.size() < kKept) {
    recent_.push_back(t);
  } else {
    recent_[next_] = t;
    next_ = (next_ + 1) % kKept;
  }
}

FrameTimings FrameTimingsHistory::mean() const {
  FrameTimings m;
  if (recent_.empty()) return m;
  for (const FrameTimings& t : recent_) {
    m.totalMs += t.totalMs;
    m.uiMs += t.uiMs;
    m.deformMs += t.deformMs;
    m.normalsMs += t.normalsMs;
    m.uploadMs += t.uploadMs;
    m.measureMs += t.measureMs;
    m.swapMs += t.swapMs;
    if (m.drawMs.size() < t.drawMs.size()) m.drawMs.resize(t.drawMs.size(), 0.0);
    for (std::size_t v = 0; v < t.drawMs.size(); ++v) m.drawMs[v] += t.drawMs[v];
  }
  const double n = static_cast<double>(recent_.size());
  for (double* x : {&m.totalMs, &m.uiMs, &m.deformMs, &m.normalsMs, &m.uploadMs, &m.measureMs, &m.swapMs}) *x /= n;
  for (double& d : m.drawMs) d /= n;
  return m;
}

void drawFrameTimingsWindow(const FrameTimingsHistory& history, bool* open) {
  if (!*open) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  // Mid-width, below the views' labels (the pose library is at the right, the legends at the bottom right).
  ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + 0.5f * vp->Size.x - 100, vp->Pos.y + 110), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.85f);
  if (ImGui::Begin("Frame timings", open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing)) {
    const FrameTimings& last = history.last();
    const FrameTimings mean = history.mean();
    ImGui::TextUnformatted("ms            last    mean");
    auto row = [](const char* name, double a, double b) { ImGui::Text("%-12s %7.2f %7.2f", name, a, b); };
    row("frame", last.totalMs, mean.totalMs);
    row("deform", last.deformMs, mean.deformMs);
    row("normals", last.normalsMs, mean.normalsMs);
    row("upload", last.uploadMs, mean.uploadMs);
    row("quantities", last.measureMs, mean.measureMs);
    for (std::size_t v = 0; v < std::max(last.drawMs.size(), mean.drawMs.size()); ++v) {
      char name[32];
      std::snprintf(name, sizeof name, "draw pane %zu", v + 1);
      row(name, v < last.drawMs.size() ? last.drawMs[v] : 0.0, v < mean.drawMs.size() ? mean.drawMs[v] : 0.0);
    }
    row("UI", last.uiMs, mean.uiMs);
    row("swap", last.swapMs, mean.swapMs);
    ImGui::Text("%.1f frames/s (mean); deformed %d, uploaded %d views", mean.totalMs > 0 ? 1000.0 / mean.totalMs : 0.0,
                last.deforms, last.uploads);
    ImGui::TextDisabled("Each pane's draw is finished before the next is timed.");
  }
  ImGui::End();
}

}  // namespace somicage::editor
