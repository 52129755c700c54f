#include "cli/tightness_report.h"

#include <cmath>

#include "cli/command_support.h"

namespace somicage {

std::string describeTightness(const CageTightness& tightness) {
  return "Hausdorff cage -> mesh " + formatNumber(tightness.hausdorff, 3) + " diagonals, volume cage / mesh " +
         (std::isnan(tightness.volumeRatio) ? std::string("- (open mesh)") : formatNumber(tightness.volumeRatio, 3));
}

void writeTightness(JsonObjectWriter& json, const CageTightness& tightness) {
  json.field("hausdorff_diagonals", tightness.hausdorff);
  const bool closed = !std::isnan(tightness.volumeRatio);
  if (closed) {
    json.field("volume_ratio", tightness.volumeRatio);
  } else {
    json.null("volume_ratio");
  }
  json.field("mesh_closed", closed);
}

}  // namespace somicage
