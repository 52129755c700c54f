#include "model/selection.h"

#include <algorithm>
#include <limits>

namespace somicage::editor {

namespace {
Eigen::Vector3d row3(const Eigen::MatrixXd& points, Eigen::Index i) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (Eigen::Index c = 0; c < std::min<Eigen::Index>(points.cols(), 3); ++c) p[c] = points(i, c);
  return p;
}
}  // namespace

std::vector<ScreenPoint> projectPoints(const OrbitCamera& camera, const Eigen::MatrixXd& points, double width,
                                       double height) {
  std::vector<ScreenPoint> out(static_cast<std::size_t>(points.rows()));
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    ScreenPoint& s = out[static_cast<std::size_t>(i)];
    s.visible = camera.project(row3(points, i), width, height, s.position, &s.depth);
  }
  return out;
}

int pickPoint(const std::vector<ScreenPoint>& points, const Eigen::Vector2d& mouse, double radius) {
  int best = -1;
  double bestDist = std::numeric_limits<double>::infinity(), bestDepth = bestDist;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ScreenPoint& p = points[i];
    if (!p.visible) continue;
    const double d = (p.position - mouse).norm();
    if (d > radius) continue;
    const bool clearlyCloser = d < bestDist - 1.0;
    const bool tieButNearer = std::abs(d - bestDist) <= 1.0 && p.depth < bestDepth;
    if (best < 0 || clearlyCloser || tieButNearer) {
      best = static_cast<int>(i);
      bestDist = d;
      bestDepth = p.depth;
    }
  }
  return best;
}

double segmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

std::vector<int> pointsInRect(const std::vector<ScreenPoint>& points, const Eigen::Vector2d& cornerA,
                              const Eigen::Vector2d& cornerB) {
  const Eigen::Vector2d lo = cornerA.cwiseMin(cornerB), hi = cornerA.cwiseMax(cornerB);
  std::vector<int> out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ScreenPoint& p = points[i];
    if (p.visible && (p.position.array() >= lo.array()).all() && (p.position.array() <= hi.array()).all()) {
      out.push_back(static_cast<int>(i));
    }
  }
  return out;
}

void Selection::resize(int count) { flags_.assign(static_cast<std::size_t>(std::max(count, 0)), false); }

int Selection::count() const { return static_cast<int>(std::count(flags_.begin(), flags_.end(), true)); }

std::vector<int> Selection::indices() const {
  std::vector<int> out;
  for (std::size_t i = 0; i < flags_.size(); ++i) {
    if (flags_[i]) out.push_back(static_cast<int>(i));
  }
  return out;
}

void Selection::clear() { std::fill(flags_.begin(), flags_.end(), false); }
void Selection::selectAll() { std::fill(flags_.begin(), flags_.end(), true); }

void Selection::click(int i, Mode mode) {
  const bool valid = i >= 0 && i < size();
  if (mode == Mode::Replace) {
    clear();
    if (valid) flags_[static_cast<std::size_t>(i)] = true;
  } else if (valid) {
    auto ref = flags_[static_cast<std::size_t>(i)];
    ref = mode == Mode::Toggle ? !ref : true;
  }
}

void Selection::apply(const std::vector<int>& indices, Mode mode) {
  if (mode == Mode::Replace) clear();
  for (int i : indices) {
    if (i < 0 || i >= size()) continue;
    auto ref = flags_[static_cast<std::size_t>(i)];
    ref = mode == Mode::Toggle ? !ref : true;
  }
}

void Selection::setIndices(const std::vector<int>& indices) { apply(indices, Mode::Replace); }

Eigen::VectorXd Selection::centroid(const Eigen::MatrixXd& positions) const {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(positions.cols());
  int n = 0;
  for (Eigen::Index i = 0; i < positions.rows() && i < size(); ++i) {
    if (flags_[static_cast<std::size_t>(i)]) {
      sum += positions.row(i).transpose();
      ++n;
    }
  }
  return n > 0 ? Eigen::VectorXd(sum / n) : sum;
}

}  // namespace somicage::editor
