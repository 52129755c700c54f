// How `somicage check` and `somicage cage` report a cage's fit around a mesh (core/generation/cage_enclosure.h's
// CageTightness): the same words and JSON keys in both.
#pragma once

#include <string>

#include "cli/json_writer.h"
#include "generation/cage_enclosure.h"

namespace somicage {

// "Hausdorff cage -> mesh 0.052 diagonals, volume cage / mesh 2.31" ("- (open mesh)" for an open mesh).
std::string describeTightness(const CageTightness& tightness);

// "hausdorff_diagonals", "volume_ratio" (null for an open mesh) and "mesh_closed".
void writeTightness(JsonObjectWriter& json, const CageTightness& tightness);

}  // namespace somicage
