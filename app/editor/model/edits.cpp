// Edits: the document's setters, its undo history and the commands that change the cage.
#include <cstdio>
#include <filesystem>
#include <utility>

#include "model/app_state.h"

namespace somicage::editor {

Document currentDocument(const AppState& state) {
  return {state.document.pose,
          state.document.method,
          state.document.params,
          state.animation.poses,
          state.animation.timeline,
          state.model.scene ? state.model.scene->restCage : Cage{},
          state.model.scene ? state.model.scene->cagePath : std::string()};
}

void replaceRestCage(AppState& state, const Cage& cage, const std::string& cagePath) {
  if (!state.model.scene) return;
  auto scene = std::make_shared<Scene>(*state.model.scene);
  scene->restCage = cage;
  scene->cagePath = cagePath;
  installScene(state, std::move(scene));
  setPose(state, cage.vertices);
  ensureDeformers(state);
}

void applyDocument(AppState& state, const Document& document) {
  if (state.model.scene && document.restCage.numVertices() > 0 &&
      (!sameCage(document.restCage, state.model.scene->restCage) || document.cagePath != state.model.scene->cagePath))
    replaceRestCage(state, document.restCage, document.cagePath);
  if (document.pose.rows() == state.document.pose.rows() && document.pose.cols() == state.document.pose.cols())
    setPose(state, document.pose);
  setParams(state, document.params);
  if (document.method != state.document.method) setMethod(state, document.method);
  state.animation.poses = document.poses;
  state.animation.timeline = document.timeline;
}

bool commitEdit(AppState& state, const std::string& name) {
  if (!state.model.scene) return false;
  const bool added = state.document.history.commit(name, currentDocument(state));
  if (added) logLine(state, "step " + name);
  return added;
}

void logLine(const AppState& state, const std::string& line) {
  if (!state.status.logActions) return;
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
}

void setPose(AppState& state, const Eigen::MatrixXd& pose) {
  state.document.pose = pose;
  ++state.document.poseGeneration;
  state.model.deformDirty = true;
  if (state.model.precomputeCancelled) ensureDeformers(state);  // the edit needs the deformers Esc stopped
}

void resetPose(AppState& state) {
  if (!state.model.scene) return;
  setPose(state, state.model.scene->restCage.vertices);
  state.status.message = commitEdit(state, "Reset pose") ? "reset the pose" : "the pose is at rest already";
}

void setParams(AppState& state, const DeformParams& params) {
  state.document.params = params;
  state.model.deformDirty = true;
  if (state.model.precomputeCancelled) ensureDeformers(state);
}

void undo(AppState& state) {
  if (!state.document.history.canUndo()) {
    state.status.message = "nothing to undo";
    return;
  }
  const std::string name = state.document.history.step(state.document.history.cursor()).name;
  applyDocument(state, state.document.history.undo());
  state.status.message = "undo " + name;
}

void redo(AppState& state) {
  if (!state.document.history.canRedo()) {
    state.status.message = "nothing to redo";
    return;
  }
  applyDocument(state, state.document.history.redo());
  state.status.message = "redo " + state.document.history.step(state.document.history.cursor()).name;
}

void jumpToStep(AppState& state, std::size_t step) {
  if (step >= state.document.history.size() || step == state.document.history.cursor()) return;
  applyDocument(state, state.document.history.jumpTo(step));
  state.status.message = "history: back at \"" + state.document.history.step(step).name + "\"";
}

bool hasUnsavedChanges(const AppState& state) { return state.document.history.unsaved(); }

std::string documentName(const AppState& state) {
  if (!state.document.path.empty()) return std::filesystem::path(state.document.path).stem().string();
  return state.model.scene ? state.model.scene->name : "";
}

std::string windowTitle(const AppState& state) {
  const std::string name = documentName(state);
  if (name.empty()) return "SomiCage";
  return name + (hasUnsavedChanges(state) ? "*" : "") + " - SomiCage";
}

void setMethod(AppState& state, Method method) {
  if (state.document.method == method) return;
  state.document.method = method;
  state.model.deformDirty = true;
  ensureDeformers(state);
}

}  // namespace somicage::editor
