// Runs scene loading and makeDeformer() on a job (background_job.h), with progress and cancellation, so the UI stays
// responsive and keeps showing the old scene until the new one is ready. A request whose deformers would not fit in
// the free memory fails before any precompute, with the estimate in its error (core/deform/memory_estimate.h). No GL.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "deform/deformer.h"
#include "engine/view_spec.h"
#include "jobs/background_job.h"
#include "jobs/thread_budget.h"
#include "model/scene.h"

namespace somicage::editor {

// The editor stores coordinates in float: half the memory and the bytes read per frame (docs/engine.md).
inline PrecomputeOptions interactiveOptions() {
  PrecomputeOptions options;
  options.floatStorage = true;
  return options;
}

// One deformer per method and method options (views with equal keys share it).
using DeformerSet = std::map<DeformerKey, std::shared_ptr<const CageDeformer>>;

struct PrecomputeRequest {
  // Either a ready scene, or a loader run on the worker (file loading can take a while too).
  std::shared_ptr<const Scene> scene;
  std::function<Scene()> loadScene;
  std::string posedPath;             // a posed cage to read against the scene's rest cage, on the job too ("": none)
  std::vector<DeformerKey> methods;  // deformers to build, in this order (each with its options)
  PrecomputeOptions options = interactiveOptions();
  bool withGradients = false;  // a J-based quantity is shown: its gradients count in the memory check too
  // The cores it may use (thread_budget.h): all of them while a scene loads (the UI has nothing to deform), else all
  // but the UI's.
  int threads = ThreadBudget::machine().cores();
};

// A posed cage read on the job with the scene it poses (PrecomputeRequest::posedPath).
struct PosedCageRead {
  std::string path;                     // "": none asked for
  std::optional<Eigen::MatrixXd> pose;  // #V by d: read, and it fits the rest cage
  std::string error;                    // else why not (the file, what is wrong)
};

// The posed cage's vertices in the file at path against the rest cage, or why they cannot be had. Read on a job only:
// the precompute's (a posed cage given with the scene) or JobsState::posedCage (one loaded or dropped on the scene
// shown); the UI thread reads no file.
PosedCageRead readPosedCage(const std::string& path, const Cage& restCage);

// A posed cage read on JobsState::posedCage for the scene shown when it was asked for (document_files.cpp).
struct PosedCageLoad {
  std::shared_ptr<const Scene> scene;  // the pose applies to this scene only
  PosedCageRead read;
};

struct PrecomputeOutcome {
  std::uint64_t id = 0;                // as returned by start()
  std::shared_ptr<const Scene> scene;  // the scene the deformers belong to (null if loading failed)
  PosedCageRead posed;                 // the request's posed cage, read once the scene was there
  DeformerSet deformers;
  double seconds = 0.0;  // wall time of the whole request
  bool cancelled = false;
  std::string error;  // non-empty on failure (InputError text, bad_alloc, ...)
  // What the user should be told about deformers that were built (describeNotice: a Mesh_3 fallback to TetGen).
  std::vector<std::string> notices;
};

class PrecomputeWorker {
 public:
  // Supersedes any running request (its outcome never arrives; nothing waits for it), then starts this one. Returns
  // its id.
  std::uint64_t start(PrecomputeRequest request);
  void cancel() { job_.cancel(); }  // asks the running request to stop; it finishes with cancelled = true
  // Stops the latest request and drops what it has or will have (its loaded scene, its outcome): nothing of it
  // arrives. A load dropped on Cancel (pollWorker's question): its scene is freed once nothing else holds it.
  void discard();
  bool busy() const { return job_.busy(); }
  // Called on the job's thread when a request has finished (background_job.h), and when its scene has loaded.
  void setOnFinished(std::function<void()> onFinished);
  // The latest request's scene once it has loaded (before its deformers), with its posed cage, once; empty before
  // or when taken. The editor shows it, undeformed, while the deformers are computed.
  struct LoadedScene {
    std::shared_ptr<const Scene> scene;
    PosedCageRead posed;
  };
  std::optional<LoadedScene> takeLoadedScene();
  double progress() const { return job_.progress(); }  // 0..1 over all methods of the request
  std::string stage() const { return job_.stage(); }   // e.g. "Loading files", "Somigliana 2/3"
  // The outcome of the last finished request, once; empty while running or when already taken.
  std::optional<PrecomputeOutcome> poll() { return job_.poll(); }

 private:
  struct Handover {  // written by the job, taken by the UI thread
    std::mutex mutex;
    std::uint64_t id = 0;
    std::optional<LoadedScene> loaded;
  };
  std::uint64_t nextId_ = 1;
  std::shared_ptr<Handover> loaded_ = std::make_shared<Handover>();
  std::shared_ptr<const std::function<void()>> wake_;
  BackgroundJob<PrecomputeOutcome> job_;
};

}  // namespace somicage::editor
