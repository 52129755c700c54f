#include "editor_renderer.h"

#include <cmath>

#include "gl_context.h"

namespace somicage::editor {

namespace {
const Eigen::Vector3f kBackground(0.20f, 0.21f, 0.24f);
const Eigen::Vector3f kViewBackground(0.27f, 0.28f, 0.32f);
}  // namespace

Renderer::Renderer() = default;

void Renderer::sync(const AppState& state) {
  if (!state.scene) return;
  const std::vector<Method> methods = state.viewMethods();
  if (meshes_.size() < methods.size()) meshes_.resize(methods.size());
  for (std::size_t v = 0; v < methods.size(); ++v) {
    MeshSlot& slot = meshes_[v];
    if (!slot.mesh) slot.mesh = std::make_unique<render::MeshRenderer>();
    const bool deformed = hasDeformer(state, methods[v]) && state.deformed.count(methods[v]) > 0;
    const bool newScene = slot.sceneGeneration != state.sceneGeneration;
    if (newScene) slot.mesh->setTopology(state.scene->meshTriangles);
    if (newScene || slot.method != methods[v] || slot.deformGeneration != state.deformGeneration ||
        slot.showedDeformed != deformed) {
      slot.mesh->setPositions(displayedPoints(state, methods[v]));
      slot.sceneGeneration = state.sceneGeneration;
      slot.deformGeneration = state.deformGeneration;
      slot.method = methods[v];
      slot.showedDeformed = deformed;
    }
  }
  if (cageScene_ != state.sceneGeneration) {
    cage_.setTopology(state.scene->restCage.faces);
    cageScene_ = state.sceneGeneration;
    cagePose_ = ~0ull;
  }
  if (cagePose_ != state.poseGeneration) {
    cage_.setPositions(state.pose);
    cage_.setSelection(state.selection.flags());
    cagePose_ = state.poseGeneration;
  }
}

void Renderer::draw(const AppState& state, const std::vector<ViewRect>& views, int framebufferWidth,
                    int framebufferHeight, double framebufferScale) {
  render::clearFramebuffer(framebufferWidth, framebufferHeight, kBackground);
  if (!state.scene) return;
  render::ViewMatrices matrices;
  matrices.view = state.camera.viewMatrix().cast<float>();
  matrices.orthographic = state.camera.mode2D();
  render::MeshStyle meshStyle;
  meshStyle.wireframe = state.wireframe < 0 ? state.dim() == 2 : state.wireframe > 0;
  render::CageStyle cageStyle;
  if (state.dim() == 2) cageStyle.edgeColor = Eigen::Vector4f(0.25f, 0.45f, 0.95f, 1.0f);
  for (std::size_t v = 0; v < views.size() && v < meshes_.size(); ++v) {
    const ViewRect& r = views[v];
    render::ViewportRect rect;
    rect.x = static_cast<int>(std::lround(r.x * framebufferScale));
    rect.width = std::max(1, static_cast<int>(std::lround(r.width * framebufferScale)));
    rect.height = std::max(1, static_cast<int>(std::lround(r.height * framebufferScale)));
    rect.y = framebufferHeight - static_cast<int>(std::lround(r.y * framebufferScale)) - rect.height;  // GL: bottom-left
    render::beginViewport(rect, &kViewBackground);
    matrices.projection = state.camera.projectionMatrix(r.width / r.height).cast<float>();
    if (state.showMesh && meshes_[v].mesh) meshes_[v].mesh->draw(matrices, meshStyle);
    if (state.showCage) cage_.draw(matrices, cageStyle);
  }
  render::endViewports(framebufferWidth, framebufferHeight);
}

}  // namespace somicage::editor
