#include "precompute_worker.h"

#include <chrono>
#include <exception>
#include <new>

#include "errors.h"
#include "memory_estimate.h"

namespace somicage::editor {

namespace {
// Refuses a request whose deformers would not fit in the free memory, before any of them is built.
void requireMemoryFor(const PrecomputeRequest& request) {
  const Scene& scene = *request.scene;
  MemoryEstimate estimate;
  for (Method m : request.methods)
    estimate += estimatePrecomputeMemory(m, scene.dim(), scene.restCage.numVertices(), scene.restCage.numFaces(),
                                         static_cast<std::size_t>(scene.meshVertices.rows()),
                                         request.options.floatStorage, request.options.threads);
  requireMemory(estimate, availableMemoryBytes(), scene.isDemo() ? scene.name : scene.meshPath,
                memoryHint(!request.options.floatStorage));
}
}  // namespace

PrecomputeWorker::~PrecomputeWorker() {
  cancel_ = true;
  if (thread_.joinable()) thread_.join();
}

std::uint64_t PrecomputeWorker::start(PrecomputeRequest request) {
  cancel_ = true;
  if (thread_.joinable()) thread_.join();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    outcome_.reset();  // a cancelled predecessor's outcome is of no interest any more
  }
  cancel_ = false;
  progress_ = 0.0;
  busy_ = true;
  const std::uint64_t id = nextId_++;
  thread_ = std::thread(&PrecomputeWorker::run, this, std::move(request), id);
  return id;
}

void PrecomputeWorker::cancel() { cancel_ = true; }

std::string PrecomputeWorker::stage() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stage_;
}

void PrecomputeWorker::setStage(std::string s) {
  std::lock_guard<std::mutex> lock(mutex_);
  stage_ = std::move(s);
}

std::optional<PrecomputeOutcome> PrecomputeWorker::poll() {
  if (busy_) return std::nullopt;
  std::lock_guard<std::mutex> lock(mutex_);
  std::optional<PrecomputeOutcome> out = std::move(outcome_);
  outcome_.reset();
  return out;
}

std::optional<PrecomputeOutcome> PrecomputeWorker::wait() {
  if (thread_.joinable()) thread_.join();
  return poll();
}

void PrecomputeWorker::run(PrecomputeRequest request, std::uint64_t id) {
  const auto t0 = std::chrono::steady_clock::now();
  PrecomputeOutcome out;
  out.id = id;
  try {
    if (!request.scene) {
      setStage("Loading files");
      request.scene = std::make_shared<const Scene>(request.loadScene());
    }
    out.scene = request.scene;
    requireMemoryFor(request);
    const std::size_t n = request.methods.size();
    for (std::size_t k = 0; k < n; ++k) {
      if (cancel_) throw Cancelled();
      const Method m = request.methods[k];
      setStage(std::string(m->displayName) + " " + std::to_string(k + 1) + "/" + std::to_string(n));
      auto progress = [this, k, n](double f) {
        progress_ = (static_cast<double>(k) + f) / static_cast<double>(n);
        return !cancel_.load();
      };
      out.deformers[m] =
          makeDeformer(m, request.scene->restCage, request.scene->meshVertices, request.options, progress);
    }
    progress_ = 1.0;
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
  {
    std::lock_guard<std::mutex> lock(mutex_);
    outcome_ = std::move(out);
    stage_.clear();
  }
  busy_ = false;
}

}  // namespace somicage::editor
