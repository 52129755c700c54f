// The editor's per-frame deformation on the GPU: an OpenGL 4.3 compute shader that evaluates exactly what
// evaluateFrame() (core/deform/frame_evaluation.h) does on the CPU, for every method and with the exterior blend, and
// writes the deformed positions straight into a MeshRenderer's vertex buffer; two more passes compute its smooth
// vertex normals there. Per frame only W (K by at most 12 floats) goes up; positions never come back to the CPU
// (readBack() is for tests). No GL types in this header; create, use and destroy only while the GL context that
// initOpenGl() loaded is current.
//
// Precision: C is stored in float on the GPU (converted once from double storage) and every frame sums K float
// products per output, then solves the 3x3 (2x2) system of Eq. 11 in float. The tests (tests/editor/
// gpu_deformer_test.cpp) hold the result to the CPU deform() within 1e-5 of the cage diameter.
#pragma once

#include <Eigen/Core>
#include <chrono>
#include <memory>
#include <string>

#include "deform/deformer.h"
#include "mesh_renderer.h"

namespace somicage::render {

// How the deformation kernel maps work to invocations (see shaders/deform_frame.comp.glsl).
struct GpuDeformerLayout {
  int rowThreads = 0;   // invocations per point, a power of two <= 64; 0 = automatic (see chooseLayout)
  int groupPoints = 0;  // points per work group; 0 = automatic
};

class GpuDeformer {
 public:
  // True when the current context can run the deformer (OpenGL 4.3: compute shaders and storage buffers).
  // Otherwise false, and *reason (when given) says what is missing, for the UI.
  static bool available(std::string* reason = nullptr);

  // Requires available(). Compiles nothing yet (each specialisation of the kernel is compiled on first use).
  explicit GpuDeformer(GpuDeformerLayout layout = {});
  ~GpuDeformer();
  GpuDeformer(const GpuDeformer&) = delete;
  GpuDeformer& operator=(const GpuDeformer&) = delete;
  GpuDeformer(GpuDeformer&&) noexcept;
  GpuDeformer& operator=(GpuDeformer&&) noexcept;

  // Uploads C = deformer.frameCoordinates() (#P + 2 #E by K, converted to float when stored in double) and its
  // exterior blends, once per precompute. Keeps a reference to `deformer` for frameWeights(): it must outlive
  // this upload.
  void upload(const CageDeformer& deformer);
  bool uploaded() const;
  int numPoints() const;

  // Deforms into target's vertex buffers: positions (#P by 3 floats, z = 0 in 2D) and, when target has
  // triangles, their smooth vertex normals (as render/mesh_normals.h computes them). Builds the per-frame W on the
  // CPU (CageDeformer::frameWeights, which validates params and may throw InputError). target must draw #P
  // vertices. Does not wait for the GPU.
  void deform(const Eigen::MatrixXd& posedVertices, const DeformParams& params, MeshRenderer& target);
  // The same with a frame's weights built by the caller (the uploaded deformer's frameWeights).
  void deform(const FrameWeights& W, MeshRenderer& target);

  // Tests only (stalls): the positions (#P by d) and normals (#P by 3) that the last deform() wrote into target.
  Eigen::MatrixXd readBack(MeshRenderer& target) const;
  Eigen::MatrixXd readBackNormals(MeshRenderer& target) const;

  // Timing of deform(): the CPU part of the last call (frameWeights, the W upload, issuing the dispatches), and
  // the GPU time of the most recent call whose GL timer query has finished (NaN before any), read without waiting.
  // On a software renderer (softwareRenderer()) timer queries do not cover the compute work, which runs on the
  // renderer's CPU threads when flushed; there deform() ends with glFinish and the "GPU time" is that wall time.
  double lastCpuMilliseconds() const;
  double lastGpuMilliseconds();

  // The work layout in use ("32 x 8": invocations per point x points per group).
  GpuDeformerLayout layout() const;

  // The automatic layout for the current context: 32 invocations per point reading its row of C side by side
  // (coalesced loads) on GPUs; 8 per point on software renderers, where it measured fastest (gpu_deformer.cpp).
  static GpuDeformerLayout chooseLayout();

  // True for renderers that run on the CPU (Mesa llvmpipe/softpipe, SwiftShader): compute shaders work there, but
  // the CPU backend (core's evaluateFrame) is an order of magnitude faster, so the editor defaults to it.
  static bool softwareRenderer();

 private:
  // deform()'s GPU part; t0: when the frame started, for lastCpuMilliseconds().
  void submit(const FrameWeights& W, MeshRenderer& target, std::chrono::steady_clock::time_point t0);

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace somicage::render
