// somicage.Deformer: one precompute (makeDeformer) over a cage and points, then deform() and analyze() for every
// posed cage and parameter set. They run with the GIL released; the precompute reports progress and can be cancelled
// (python_progress.h). The deformed points come back as a Fortran-ordered (#P, d) float64 array that owns the
// engine's result matrix: no copy on the way out.
#pragma once

#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "deform/deformer.h"
#include "deform/jacobian.h"
#include "numpy_arrays.h"
#include "python_cage.h"
#include "python_progress.h"

namespace somicage {

struct PythonDeformOptions {
  double nu = 0.0;
  double gamma = 0.0;
  std::string variant = "global";
  std::optional<double> blend;  // overrides variant
  bool tractionFix = true;
  bool corotational = false;  // bem: remove the best-fit rotation before the linear solve
  std::vector<std::string> choices;  // a value name per choiceParameters() (bulging, normals); empty: defaults
};

class PythonDeformer {
 public:
  // points: (#P, d), or (#P, 3) for a 2D cage (x, y are used, as by `somicage deform`).
  // tets: a MEDIT volume mesh of the cage for a method that needs one (Phong's option "tets"); empty: the
  // cage's star when it is star-shaped from its centroid and no tetLevel is given, else the cage tetrahedralized at
  // tetLevel (Phong's option "tet-level", cage_tetrahedralization.h; default kDefaultTetLevel), as the CLI does.
  PythonDeformer(const PythonCage& cage, const ArrayArgument& points, const std::string& method, int threads,
                 bool floatStorage, const ProgressArgument& progress, const std::string& tets = "",
                 std::optional<int> tetLevel = std::nullopt);

  // posed: the cage's vertices moved, (#V, d) (or (#V, 3) for a 2D cage). Returns (#P, d).
  Eigen::MatrixXd deform(const ArrayArgument& posed, const PythonDeformOptions& options) const;

  // The numbers of `somicage analyze --json` for that pose, as a dict with its keys; faces: lists of 0-based indices
  // of the points (none: no volume or area ratios); nuSweep: (from, to, count) as --nu-sweep FROM:TO:N. The
  // deformation gradients are integrated on the first call and kept; progress covers that integration and the sweep
  // (and stops them, as in the constructor). seams: measure seam_jump (seam_jumps.h; nullopt: as analyze does,
  // for a volume method), over the tetrahedral mesh the method has or Phong would use (tets=, else the cage's star).
  pybind11::dict analyze(const ArrayArgument& posed, const std::vector<std::vector<int>>& faces,
                         const PythonDeformOptions& options,
                         const std::optional<std::tuple<double, double, int>>& nuSweep,
                         const ProgressArgument& progress, std::optional<bool> seams = std::nullopt) const;

  const CageDeformer& engine() const { return *deformer_; }
  int dim() const { return deformer_->dim(); }

 private:
  Eigen::MatrixXd posedVertices(const ArrayArgument& posed) const;

  std::unique_ptr<CageDeformer> deformer_;
  Cage restCage_;           // for the pose's vertex count and order checks
  Eigen::MatrixXd points_;  // the deformer's points, for analyze
  PrecomputeOptions options_;  // the precompute's (its volume mesh, tets=), for the seams' mesh
};

}  // namespace somicage
