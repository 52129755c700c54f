// The engine facade: the one sequence every front end (the command line, the editor, the Python module) runs.
//   1. load + repair + validate + warn a cage (prepareCage / loadUsableCage): always in this order, here only;
//   2. the points of a mesh for that cage, with the placement warning (meshPointsFor);
//   3. precompute (precompute): the memory check, then the method's precompute (method.h), CPU or with an
//      injected integrator (PrecomputeOptions::rowIntegrator), with progress and cancel;
//   4. deform to positions (deformPoints), with the posed cage checked against the rest cage;
//   5. deform to quantities (analyzePose): the numbers of `somicage analyze`, from the exact J (jacobian.h).
// Plain Eigen in and out; every problem with an input is an InputError with the message the command line prints.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/deformation_analysis.h"
#include "base/progress.h"
#include "deform/deformer.h"
#include "deform/frame_evaluator.h"
#include "deform/memory_estimate.h"
#include "geometry/cage.h"
#include "io/mesh_formats.h"
#include "io/obj_io.h"

namespace somicage {

// Something a front end should tell the user while loading: a repair made, or a warning about the input.
struct Notice {
  enum class Kind { Repair, Warning };
  Kind kind;
  std::string source;  // the file (or name) it is about; empty when the text names its files itself
  std::string text;    // one sentence: what was done or what is wrong, and what to do about it
};
using NoticeSink = std::function<void(const Notice&)>;
// "note: SOURCE: TEXT" for a repair, "warning: SOURCE: TEXT" for a warning (no "SOURCE: " when it has none): the
// command line prints it after "somicage: ", the Python module emits it as a SomiCageWarning.
std::string describeNotice(const Notice& notice);
inline void ignoreNotices(const Notice&) {}

// Repairs the orientation (cage_repair.h), then validates the repaired cage (cage_validation.h): each repair is a
// Repair notice and each warning a Warning notice, both sent before a refusal, so the user sees what was tried.
// Throws InputError naming `source` when the repaired cage is still not valid.
Cage prepareCage(Cage cage, const std::string& source, const NoticeSink& notices);

// The cage in a file of any readable format (mesh_formats.h: loadAnyMesh, cageFromMesh), then prepareCage. A 3D cage
// that is not closed as read from a format ReadOptions::weld applies to, read without it, is refused first with
// --weld as the remedy (saying whether the welded cage would be closed).
Cage loadUsableCage(const std::string& path, const NoticeSink& notices, const ReadOptions& read = {});

// The points a cage of dimension d deforms (#V by d: the mesh's x, y, z, or x, y for a 2D cage), with a Warning
// notice (naming both sources in its text) when the mesh is far larger or smaller than the cage, or beside it
// (mesh_placement.h).
Eigen::MatrixXd meshPointsFor(const Cage& cage, const Eigen::MatrixXd& meshVertices, const std::string& meshSource,
                              const std::string& cageSource, const NoticeSink& notices);

// For a method that needs a volume mesh of the cage (MethodDescriptor::needsVolumeMesh) and has none yet: makes it
// (deformer.h: volumeMeshFor, from the method options "tets" / "tet-level" and the mesher) and stores it in
// options.volumeMesh, with a Repair notice naming the file when simplices were reoriented, and a Warning notice when
// the mesher fell back to another mesh than asked (VolumeMesh::fallback). Nothing otherwise.
// progress goes to the mesher, which may take seconds (Cancelled when it returns false).
void prepareVolumeMesh(Method method, const Cage& restCage, PrecomputeOptions& options, const NoticeSink& notices,
                       const ProgressCallback& progress = noProgress);

// The memory a precompute of `points` points will take (memory_estimate.h), with the deformation gradient's
// (jacobian.h) when withGradients; a volume method's counts the columns of options.volumeMesh (prepareVolumeMesh
// first). Throws InputError naming `source`, with `hint`, when it would not fit in the free memory.
MemoryEstimate requirePrecomputeMemory(Method method, const Cage& cage, std::size_t points,
                                       const PrecomputeOptions& options, const std::string& source,
                                       const std::string& hint, bool withGradients = false);

// How precompute checks the memory first.
struct MemoryCheck {
  std::string hint;            // what to do when it does not fit; empty: memoryHint(!options.floatStorage)
  bool withGradients = false;  // the deformation gradients will be built too (jacobian.h: analyze)
  std::function<void(const MemoryEstimate&)> fits;  // told the estimate when it fits, before the work; may be empty
};

// prepareVolumeMesh (notices dropped: call it first to show them), requirePrecomputeMemory (as `memory` says),
// then the method's precompute of points (#P by d) in the rest cage.
// Throws Cancelled when progress returns false.
std::unique_ptr<CageDeformer> precompute(Method method, const Cage& restCage, const Eigen::MatrixXd& points,
                                         const PrecomputeOptions& options, const std::string& source,
                                         const ProgressCallback& progress = noProgress, const MemoryCheck& memory = {});

// The Warning notice naming meshSource when some of the deformer's points lie outside the cage (or on it), in the
// words every front end shows (exterior_points.h); nullopt when none do.
std::optional<Notice> exteriorPointsNotice(const CageDeformer& deformer, const std::string& meshSource);

// Throws InputError naming `source` when posed is not #V by d of the rest cage, or not finite.
void requirePosedVertices(const Cage& restCage, const Eigen::MatrixXd& posed, const std::string& source);

// The deformed points (#P by d) for a posed cage of restCage (#V by d): checks the pose (requirePosedVertices,
// naming posedSource) and the parameters (the method's validateParams: InputError naming them), and the output:
// InputError naming meshSource if a point could not be deformed (a bug, never silent: every point gets a finite
// position).
Eigen::MatrixXd deformPoints(const CageDeformer& deformer, const Cage& restCage, const Eigen::MatrixXd& posed,
                             const DeformParams& params, const std::string& posedSource, const std::string& meshSource);
// The same with the frame evaluated by `evaluator` (frame_evaluator.h: one made for `deformer`).
Eigen::MatrixXd deformPoints(const CageDeformer& deformer, FrameEvaluator& evaluator, const Cage& restCage,
                             const Eigen::MatrixXd& posed, const DeformParams& params, const std::string& posedSource,
                             const std::string& meshSource);

// Numbers by name, in order: the quantiles {"min", ..., "max"} of a quantity.
using NamedNumbers = std::vector<std::pair<std::string, double>>;

// One pose measured: what `somicage analyze --json` prints (and Python's Deformer.analyze returns).
struct PoseAnalysis {
  DeformationAnalysis fields;         // positions, J, det J and distortion per point, area ratios, the volume
  NamedNumbers jacobianDet;           // min, p05, p50, p95, max of det J over the points with a J
  NamedNumbers conformalDistortion;   // p50, p95, max of sigma_max / sigma_min
  NamedNumbers areaRatio;             // p05, p50, p95, max of the faces' deformed / rest area
  NamedNumbers seamJump;              // p50, p95, max over the crossing edges (seam_jumps.h); empty: not measured
  std::vector<NuSweepEntry> nuSweep;  // one entry per nu of the sweep asked for
};

// Whether analyze measures the seams (seam_jumps.h) by default: for a method on a volume mesh (Phong), whose J
// jumps; a smooth method's are 0 and cost a tetrahedralization and a second precompute, so they are asked for.
bool measuresSeamsByDefault(Method method);

// The seam evaluator of the deformer's points (restPoints, #P by d) with faces over them (indices checked, naming
// facesSource): over the deformer's volume mesh, else the one its method would get for the cage (volumeMeshFor with
// `options`, the deformer's precompute options: InputError naming --tets when there is none). The memory of its
// precompute and gradients is checked first (requirePrecomputeMemory, naming facesSource).
std::unique_ptr<SeamJumpEvaluator> prepareSeamJumps(const CageDeformer& deformer, const Cage& restCage,
                                                    const Eigen::MatrixXd& restPoints,
                                                    const std::vector<std::vector<int>>& faces,
                                                    const PrecomputeOptions& options, const std::string& facesSource,
                                                    const ProgressCallback& progress = noProgress);

// For the deformer the gradients were made of: the pose and the parameters checked as deformPoints checks them
// (InputError naming posedSource or the parameter) and the faces' indices (naming facesSource); then
// analyzeDeformation (deformation_analysis.h) of the deformer's points (restPoints) with faces over them (and the
// seams when `seams` is given: prepareSeamJumps of the same points and faces), its quantiles, and sweepNu over nus
// (none: no sweep; progress is the sweep's).
PoseAnalysis analyzePose(const CageDeformer& deformer, const DeformationGradients& gradients, const Cage& restCage,
                         const Eigen::MatrixXd& restPoints, const std::vector<std::vector<int>>& faces,
                         const Eigen::MatrixXd& posed, const DeformParams& params, const std::vector<double>& nus,
                         const std::string& posedSource, const std::string& facesSource,
                         const ProgressCallback& progress = noProgress, const SeamJumpEvaluator* seams = nullptr);

}  // namespace somicage
