#include "gpu_benchmark.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <vector>

#include "gl_objects.h"
#include "gpu_deformer.h"
#include "mesh_renderer.h"
#include "offscreen_context.h"

namespace somicage::render {

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

}  // namespace

GpuFrameTiming benchmarkGpuDeform(const CageDeformer& deformer, const Eigen::MatrixXd& posed,
                                  const DeformParams& params, int frames, const Eigen::MatrixXi& triangles,
                                  GpuDeformerLayout layout) {
  GpuFrameTiming timing;
  const OffscreenGlContext context(4, 3);
  if (!context.ok()) {
    timing.reason = context.reason();
    return timing;
  }
  timing.device = context.info().renderer + " (OpenGL " + context.info().version + ")";
  if (!GpuDeformer::available(&timing.reason)) return timing;
  try {
    // The GPU objects live in this scope, so they are deleted before the context.
    MeshRenderer mesh;
    if (triangles.size() > 0) mesh.setTopology(triangles);
    GpuDeformer gpu(layout);
    timing.layout = std::to_string(gpu.layout().rowThreads) + " x " + std::to_string(gpu.layout().groupPoints);

    glFinish();
    Clock::time_point t0 = Clock::now();
    gpu.upload(deformer);
    glFinish();
    timing.uploadMs = since(t0);

    for (int i = 0; i < 2; ++i) gpu.deform(posed, params, mesh);  // compiles the kernels, touches the buffers
    glFinish();

    std::vector<double> wall, gpuTimes, weights;
    for (int i = 0; i < std::max(frames, 1); ++i) {
      t0 = Clock::now();
      (void)deformer.frameWeights(posed, params);
      weights.push_back(since(t0));

      glFinish();
      t0 = Clock::now();
      gpu.deform(posed, params, mesh);
      glFinish();
      wall.push_back(since(t0));
      gpuTimes.push_back(gpu.lastGpuMilliseconds());  // deform()'s own timer query, finished after glFinish
    }
    timing.frames = static_cast<int>(wall.size());
    timing.frameMs = median(wall);
    timing.gpuMs = median(gpuTimes);
    timing.weightsMs = median(weights);
    timing.ok = true;
  } catch (const std::exception& e) {
    timing.reason = e.what();
  }
  return timing;
}

double timeGpuDeformMs(const CageDeformer& deformer, const Eigen::MatrixXd& posed, const DeformParams& params,
                       int frames, std::string* reason) {
  const GpuFrameTiming timing = benchmarkGpuDeform(deformer, posed, params, frames);
  if (reason) *reason = timing.reason;
  return timing.ok ? timing.frameMs : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace somicage::render
