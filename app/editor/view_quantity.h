// What a view shows on its mesh besides shading (issue 12, polyscope's quantity model): a quantity is per-vertex
// scalars plus how to colour them. The J-based ones (det J, distortion, fold-overs) come from core's exact
// deformation gradient (core/deformation_analysis.h); its coordinate gradients are held only while such a quantity
// is shown, and evaluated when the pose settles (not during a drag). No GL, no ImGui.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "deformation_analysis.h"
#include "deformer.h"

namespace somicage::editor {

// How scalars become colours (render/color_map.h draws them): a diverging map centred at 1 on a log scale for
// ratios, viridis for magnitudes >= 1, and fold-overs (det J <= 0) in a colour of their own in every map.
enum class ColorScale { LogDiverging, Viridis };

struct QuantityDescriptor {
  const char* id;    // --show value
  const char* name;  // the Show menu and the legend
  ColorScale scale;
  bool usesJacobian;
  // The per-vertex scalars of a measured pose (#V); null for shading only.
  Eigen::VectorXd (*values)(const DeformationAnalysis& analysis, const Eigen::MatrixXi& triangles);
};

// The "Show" choices; index 0 is shading only. Add a quantity by adding a descriptor and its values in
// view_quantity.cpp.
const std::vector<QuantityDescriptor>& quantityDescriptors();
// The index of the descriptor with this id; throws InputError(option, ...) listing the ids otherwise.
int quantityIndex(const std::string& id, const std::string& option);

// One view's measured pose.
struct ViewMeasurement {
  Eigen::VectorXd values;    // #V scalars of the shown quantity (NaN: undefined)
  Eigen::VectorXd detJ;      // #V
  bool closed = false;       // the mesh is closed (else volumeChange is of the capped mesh)
  double volumeChange = 0;   // deformed / rest - 1
  int foldovers = 0;         // vertices with det J <= 0
  double distortionP95 = 0;  // 95th percentile of sigma_max / sigma_min
};

// The colour range shared by the views (a compare view colours every pane alike). LogDiverging: [1/m, m] with
// m = the largest ratio away from 1 (at least 1 + 1e-3); Viridis: [1, max].
struct ColorRange {
  double lo = 1, hi = 1;
};
ColorRange sharedRange(const std::vector<const ViewMeasurement*>& views, ColorScale scale);
// Where a value falls in the range, in [0, 1]; -1 for a fold-over (det J <= 0), -2 for NaN.
float colorCoordinate(double value, double detJ, const ColorRange& range, ColorScale scale);

// The deformation gradients of one method's deformer, held while a J-based quantity is shown.
class ViewQuantities {
 public:
  // Measures every method whose deformer is in `deformers` for the pose (no-op when nothing changed since the last
  // call: same deformers, pose, params and quantity). quantity 0 frees the gradients.
  void update(const std::map<Method, std::shared_ptr<const CageDeformer>>& deformers,
              const std::vector<Method>& methods, const Eigen::MatrixXd& restMesh, const Eigen::MatrixXi& triangles,
              const Eigen::MatrixXd& pose, const DeformParams& params, int quantity, std::uint64_t generation);
  const ViewMeasurement* measurement(Method method) const;

  // The nu sweep of one deformer's pose (deformation_analysis.h: sweepNu): with the held gradients, or with ones
  // made for this call only. `generation` names the pose, as in update().
  void sweepNu(const std::shared_ptr<const CageDeformer>& deformer, const Eigen::MatrixXd& restMesh,
               const Eigen::MatrixXi& triangles, const Eigen::MatrixXd& pose, const DeformParams& params,
               const std::vector<double>& nus, std::uint64_t generation);
  const std::vector<NuSweepEntry>& nuSweep() const { return nuSweep_; }
  std::uint64_t nuSweepGeneration() const { return nuSweepGeneration_; }  // the pose the sweep was made for
  std::uint64_t generation() const { return generation_; }                // bumps when a measurement changes

 private:
  struct Entry {
    std::shared_ptr<const CageDeformer> deformer;
    std::unique_ptr<DeformationGradients> gradients;
    ViewMeasurement measurement;
  };
  std::map<Method, Entry> entries_;
  std::uint64_t measured_ = ~0ull, generation_ = 0;
  int quantity_ = 0;
  std::vector<NuSweepEntry> nuSweep_;
  std::uint64_t nuSweepGeneration_ = ~0ull;
};

}  // namespace somicage::editor
