// The editor's Renderer: owns the GPU copies of the scene (one mesh per viewport, one cage) and draws the
// viewports from AppState. Declared next to AppState and destroyed before the GL context. The GL calls
// themselves live in render/; this file sees no GL header.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "app_state.h"
#include "cage_renderer.h"
#include "layout.h"
#include "mesh_renderer.h"

namespace somicage::editor {

class Renderer {
 public:
  Renderer();

  // Uploads what changed since the last call: topology when the scene changed, positions when the pose or
  // the deformation changed, the selection flags when the pose generation changed.
  void sync(const AppState& state);

  // Clears the framebuffer and draws every viewport. views are in window pixels; framebufferScale converts
  // them to framebuffer pixels (HiDPI).
  void draw(const AppState& state, const std::vector<ViewRect>& views, int framebufferWidth, int framebufferHeight,
            double framebufferScale);

 private:
  struct MeshSlot {
    std::unique_ptr<render::MeshRenderer> mesh;
    std::uint64_t sceneGeneration = ~0ull, deformGeneration = ~0ull;
    Method method = Method::Somigliana;
    bool showedDeformed = false;
  };
  std::vector<MeshSlot> meshes_;
  render::CageRenderer cage_;
  std::uint64_t cageScene_ = ~0ull, cagePose_ = ~0ull;
};

}  // namespace somicage::editor
