// The editor's quantity state: what each view shows (view_quantity.h) and the measurements installed from the
// measurement job (measure_worker.h, state.jobs.measure), one per view. No GL, no ImGui.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "analysis/deformation_analysis.h"
#include "jobs/measure_worker.h"
#include "model/view_quantity.h"

namespace somicage::editor {

struct ViewQuantities {
  ShowSettings show;
  std::vector<std::optional<ViewMeasurement>> measured;  // per view: the installed measurement, if any
  MeasureKey installed;                                  // the key of the measurements in `measured`
  std::uint64_t generation = 0;                          // bumps when `measured` changes (the renderer re-uploads)
  int droppedStale = 0;                                  // outcomes dropped because their key was no longer current

  std::vector<NuSweepEntry> nuSweep;              // the current parameters' (the volume line, the click)
  std::vector<VariantSweep> nuSweepVariants;       // Somigliana: each variant's fold-overs at the same nu
  // What the sweep was made of, nu aside (nu is what it sweeps): the pose, the method's deformer and its other
  // parameters. An empty pose: it was made of a pose already gone when it arrived.
  Eigen::MatrixXd nuSweepPose;
  std::weak_ptr<const CageDeformer> nuSweepDeformer;
  DeformParams nuSweepParams;
  bool sweepRequested = false;

  // Drops the plot (another scene or cage, compare turned on or off).
  void clearSweep() {
    nuSweep.clear();
    nuSweepVariants.clear();
    nuSweepPose.resize(0, 0);
    nuSweepDeformer.reset();
  }

  const ViewMeasurement* measurement(std::size_t view) const {
    return view < measured.size() && measured[view] ? &*measured[view] : nullptr;
  }
  std::vector<const ViewMeasurement*> measurements(std::size_t viewCount) const {
    std::vector<const ViewMeasurement*> out;
    for (std::size_t v = 0; v < viewCount; ++v) out.push_back(measurement(v));
    return out;
  }
};

}  // namespace somicage::editor
