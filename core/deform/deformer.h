// One interface for every cage deformation method: precompute once from the rest cage and the points,
// then deform() for every posed cage and parameter set (cheap, called every frame).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "base/progress.h"
#include "deform/deform_params.h"
#include "deform/exterior_points.h"
#include "deform/frame_evaluation.h"
#include "deform/method.h"
#include "geometry/cage.h"
#include "geometry/integration_options.h"
#include "geometry/volume_mesh.h"

namespace somicage {

class DeformationGradients;  // jacobian.h

struct PrecomputeOptions {
  IntegrationOptions integration;  // Somigliana only
  int threads = 0;                 // 0 = the OpenMP default, for the precompute and every frame
  bool floatStorage = false;       // store the coordinate matrix in float (see frame_evaluation.h)
  // Integrates the rows of the methods that integrate row by row (Somigliana): empty = the CPU's; a device's
  // (cuda_backend.h: cudaRowIntegrator) may be injected. The rows are written into C by the method either way.
  RowIntegrator rowIntegrator;
  // The method's own options (MethodDescriptor::options), by key: e.g. Phong's "tets" and "tet-level".
  MethodOptions methodOptions;
  // For a method that needs a volume mesh of the rest cage (MethodDescriptor::needsVolumeMesh): the mesh when a
  // front end has made it already (engine.h: prepareVolumeMesh), else the method makes it (volumeMeshFor: the
  // "tets" file, else volumeMesher, else the star of the cage's faces).
  std::shared_ptr<const VolumeMesh> volumeMesh;
  VolumeMesher volumeMesher;
  // For a volume method: point p is evaluated in simplex pointSimplices[p] of the volume mesh (>= 0, one that holds
  // it) instead of the one it is located in: a point on a face between two simplices seen from either side
  // (seam_jumps.h). Empty: every point is located. Methods without a volume mesh ignore it (their rows are one
  // function of the point).
  std::vector<int> pointSimplices;
};

// A volume method's mesh: options.volumeMesh; else the MEDIT file methodOptions["tets"] (checkVolumeMesh: *reoriented
// counts the reoriented simplices); else, with no "tet-level" asked for, the cage's star (starVolumeMesh) when it is
// star-shaped from its centroid; else options.volumeMesher's (checked too). Throws InputError naming --tets when
// there is none (a cage not star-shaped from its centroid, and no mesher). progress goes to the mesher (Cancelled).
std::shared_ptr<const VolumeMesh> volumeMeshFor(const Cage& restCage, const PrecomputeOptions& options,
                                                int* reoriented = nullptr,
                                                const ProgressCallback& progress = noProgress);

// Per-point facts established by the precompute (#P each; empty where a method does not provide them).
struct PrecomputeDiagnostics {
  Eigen::VectorXd winding;        // generalised winding number w.r.t. the rest cage: 1 inside, 0 outside
  Eigen::VectorXd unityResidual;  // Somigliana: max |sum_i T_i - I| (Eq. 9); meaningful inside only
  // Somigliana, Green: how each point is deformed; the ones not Inside follow the exterior rule of
  // exterior_points.h (outside the cage, on it, or with unreliable integrals).
  std::vector<PointRegion> regions;

  int exteriorCount() const {
    return static_cast<int>(
        std::count_if(regions.begin(), regions.end(), [](PointRegion r) { return r != PointRegion::Inside; }));
  }
};

// A method's precomputed coordinates (the matrix C of frame_evaluation.h) and its per-frame weights.
class CageDeformer {
 public:
  virtual ~CageDeformer() = default;

  virtual Method method() const = 0;
  virtual int dim() const = 0;

  // The per-frame weight matrix W for a posed cage (#V by d, rest cage order). Validates params.
  virtual FrameWeights frameWeights(const Eigen::MatrixXd& posedVertices, const DeformParams& params) const = 0;

  // The exact gradients dC_p/dx_a (a < d) of the point rows of C (#P rows, C's columns and storage each) for the
  // deformation gradient (jacobian.h), from dual numbers through the method's closed forms; the rows of points
  // that are not Inside (diagnostics().regions) are zero. Integrates again: build them only while a J-based
  // quantity is in use. points: the points the deformer was made for.
  virtual std::vector<FrameCoordinates> coordinateGradients(const Eigen::MatrixXd& points,
                                                            const ProgressCallback& progress) const = 0;

  // A volume method's mesh of the rest cage (MethodDescriptor::needsVolumeMesh; null for the other methods) and its
  // vertices for a posed cage (#N by d: the cage's, then the Steiner vertices where the frame puts them; empty
  // without a mesh): what the editor draws as the tetrahedra's wireframe. Validates params.
  virtual std::shared_ptr<const VolumeMesh> volumeMesh() const { return nullptr; }
  virtual Eigen::MatrixXd posedVolumeMesh(const Eigen::MatrixXd& posedVertices, const DeformParams& params) const;

  // The exact gradients of J at the deformer's points (jacobian.h), integrated on the first call and kept with C:
  // they are a function of what C is (the rest cage, the points, the method and its precompute options), never of
  // the pose or the parameters (nu, gamma, variant, normals and bulging enter only W), so this deformer is their
  // key and a new cage, points or options mean a new deformer (docs/engine.md, "The gradients' cache"). Every front
  // end takes them here. A second caller waits for a running integration and shares its result; a cancelled one
  // (Cancelled) keeps nothing. points: the points the deformer was made for.
  std::shared_ptr<const DeformationGradients> gradients(const Eigen::MatrixXd& points,
                                                        const ProgressCallback& progress = noProgress) const;
  std::shared_ptr<const DeformationGradients> keptGradients() const;  // null while none are kept
  // Forgets the kept gradients (their memory is freed once no caller holds them); an integration running meanwhile
  // returns its result without keeping it.
  void releaseGradients() const;
  int gradientIntegrations() const;  // how often gradients() integrated (what the cache's tests count)

  const FrameCoordinates& frameCoordinates() const { return coordinates_; }
  const PrecomputeDiagnostics& diagnostics() const { return diagnostics_; }
  int numPoints() const { return coordinates_.numPoints(); }
  int threads() const { return threads_; }  // a frame's OpenMP threads (0: the default)

  // The deformed points (#P by d, resized) for a posed cage: evaluateFrame(C, frameWeights(...)).
  void deform(const Eigen::MatrixXd& posedVertices, const DeformParams& params, Eigen::MatrixXd& out) const;
  Eigen::MatrixXd deform(const Eigen::MatrixXd& posedVertices, const DeformParams& params) const {
    Eigen::MatrixXd out;
    deform(posedVertices, params, out);
    return out;
  }

 protected:
  CageDeformer(FrameCoordinates coordinates, int threads) : coordinates_(std::move(coordinates)), threads_(threads) {}

  FrameCoordinates coordinates_;
  int threads_;
  PrecomputeDiagnostics diagnostics_;

 private:
  struct GradientCache {
    std::mutex integrating;  // held through an integration: one at a time
    std::mutex slot;         // held briefly, for the fields below
    std::shared_ptr<const DeformationGradients> kept;
    std::uint64_t releases = 0;
    int integrations = 0;
  };
  mutable GradientCache gradientCache_;
};

// Precomputes the coordinates of points (#P by d) in the rest cage with the method's descriptor (method.h).
// Throws Cancelled if progress says stop.
std::unique_ptr<CageDeformer> makeDeformer(Method method, const Cage& restCage, const Eigen::MatrixXd& points,
                                           const PrecomputeOptions& options = {},
                                           const ProgressCallback& progress = noProgress);

}  // namespace somicage
