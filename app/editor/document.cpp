#include "document.h"

namespace somicage::editor {

bool operator==(const Document& a, const Document& b) {
  const DeformParams &p = a.params, &q = b.params;
  return a.method == b.method && a.pose.rows() == b.pose.rows() && a.pose.cols() == b.pose.cols() && a.pose == b.pose &&
         p.nu == q.nu && p.gamma == q.gamma && p.blend == q.blend && p.tractionCorrection == q.tractionCorrection;
}

}  // namespace somicage::editor
