#include "interaction/element_pick.h"

#include <algorithm>
#include <limits>
#include <set>
#include <utility>

namespace somicage::editor {

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

bool insideTriangle(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                    const Eigen::Vector2d& c) {
  const double d1 = cross(b - a, p - a), d2 = cross(c - b, p - b), d3 = cross(a - c, p - c);
  return (d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0);
}

std::vector<int> pickEdge(const std::vector<ScreenPoint>& pts, const Eigen::MatrixXi& faces,
                          const Eigen::Vector2d& mouse, double radius) {
  double best = radius;
  std::vector<int> hit;
  for (const auto& [a, b] : cageEdges(faces)) {
    const ScreenPoint &pa = pts[static_cast<std::size_t>(a)], &pb = pts[static_cast<std::size_t>(b)];
    if (!pa.visible || !pb.visible) continue;
    const double d = segmentDistance(mouse, pa.position, pb.position);
    if (d <= best) {
      best = d;
      hit = {a, b};
    }
  }
  return hit;
}

}  // namespace

const char* elementModeName(ElementMode mode) {
  switch (mode) {
    case ElementMode::Vertex:
      return "vertices";
    case ElementMode::Edge:
      return "edges";
    case ElementMode::Face:
      return "faces";
  }
  return "?";
}

std::vector<std::pair<int, int>> cageEdges(const Eigen::MatrixXi& faces) {
  std::set<std::pair<int, int>> edges;
  const Eigen::Index n = faces.cols();
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    for (Eigen::Index k = 0; k < (n == 2 ? 1 : n); ++k) {
      const int a = faces(f, k), b = faces(f, (k + 1) % n);
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return {edges.begin(), edges.end()};
}

std::vector<std::pair<int, int>> selectedEdges(const Eigen::MatrixXi& faces, const std::vector<bool>& selected) {
  const auto isSelected = [&](int v) { return v >= 0 && static_cast<std::size_t>(v) < selected.size() && selected[v]; };
  std::vector<std::pair<int, int>> edges;
  for (const auto& e : cageEdges(faces))
    if (isSelected(e.first) && isSelected(e.second)) edges.push_back(e);
  return edges;
}

std::vector<int> pickElement(ElementMode mode, const std::vector<ScreenPoint>& pts, const Eigen::MatrixXi& faces,
                             const Eigen::Vector2d& mouse, double radius) {
  if (mode == ElementMode::Vertex) {
    const int v = pickPoint(pts, mouse, radius);
    return v < 0 ? std::vector<int>{} : std::vector<int>{v};
  }
  if (mode == ElementMode::Edge || faces.cols() == 2) return pickEdge(pts, faces, mouse, radius);
  double nearest = std::numeric_limits<double>::infinity();
  std::vector<int> hit;
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    const ScreenPoint &a = pts[static_cast<std::size_t>(faces(f, 0))], &b = pts[static_cast<std::size_t>(faces(f, 1))],
                      &c = pts[static_cast<std::size_t>(faces(f, 2))];
    if (!a.visible || !b.visible || !c.visible || !insideTriangle(mouse, a.position, b.position, c.position)) continue;
    const double depth = (a.depth + b.depth + c.depth) / 3.0;
    if (depth < nearest) {
      nearest = depth;
      hit = {faces(f, 0), faces(f, 1), faces(f, 2)};
    }
  }
  return hit;
}

}  // namespace somicage::editor
