#include "editor_renderer.h"

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <string>

#include "base/errors.h"
#include "engine/view_spec.h"
#include "geometry/volume_mesh.h"
#include "gl_context.h"
#include "jobs/cage_maker.h"
#include "mesh_normals.h"
#include "model/frame_device_evaluators.h"
#include "model/view_quantity.h"
#include "ui/frame_timings.h"
#include "ui/quantity_overlay.h"
#include "view_matrices.h"

namespace somicage::editor {

namespace {
const Eigen::Vector3f kBackground(0.20f, 0.21f, 0.24f);
const Eigen::Vector3f kViewBackground(0.27f, 0.28f, 0.32f);

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// Normals and the upload, each timed into the frame's breakdown.
void uploadPositions(render::MeshRenderer& mesh, const Eigen::MatrixXd& points, const Eigen::MatrixXi& triangles,
                     FrameTimings& timings) {
  auto t0 = Clock::now();
  const render::RowMatrixX3f normals = render::vertexNormals(points, triangles);
  timings.normalsMs += msSince(t0);
  t0 = Clock::now();
  mesh.setPositions(render::toFloat3(points), normals);
  timings.uploadMs += msSince(t0);
  ++timings.uploads;
}
}  // namespace

Renderer::Renderer() = default;

bool Renderer::syncGpu(MeshSlot& slot, const AppState& state, std::size_t v, bool newScene) {
  const ViewSpec view = state.views()[v];
  const std::shared_ptr<const CageDeformer>& deformer = state.model.deformers.at(deformerKey(view));
  if (!slot.gpu) slot.gpu = std::make_unique<render::GpuDeformer>();
  const bool newDeformer = slot.uploaded != deformer;
  if (newDeformer) {
    slot.uploaded.reset();
    slot.gpu->upload(*deformer);
    slot.uploaded = deformer;
  }
  const bool current = slot.onGpu && slot.view == view && slot.deformGeneration == state.model.deformGeneration;
  if (!newScene && !newDeformer && current) return false;
  slot.gpu->deform(state.document.pose, view.params(state.document.params), *slot.mesh);
  slot.onGpu = true;
  return true;
}

void Renderer::sync(AppState& state) {
  if (!state.model.scene) return;
  const std::vector<ViewSpec> views = state.views();
  if (meshes_.size() < views.size()) meshes_.resize(views.size());
  for (std::size_t v = views.size(); v < meshes_.size(); ++v) {  // hidden views give their GPU memory back
    meshes_[v].gpu.reset();
    meshes_[v].uploaded.reset();
    meshes_[v].onGpu = false;
  }
  const bool inPlace = state.model.devices.inPlace();
  double gpuMs = 0.0, cpuMs = 0.0;
  bool ranOnGpu = false, timed = false;
  for (std::size_t v = 0; v < views.size(); ++v) {
    MeshSlot& slot = meshes_[v];
    if (!slot.mesh) slot.mesh = std::make_unique<render::MeshRenderer>();
    const bool newScene = slot.sceneGeneration != state.model.sceneGeneration;
    if (newScene) slot.mesh->setTopology(state.model.scene->meshTriangles);
    if (state.model.devices.inPlace() && hasDeformer(state, deformerKey(views[v]))) {  // (a failure turns it off)
      try {
        if (syncGpu(slot, state, v, newScene)) {
          ranOnGpu = true;
          cpuMs += slot.gpu->lastCpuMilliseconds();
          state.status.stats.frame.deformMs += slot.gpu->lastCpuMilliseconds();
          ++state.status.stats.frame.deforms;
        }
        const double ms = slot.gpu->lastGpuMilliseconds();
        if (std::isfinite(ms)) {
          gpuMs += ms;
          timed = true;
        }
      } catch (const InputError& e) {  // bad parameters: as on the CPU path
        state.status.errors.push_back(std::string("deformation failed: ") + e.what());
      } catch (const std::exception& e) {  // the GPU cannot do it (shader, memory): fall back to the CPU for good
        deviceFailed(state, kInPlaceDevice, e.what());
        state.model.deformDirty = true;
        slot.gpu.reset();
        slot.uploaded.reset();
        slot.onGpu = false;
      }
      slot.sceneGeneration = state.model.sceneGeneration;
      slot.deformGeneration = state.model.deformGeneration;
      slot.view = views[v];
      slot.showedDeformed = true;
      continue;
    }
    if (slot.gpu) {  // back on the CPU: free the GPU copy of C
      slot.gpu.reset();
      slot.uploaded.reset();
    }
    const bool deformed = hasDeformer(state, deformerKey(views[v])) && v < state.model.deformed.size() &&
                          state.model.deformed[v].rows() == state.model.scene->meshVertices.rows();
    if (newScene || slot.view != views[v] || slot.deformGeneration != state.model.deformGeneration ||
        slot.showedDeformed != deformed || slot.onGpu) {
      uploadPositions(*slot.mesh, displayedPoints(state, v), state.model.scene->meshTriangles,
                      state.status.stats.frame);
      slot.sceneGeneration = state.model.sceneGeneration;
      slot.deformGeneration = state.model.deformGeneration;
      slot.view = views[v];
      slot.showedDeformed = deformed;
      slot.onGpu = false;
    }
  }
  syncScalars(state, state.status.stats.frame);
  for (std::size_t v = 0; v < views.size(); ++v) syncTets(meshes_[v], state, v);
  if (ranOnGpu) state.status.stats.lastDeformCpuMs = cpuMs;
  if (inPlace && state.model.devices.inPlace())
    state.status.stats.lastDeformMs = timed ? gpuMs : std::numeric_limits<double>::quiet_NaN();
  if (cageScene_ != state.model.sceneGeneration) {
    cage_.setTopology(state.model.scene->restCage.faces);
    cageScene_ = state.model.sceneGeneration;
    cagePose_ = ~0ull;
  }
  if (cagePose_ != state.document.poseGeneration) {
    cage_.setPositions(state.document.pose);
    cage_.setSelection(state.input.selection.flags());
    cagePose_ = state.document.poseGeneration;
  }
  const CageMaker& maker = state.jobs.cageMaker;
  if (previewGeneration_ != maker.candidateGeneration()) {
    previewGeneration_ = maker.candidateGeneration();
    if (maker.candidate()) {
      preview_.setTopology(maker.candidate()->generated.cage.faces);
      preview_.setPositions(maker.candidate()->generated.cage.vertices);
    }
  }
}

void Renderer::syncTets(MeshSlot& slot, const AppState& state, std::size_t v) {
  const auto found = state.model.deformers.find(deformerKey(state.views()[v]));
  const std::shared_ptr<const CageDeformer> deformer = found == state.model.deformers.end() ? nullptr : found->second;
  slot.tetsShown = state.view.showTets && deformer && deformer->volumeMesh();
  if (!slot.tetsShown) return;
  if (!slot.tets) slot.tets = std::make_unique<render::CageRenderer>();
  if (slot.tetsDeformer != deformer) {
    slot.tets->setTopology(volumeMeshEdges(*deformer->volumeMesh()));
    slot.tetsDeformer = deformer;
    slot.tetsGeneration = ~0ull;
  }
  if (slot.tetsGeneration == state.model.deformGeneration) return;
  try {  // the Steiner vertices where this frame puts them (a solve as small as the mesh)
    slot.tets->setPositions(deformer->posedVolumeMesh(state.document.pose, state.viewParams(v)));
    slot.tetsGeneration = state.model.deformGeneration;
  } catch (const InputError&) {  // parameters the method refuses: the deformation reports them
    slot.tetsShown = false;
  }
}

void Renderer::syncScalars(const AppState& state, FrameTimings& timings) {
  const std::vector<ViewSpec> views = state.views();
  for (std::size_t v = 0; v < views.size() && v < meshes_.size(); ++v) {
    MeshSlot& slot = meshes_[v];
    const int quantity = state.view.quantities.show.view(v).quantity;
    const QuantityDescriptor& d = quantityDescriptor(quantity);
    const ColorRange range = quantity > 0 ? shownRange(state, quantity) : ColorRange{};
    if (slot.quantityGeneration == state.view.quantities.generation && slot.view == views[v] &&
        slot.quantity == quantity && slot.range.lo == range.lo && slot.range.hi == range.hi)
      continue;
    slot.quantityGeneration = state.view.quantities.generation;
    slot.quantity = quantity;
    slot.range = range;
    const ViewMeasurement* m = quantity > 0 ? state.view.quantities.measurement(v) : nullptr;
    if (!m || m->values.size() != state.model.scene->meshVertices.rows()) {
      slot.colorMap = -1;
      continue;
    }
    const double noDetJ = std::numeric_limits<double>::quiet_NaN();
    Eigen::VectorXf t(m->values.size());
    for (Eigen::Index i = 0; i < t.size(); ++i)
      t[i] = colorCoordinate(m->values[i], m->detJ.size() ? m->detJ[i] : noDetJ, range, d.scale);
    const auto t0 = Clock::now();
    slot.mesh->setScalars(t);
    timings.uploadMs += msSince(t0);
    slot.colorMap = d.scale == ColorScale::LogDiverging ? render::kDivergingMap : render::kViridisMap;
  }
}

void Renderer::draw(const AppState& state, const std::vector<ViewRect>& views, int framebufferWidth,
                    int framebufferHeight, double framebufferScale, FrameTimings* timings) {
  render::clearFramebuffer(framebufferWidth, framebufferHeight, kBackground);
  if (!state.model.scene) return;
  render::ViewMatrices matrices;
  matrices.view = state.view.camera.viewMatrix().cast<float>();
  matrices.orthographic = state.view.camera.mode2D();
  render::MeshStyle meshStyle;
  meshStyle.wireframe = state.view.wireframe < 0 ? state.dim() == 2 : state.view.wireframe > 0;
  meshStyle.flat = state.view.flatShading;
  render::CageStyle cageStyle;
  if (state.dim() == 2) cageStyle.edgeColor = Eigen::Vector4f(0.25f, 0.45f, 0.95f, 1.0f);
  render::CageStyle previewStyle;  // Make cage's candidate: green, no handles (it cannot be edited yet)
  previewStyle.faceColor = Eigen::Vector4f(0.20f, 0.85f, 0.35f, 0.10f);
  previewStyle.edgeColor = Eigen::Vector4f(0.10f, 0.80f, 0.25f, 1.0f);
  previewStyle.showHandles = false;
  render::CageStyle tetsStyle;  // View > Show tetrahedra: edges only, orange (the cage is blue)
  tetsStyle.edgeColor = Eigen::Vector4f(0.95f, 0.55f, 0.15f, 0.9f);
  tetsStyle.showFaces = tetsStyle.showHandles = false;
  if (timings) timings->drawMs.assign(std::min(views.size(), meshes_.size()), 0.0);
  for (std::size_t v = 0; v < views.size() && v < meshes_.size(); ++v) {
    const auto t0 = Clock::now();
    const ViewRect& r = views[v];
    render::ViewportRect rect;
    rect.x = static_cast<int>(std::lround(r.x * framebufferScale));
    rect.width = std::max(1, static_cast<int>(std::lround(r.width * framebufferScale)));
    rect.height = std::max(1, static_cast<int>(std::lround(r.height * framebufferScale)));
    rect.y =
        framebufferHeight - static_cast<int>(std::lround(r.y * framebufferScale)) - rect.height;  // GL: bottom-left
    render::beginViewport(rect, &kViewBackground);
    matrices.projection = state.view.camera.projectionMatrix(r.width / r.height).cast<float>();
    meshStyle.colorMap = state.view.quantities.show.view(v).quantity > 0 ? meshes_[v].colorMap : -1;
    if (state.view.showMesh && meshes_[v].mesh) {
      meshes_[v].mesh->draw(matrices, meshStyle);
      if (timings) ++timings->meshDraws;
    }
    if (meshes_[v].tetsShown) meshes_[v].tets->draw(matrices, tetsStyle);
    if (state.jobs.cageMaker.isOpen() && state.jobs.cageMaker.candidate()) {
      preview_.draw(matrices, previewStyle);  // in place of the scene's cage
    } else if (state.view.showCage) {
      cage_.draw(matrices, cageStyle);
    }
    if (timings) {  // the pane's commands run now, not at the swap (llvmpipe rasterises at the flush)
      render::finishGl();
      timings->drawMs[v] = msSince(t0);
    }
  }
  render::endViewports(framebufferWidth, framebufferHeight);
}

}  // namespace somicage::editor
