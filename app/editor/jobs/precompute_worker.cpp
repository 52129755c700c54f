#include "jobs/precompute_worker.h"

#include <chrono>
#include <exception>
#include <new>
#include <utility>

#include "base/errors.h"
#include "deform/memory_estimate.h"
#include "deform/method.h"
#include "engine/engine.h"
#include "io/mesh_formats.h"

namespace somicage::editor {

namespace {
// Each deformer's precompute options: the request's with its key's method options, and a volume method's mesh made
// now (engine.h: prepareVolumeMesh), so that the memory check counts its columns and the precompute uses that mesh.
// Making it can take seconds (CGAL): Esc cancels it as it does the precompute.
std::vector<PrecomputeOptions> preparedOptions(const PrecomputeRequest& request, JobContext& context,
                                               std::vector<std::string>& notices) {
  std::vector<PrecomputeOptions> prepared;
  for (const DeformerKey& key : request.methods) {
    PrecomputeOptions options = request.options;
    options.methodOptions = key.options;
    if (key.method->needsVolumeMesh) context.setStage(std::string(key.method->displayName) + ": tetrahedra");
    prepareVolumeMesh(
        key.method, request.scene->restCage, options,
        [&](const Notice& n) { notices.push_back(std::string(key.method->displayName) + ": " + describeNotice(n)); },
        [&context](double) { return !context.cancelled(); });
    prepared.push_back(std::move(options));
  }
  return prepared;
}

// Refuses a request whose deformers would not fit in the free memory, before any of them is built.
void requireMemoryFor(const PrecomputeRequest& request, const std::vector<PrecomputeOptions>& prepared) {
  const Scene& scene = *request.scene;
  MemoryEstimate estimate;
  const std::size_t points = static_cast<std::size_t>(scene.meshVertices.rows());
  for (std::size_t k = 0; k < request.methods.size(); ++k) {
    const Method m = request.methods[k].method;
    const int vertices = layoutVertices(m, scene.restCage, prepared[k].volumeMesh.get());
    estimate += estimatePrecomputeMemory(m, scene.dim(), vertices, scene.restCage.numFaces(), points,
                                         request.options.floatStorage, request.options.threads);
    if (request.withGradients)
      estimate.gradients += estimateGradientBytes(m, scene.dim(), vertices, scene.restCage.numFaces(), points,
                                                  request.options.floatStorage);
  }
  requireMemory(estimate, availableMemoryBytes(), scene.isDemo() ? scene.name : scene.meshPath,
                memoryHint(!request.options.floatStorage));
}

// Loads the scene (and its posed cage) if asked, checks the memory, then builds each method's deformer; never throws.
PrecomputeOutcome runRequest(PrecomputeRequest request, std::uint64_t id, JobContext& context,
                             const std::function<void(std::shared_ptr<const Scene>, const PosedCageRead&)>& loaded) {
  const auto t0 = std::chrono::steady_clock::now();
  PrecomputeOutcome out;
  out.id = id;
  try {
    if (context.cancelled()) throw Cancelled();  // superseded while it waited for its cores
    if (!request.scene) {
      context.setStage("Loading files");
      request.scene = std::make_shared<const Scene>(request.loadScene());
    }
    out.scene = request.scene;
    if (!request.posedPath.empty()) out.posed = readPosedCage(request.posedPath, request.scene->restCage);
    loaded(request.scene, out.posed);
    request.options.threads = context.threads();
    const std::vector<PrecomputeOptions> prepared = preparedOptions(request, context, out.notices);
    requireMemoryFor(request, prepared);
    const std::size_t n = request.methods.size();
    for (std::size_t k = 0; k < n; ++k) {
      if (context.cancelled()) throw Cancelled();
      const DeformerKey& key = request.methods[k];
      context.setStage(std::string(key.method->displayName) + " " + std::to_string(k + 1) + "/" + std::to_string(n));
      const double share = 1.0 / static_cast<double>(n);
      out.deformers[key] =
          makeDeformer(key.method, request.scene->restCage, request.scene->meshVertices, prepared[k],
                       context.span(static_cast<double>(k) * share, static_cast<double>(k + 1) * share));
    }
    context.report(1.0);
  } catch (const Cancelled&) {
    out.cancelled = true;
    out.deformers.clear();
  } catch (const std::bad_alloc&) {
    out.error = "out of memory during the precomputation (try a smaller mesh)";
    out.deformers.clear();
  } catch (const std::exception& e) {
    out.error = e.what();
    out.deformers.clear();
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  context.setStage("");
  return out;
}
}  // namespace

PosedCageRead readPosedCage(const std::string& path, const Cage& restCage) {
  PosedCageRead read;
  read.path = path;
  try {
    read.pose = loadPosedVertices(path, restCage);
  } catch (const std::exception& e) {
    read.error = e.what();
  }
  return read;
}

std::uint64_t PrecomputeWorker::start(PrecomputeRequest request) {
  const std::uint64_t id = nextId_++;
  const int threads = request.threads;
  job_.start(
      [request = std::move(request), id, slot = loaded_, wake = wake_](JobContext& context) mutable {
        return runRequest(std::move(request), id, context,
                          [&](std::shared_ptr<const Scene> scene, const PosedCageRead& posed) {
                            {
                              std::lock_guard<std::mutex> lock(slot->mutex);
                              slot->id = id;
                              slot->loaded = LoadedScene{std::move(scene), posed};
                            }
                            if (wake && *wake) (*wake)();  // the frame loop shows the mesh now
                          });
      },
      threads);
  return id;
}

void PrecomputeWorker::setOnFinished(std::function<void()> onFinished) {
  wake_ = std::make_shared<const std::function<void()>>(onFinished);
  job_.setOnFinished(std::move(onFinished));
}

void PrecomputeWorker::discard() {
  job_.discard();
  ++nextId_;  // its scene, if it loads after this, is never taken (takeLoadedScene)
  std::lock_guard<std::mutex> lock(loaded_->mutex);
  loaded_->loaded.reset();
}

std::optional<PrecomputeWorker::LoadedScene> PrecomputeWorker::takeLoadedScene() {
  std::lock_guard<std::mutex> lock(loaded_->mutex);
  if (loaded_->id + 1 != nextId_) return std::nullopt;  // an older request's
  return std::exchange(loaded_->loaded, std::nullopt);
}

}  // namespace somicage::editor
