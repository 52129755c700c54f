// The editor's Renderer: owns the GPU copies of the scene (one mesh per viewport, one cage) and draws the
// viewports from AppState. Declared next to AppState and destroyed before the GL context. The GL calls
// themselves live in render/; this file sees no GL header. In place on OpenGL (frame_device_evaluators.h: the
// "opengl" device) it also owns one GpuDeformer per viewport, which deforms straight into that viewport's vertex
// buffers.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "cage_renderer.h"
#include "engine/view_spec.h"
#include "gpu_deformer.h"
#include "mesh_renderer.h"
#include "model/app_state.h"
#include "model/view_quantity.h"
#include "ui/frame_timings.h"
#include "ui/layout.h"

namespace somicage::editor {

class Renderer {
 public:
  Renderer();

  // Uploads what changed since the last call: topology when the scene changed, positions when the pose or
  // the deformation changed, the selection flags when the pose generation changed. In place on OpenGL, deforms
  // the changed views on the GPU instead (C uploaded once per deformer) and writes the timing into state.stats; a
  // GPU failure switches the state to the CPU (the reason in devices.unavailable and state.errors).
  void sync(AppState& state);

  // Clears the framebuffer and draws every viewport. views are in window pixels; framebufferScale converts
  // them to framebuffer pixels (HiDPI).
  // With `timings`, each pane's draw is finished (glFinish) and timed into it.
  void draw(const AppState& state, const std::vector<ViewRect>& views, int framebufferWidth, int framebufferHeight,
            double framebufferScale, FrameTimings* timings = nullptr);

 private:
  struct MeshSlot {
    std::unique_ptr<render::MeshRenderer> mesh;
    std::uint64_t sceneGeneration = ~0ull, deformGeneration = ~0ull;
    ViewSpec view;  // what the slot shows (its method and own parameters)
    bool showedDeformed = false;
    // In place on OpenGL: the deformer whose C is on the GPU (held, so its address cannot be reused by a new one).
    std::unique_ptr<render::GpuDeformer> gpu;
    std::shared_ptr<const CageDeformer> uploaded;
    bool onGpu = false;                        // the vertex buffers hold the GPU's result
    std::uint64_t quantityGeneration = ~0ull;  // ViewQuantities::generation of the uploaded scalars
    int quantity = 0;                          // and their quantity and range
    ColorRange range;
    int colorMap = -1;  // MeshStyle::colorMap of the uploaded scalars
    // View > Show tetrahedra: the view's volume mesh as a wireframe (edges of the deformer's mesh, posed).
    std::unique_ptr<render::CageRenderer> tets;
    std::shared_ptr<const CageDeformer> tetsDeformer;  // whose mesh the edges are (held: its address stays unique)
    std::uint64_t tetsGeneration = ~0ull;              // the deformGeneration the positions are posed for
    bool tetsShown = false;                            // the positions are current and drawn
  };
  // Poses slot v's tetrahedra for the view's deformer when View > Show tetrahedra is on and it has a volume mesh.
  void syncTets(MeshSlot& slot, const AppState& state, std::size_t v);
  // Uploads the shown quantity's colour-map coordinates of each view (shared range) when they changed.
  void syncScalars(const AppState& state, FrameTimings& timings);
  // Deforms slot v (view v) on the GPU when stale; returns true when it ran. Throws what GpuDeformer throws.
  bool syncGpu(MeshSlot& slot, const AppState& state, std::size_t v, bool newScene);
  std::vector<MeshSlot> meshes_;
  render::CageRenderer cage_;
  std::uint64_t cageScene_ = ~0ull, cagePose_ = ~0ull;
  render::CageRenderer preview_;  // File > Make cage's candidate (cage_maker.h)
  std::uint64_t previewGeneration_ = ~0ull;
};

}  // namespace somicage::editor
