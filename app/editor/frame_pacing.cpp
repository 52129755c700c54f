#include "frame_pacing.h"

namespace somicage::editor {

bool FramePacer::shouldDraw(const FrameDemand& d) {
  if (d.input || d.queued) settle_ = kSettleFrames;
  if (d.input || d.queued || d.changing || d.busy || settle_ > 0) {
    if (settle_ > 0) --settle_;
    return true;
  }
  return false;
}

double FramePacer::waitSeconds(const FrameDemand& d) const {
  if (d.queued || d.changing || settle_ > 0) return 0.0;
  return d.busy ? kBusySeconds : kIdleSeconds;
}

}  // namespace somicage::editor
