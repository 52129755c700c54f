#include "model/document.h"

namespace somicage::editor {

namespace {

bool samePoses(const PoseLibrary& a, const PoseLibrary& b) {
  if (a.poses().size() != b.poses().size()) return false;
  for (size_t k = 0; k < a.poses().size(); ++k) {
    const NamedPose &p = a.poses()[k], &q = b.poses()[k];
    if (p.name != q.name || p.vertices.rows() != q.vertices.rows() || p.vertices.cols() != q.vertices.cols() ||
        p.vertices != q.vertices)
      return false;
  }
  return true;
}

bool sameTimeline(const Timeline& a, const Timeline& b) {
  if (a.keys.size() != b.keys.size() || a.interpolation != b.interpolation || a.fps != b.fps ||
      a.firstFrame != b.firstFrame || a.lastFrame != b.lastFrame || a.loop != b.loop)
    return false;
  for (size_t k = 0; k < a.keys.size(); ++k) {
    const Keyframe &p = a.keys[k], &q = b.keys[k];
    if (p.frame != q.frame || p.pose != q.pose || p.nu != q.nu || p.gamma != q.gamma) return false;
  }
  return true;
}

}  // namespace

bool sameCage(const Cage& a, const Cage& b) {
  return a.vertices.rows() == b.vertices.rows() && a.vertices.cols() == b.vertices.cols() && a.vertices == b.vertices &&
         a.faces.rows() == b.faces.rows() && a.faces.cols() == b.faces.cols() && a.faces == b.faces;
}

bool operator==(const Document& a, const Document& b) {
  return a.method == b.method && a.pose.rows() == b.pose.rows() && a.pose.cols() == b.pose.cols() && a.pose == b.pose &&
         a.params == b.params && samePoses(a.poses, b.poses) && sameTimeline(a.timeline, b.timeline) &&
         sameCage(a.restCage, b.restCage) && a.cagePath == b.cagePath;
}

}  // namespace somicage::editor
