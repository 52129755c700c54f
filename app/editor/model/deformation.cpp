// The deformation of every frame: the views' points on the active device.
#include <algorithm>
#include <chrono>
#include <exception>

#include "model/app_state.h"

namespace somicage::editor {

bool updateDeformation(AppState& state) {
  if (!state.model.deformDirty || !state.model.scene) return false;
  state.model.deformDirty = false;
  const std::vector<ViewSpec> views = state.views();
  state.model.deformed.resize(views.size());
  if (state.model.devices.inPlace()) {
    state.model.cpuStale.clear();
    for (std::size_t v = 0; v < views.size(); ++v) state.model.cpuStale.push_back(v);
    ++state.model.deformGeneration;  // the Renderer deforms on the GPU and reports the timing (Renderer::sync)
    return true;
  }
  state.model.cpuStale.clear();
  state.status.stats.deformThreads = ThreadBudget::machine().uiThreads();  // the cores no job holds
  useThreads(state.status.stats.deformThreads);
  bool changed = false;
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t v = 0; v < views.size(); ++v) {
    auto it = state.model.deformers.find(deformerKey(views[v]));
    if (it == state.model.deformers.end()) continue;
    try {
      deformOnDevice(state, it->second, views[v].params(state.document.params), state.model.deformed[v]);
      changed = true;
      ++state.status.stats.frame.deforms;
    } catch (const std::exception& e) {
      state.status.errors.push_back(std::string("deformation failed: ") + e.what());
    }
  }
  if (changed) {
    state.status.stats.lastDeformMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    state.status.stats.frame.deformMs += state.status.stats.lastDeformMs;
    ++state.model.deformGeneration;
  }
  return changed;
}

void ensureCpuPoints(AppState& state, std::size_t view) {
  auto stale = std::find(state.model.cpuStale.begin(), state.model.cpuStale.end(), view);
  if (stale == state.model.cpuStale.end()) return;
  state.model.cpuStale.erase(stale);
  const std::vector<ViewSpec> views = state.views();
  if (view >= views.size()) return;
  auto it = state.model.deformers.find(deformerKey(views[view]));
  if (it == state.model.deformers.end()) return;
  state.model.deformed.resize(views.size());
  useThreads(ThreadBudget::machine().uiThreads());
  const auto t0 = std::chrono::steady_clock::now();
  try {
    deformOnDevice(state, it->second, views[view].params(state.document.params), state.model.deformed[view]);
    ++state.status.stats.frame.deforms;
    state.status.stats.frame.deformMs +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  } catch (const std::exception& e) {
    state.status.errors.push_back(std::string("deformation failed: ") + e.what());
  }
}

void setDevice(AppState& state, const std::string& device) {
  if (state.model.devices.requested == device) return;
  state.model.devices.requested = device;
  state.model.devices.evaluators.clear();  // the old device's copies of C go
  state.model.deformDirty = true;
}

const Eigen::MatrixXd& displayedPoints(const AppState& state, std::size_t view) {
  const std::vector<ViewSpec> views = state.views();
  if (view < views.size() && view < state.model.deformed.size() && state.model.scene &&
      state.model.deformed[view].rows() == state.model.scene->meshVertices.rows() &&
      hasDeformer(state, deformerKey(views[view]))) {
    return state.model.deformed[view];
  }
  return state.model.scene->meshVertices;
}

}  // namespace somicage::editor
