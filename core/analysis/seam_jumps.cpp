#include "analysis/seam_jumps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "analysis/deformation_quantities.h"
#include "base/errors.h"
#include "geometry/simplex_locator.h"

namespace somicage {

namespace {

// Progress over [from, to] of the whole.
ProgressCallback spanProgress(const ProgressCallback& progress, double from, double to) {
  return [progress, from, to](double f) { return progress(from + (to - from) * f); };
}

// Per simplex s and vertex k, the simplex across the face opposite vertex k (-1: a boundary face).
Eigen::MatrixXi faceNeighbours(const VolumeMesh& mesh) {
  const int d = mesh.dim(), count = mesh.numSimplices();
  std::vector<std::tuple<std::array<int, 3>, int, int>> faces;  // sorted face vertices (a -1 in 2D), s, k
  faces.reserve(static_cast<std::size_t>(count) * static_cast<std::size_t>(d + 1));
  for (int s = 0; s < count; ++s)
    for (int k = 0; k <= d; ++k) {
      std::array<int, 3> key{-1, -1, -1};
      for (int j = 0, n = 0; j <= d; ++j)
        if (j != k) key[static_cast<std::size_t>(n++)] = mesh.simplices(s, j);
      std::sort(key.begin(), key.end());  // the -1 of a 2D face sorts first
      faces.emplace_back(key, s, k);
    }
  std::sort(faces.begin(), faces.end());
  Eigen::MatrixXi neighbours = Eigen::MatrixXi::Constant(count, d + 1, -1);
  for (std::size_t i = 0; i + 1 < faces.size(); ++i)
    if (std::get<0>(faces[i]) == std::get<0>(faces[i + 1])) {  // checkVolumeMesh: no face has three simplices
      neighbours(std::get<1>(faces[i]), std::get<2>(faces[i])) = std::get<1>(faces[i + 1]);
      neighbours(std::get<1>(faces[i + 1]), std::get<2>(faces[i + 1])) = std::get<1>(faces[i]);
    }
  return neighbours;
}

// The undirected edges of the faces (a polygon's boundary; a 2-vertex face is one edge), first < second, once each.
std::vector<std::array<int, 2>> meshEdges(const std::vector<std::vector<int>>& faces) {
  std::vector<std::array<int, 2>> edges;
  for (const std::vector<int>& f : faces) {
    const std::size_t n = f.size();
    for (std::size_t k = 0; k < (n == 2 ? 1 : n); ++k) {
      const int a = f[k], b = f[(k + 1) % n];
      if (a != b) edges.push_back({std::min(a, b), std::max(a, b)});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

}  // namespace

SeamCrossings findSeamCrossings(const VolumeMesh& mesh, const std::vector<std::vector<int>>& faces,
                                const Eigen::MatrixXd& restPoints) {
  const SimplexLocator locator(mesh);
  const Eigen::MatrixXi neighbours = faceNeighbours(mesh);
  const int d = mesh.dim();
  SeamCrossings out;
  std::vector<int>& holder = out.holders;
  holder.resize(static_cast<std::size_t>(restPoints.rows()));
  for (Eigen::Index p = 0; p < restPoints.rows(); ++p)
    holder[static_cast<std::size_t>(p)] = locator.locate(restPoints.row(p).transpose()).simplex;
  std::vector<Eigen::VectorXd> points;
  for (const std::array<int, 2>& e : meshEdges(faces)) {
    int s = holder[static_cast<std::size_t>(e[0])];
    const int last = holder[static_cast<std::size_t>(e[1])];
    if (s < 0 || last < 0 || s == last) continue;
    const Eigen::VectorXd A = restPoints.row(e[0]).transpose(), B = restPoints.row(e[1]).transpose();
    bool crossed = false;
    double t = 0;  // along the edge, A + t (B - A)
    // At most one step per simplex: a walk longer than that is going round (round-off at an edge or a corner).
    for (int step = 0; step < mesh.numSimplices() && s != last; ++step) {
      const Eigen::VectorXd la = locator.barycentric(s, A), lb = locator.barycentric(s, B);
      if (lb.minCoeff() >= -SimplexLocator::kTolerance) break;  // B is in s too (on its face with `last`)
      // The face the edge leaves s by: the first coordinate to fall to 0 beyond t.
      int leave = -1;
      double exit = std::numeric_limits<double>::infinity();
      for (int k = 0; k <= d; ++k) {
        const double rate = lb(k) - la(k);
        if (!(rate < 0)) continue;
        const double at = std::max(t, -la(k) / rate);
        if (at < exit) exit = at, leave = k;
      }
      const int next = leave < 0 ? -1 : neighbours(s, leave);
      if (next < 0) break;  // the edge leaves the mesh (and the cage) here
      if (!crossed) out.edges.push_back(e), crossed = true;
      points.push_back(A + exit * (B - A));
      out.edge.push_back(static_cast<int>(out.edges.size()) - 1);
      out.sides.push_back({s, next});
      s = next, t = exit;
    }
  }
  out.points.resize(static_cast<Eigen::Index>(points.size()), d);
  for (std::size_t k = 0; k < points.size(); ++k) out.points.row(static_cast<Eigen::Index>(k)) = points[k].transpose();
  return out;
}

SeamJumpEvaluator::SeamJumpEvaluator(Method method, const Cage& restCage, std::shared_ptr<const VolumeMesh> mesh,
                                     SeamCrossings crossings, PrecomputeOptions options,
                                     const ProgressCallback& progress)
    : mesh_(std::move(mesh)), crossings_(std::move(crossings)) {
  const Eigen::Index K = crossings_.points.rows();
  if (K == 0) {
    progress(1.0);
    return;
  }
  // Each crossing twice, seen from the simplex before the face and from the one after it.
  Eigen::MatrixXd sided(2 * K, crossings_.points.cols());
  sided << crossings_.points, crossings_.points;
  options.pointSimplices.resize(static_cast<std::size_t>(2 * K));
  for (Eigen::Index k = 0; k < K; ++k)
    for (int side = 0; side < 2; ++side)
      options.pointSimplices[static_cast<std::size_t>(side * K + k)] =
          crossings_.sides[static_cast<std::size_t>(k)][static_cast<std::size_t>(side)];
  options.volumeMesh = mesh_;
  deformer_ = makeDeformer(method, restCage, sided, options, spanProgress(progress, 0.0, 0.3));
  gradients_ = std::make_unique<DeformationGradients>(*deformer_, sided, spanProgress(progress, 0.3, 1.0));
}

std::size_t SeamJumpEvaluator::bytes() const {
  return (deformer_ ? deformer_->frameCoordinates().bytes() : 0) + (gradients_ ? gradients_->bytes() : 0);
}

SeamJumps SeamJumpEvaluator::evaluate(const Eigen::MatrixXd& posedVertices, const DeformParams& params) const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  SeamJumps out;
  out.edges = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(crossings_.edges.size()));
  out.vertices.resize(static_cast<Eigen::Index>(crossings_.holders.size()));
  for (std::size_t p = 0; p < crossings_.holders.size(); ++p)
    out.vertices(static_cast<Eigen::Index>(p)) = crossings_.holders[p] >= 0 ? 0.0 : nan;
  if (!gradients_) return out;
  Eigen::MatrixXd positions, J;
  gradients_->evaluate(posedVertices, params, positions, J);
  const Eigen::Index K = crossings_.points.rows();
  for (Eigen::Index k = 0; k < K; ++k) {
    double& edge = out.edges(crossings_.edge[static_cast<std::size_t>(k)]);
    const double jump = gradientJump(J.row(k), J.row(K + k));
    edge = std::isnan(jump) || std::isnan(edge) ? nan : std::max(edge, jump);
  }
  for (std::size_t e = 0; e < crossings_.edges.size(); ++e)
    for (const int v : crossings_.edges[e]) {
      double& vertex = out.vertices(v);
      const double jump = out.edges(static_cast<Eigen::Index>(e));
      if (!std::isnan(jump)) vertex = std::max(vertex, jump);
    }
  return out;
}

}  // namespace somicage
