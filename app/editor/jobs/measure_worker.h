// Measures the views' quantities on a worker thread (background_job.h), so the editor keeps drawing while the
// exact J is set up (seconds on FIREHYDRANT) and each pose is measured: the J-based quantities, the difference
// between two views (both deformed here, so the UI thread never deforms on the CPU for it, whatever the device),
// the coordinate field of a cage element, and the nu sweep. The worker keeps what is expensive to make and independent
// of the pose (the deformation gradients per deformer, the field's terms per element) between requests, and frees it as
// soon as no view uses it. An outcome carries the key of its request; the editor installs it only when that key is
// still the current one (a result from a stale pose, scene or choice is dropped, and the current pose measured next).
// No GL, no ImGui.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "analysis/coordinate_fields.h"
#include "analysis/deformation_analysis.h"
#include "analysis/seam_jumps.h"
#include "deform/jacobian.h"
#include "jobs/background_job.h"
#include "model/scene.h"
#include "model/view_quantity.h"

namespace somicage::editor {

struct MeasureView {
  std::shared_ptr<const CageDeformer> deformer;  // Jacobian, Difference: the view's deformer (null: nothing to measure)
  int quantity = 0;
  DeformParams params;                                // the view's parameters (the field: its nu)
  int fieldVertex = -1;                               // Field: the selected cage vertex, else
  int fieldFace = -1;                                 // the selected cage face (-1 both: nothing selected)
  std::shared_ptr<const CageDeformer> otherDeformer;  // Difference: the other view's deformer (null: no other view)
  DeformParams otherParams;                           // and its parameters
};

struct MeasureRequest {
  std::shared_ptr<const Scene> scene;
  std::vector<MeasureView> views;  // per view
  Eigen::MatrixXd pose;
  std::uint64_t poseGeneration = 0;  // names the pose and parameters (AppState::deformGeneration)
  std::vector<double> sweepNus;      // non-empty: the nu sweep of views[sweepView] instead of the views
  int sweepView = 0;
  bool sweepVariants = false;  // the sweep also runs each Somigliana variant (variantChoices()) at those nu
};

// What a request is of: two requests with equal keys measure the same thing.
struct MeasureKey {
  using Params = std::vector<double>;  // every parameter's value (parameter_schema.h: parameterValues)
  const Scene* scene = nullptr;
  std::uint64_t poseGeneration = 0;
  // deformer, quantity, vertex, face, parameters; the other view's deformer and parameters (a difference)
  std::vector<std::tuple<const CageDeformer*, int, int, int, Params, const CageDeformer*, Params>> views;
  bool sweep = false;
  bool operator==(const MeasureKey& other) const;
  bool operator!=(const MeasureKey& other) const { return !(*this == other); }
};
MeasureKey measureKey(const MeasureRequest& request);
// Whether a request has anything for the worker (a J-based, difference or field view, or a sweep).
bool needsWorker(const MeasureRequest& request);

// One variant's fold-over line of the nu sweep (the view's parameters with that variant's kind and blend).
struct VariantSweep {
  std::string variant;  // variantChoices()' name
  std::vector<NuSweepEntry> entries;
};

struct MeasureOutcome {
  MeasureKey key;
  std::vector<std::optional<ViewMeasurement>> views;  // per view of the request (empty: not measured here)
  std::vector<NuSweepEntry> sweep;                    // a sweep request's entries
  std::vector<VariantSweep> variantSweeps;            // and, with sweepVariants, one line per variant
  double seconds = 0;
  bool cancelled = false;
  std::string error;
};

class MeasureWorker {
 public:
  // Cancels a running request and starts this one.
  void start(MeasureRequest request);
  void cancel() { job_.cancel(); }
  bool busy() const { return job_.busy(); }
  // Called on the worker thread when a request has finished (background_job.h).
  void setOnFinished(std::function<void()> onFinished) { job_.setOnFinished(std::move(onFinished)); }
  bool ready() const { return job_.ready(); }  // an outcome waits for poll()
  double progress() const { return job_.progress(); }
  std::string stage() const { return job_.stage(); }
  std::optional<MeasureOutcome> poll() { return job_.poll(); }
  // Cancels and frees the gradients and field terms (no J-based quantity in use any more); a running job keeps the
  // old ones until it ends, nothing waits for it.
  void release();
  // Bytes held between requests (gradients and field terms); 0 while busy (the worker owns them then).
  std::size_t heldBytes() const;

 private:
  struct Caches {
    struct Gradients {
      std::shared_ptr<const CageDeformer> deformer;  // keeps the deformer the gradients refer to alive
      std::shared_ptr<const DeformationGradients> gradients;  // the deformer's (CageDeformer::gradients)
      std::unique_ptr<SeamJumpEvaluator> seams;  // while a view shows the seams (seam_jumps.h)
    };
    std::map<const CageDeformer*, Gradients> gradients;
    const Scene* fieldScene = nullptr;
    std::optional<ElementTerms> field, gridField;  // at the mesh vertices; 2D: at fieldGrid too
    Eigen::MatrixXd fieldGrid;
  };
  static MeasureOutcome run(const MeasureRequest& request, Caches& caches, JobContext& context);

  std::shared_ptr<Caches> caches_ = std::make_shared<Caches>();  // declared before job_: destroyed after its thread
  BackgroundJob<MeasureOutcome> job_;
};

}  // namespace somicage::editor
