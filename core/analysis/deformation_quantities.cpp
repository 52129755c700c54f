#include "analysis/deformation_quantities.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "base/errors.h"
#include "geometry/cage.h"

namespace somicage {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Calls triangle(a, b, c) for the fan of every face from its first corner.
template <typename Triangle>
void forEachFanTriangle(const std::vector<int>& face, Triangle triangle) {
  for (std::size_t k = 1; k + 1 < face.size(); ++k) triangle(face[0], face[k], face[k + 1]);
}

// Area of a polygon (fan from its first corner): signed in 2D, |sum of the triangles' vector areas| in 3D.
double faceArea(const std::vector<int>& face, const Eigen::MatrixXd& V) {
  if (V.cols() == 2) {
    double area = 0;
    forEachFanTriangle(face, [&](int a, int b, int c) {
      area += signedTriangleArea(V.row(a).transpose(), V.row(b).transpose(), V.row(c).transpose());
    });
    return area;
  }
  Eigen::Vector3d twice = Eigen::Vector3d::Zero();
  forEachFanTriangle(face, [&](int a, int b, int c) {
    const Eigen::Vector3d u = V.row(b) - V.row(a), w = V.row(c) - V.row(a);
    twice += u.cross(w);
  });
  return 0.5 * twice.norm();
}

}  // namespace

namespace {

template <int Dim>
void fillPointQuantities(const Eigen::MatrixXd& jacobians, PointQuantities& q) {
  const int numPoints = static_cast<int>(jacobians.rows());
  int foldovers = 0, undefined = 0;
#pragma omp parallel for schedule(static, 1024) reduction(+ : foldovers, undefined)
  for (int p = 0; p < numPoints; ++p) {
    if (!jacobians.row(p).allFinite()) {
      q.detJ(p) = q.distortion(p) = kNaN;
      undefined += 1;
      continue;
    }
    Eigen::Matrix<double, Dim, Dim> J;
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) J(a, b) = jacobians(p, a * Dim + b);
    q.detJ(p) = J.determinant();
    // sigma_max / sigma_min from the eigenvalues of J^T J (ascending), in closed form: cheap enough for every frame.
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, Dim, Dim>> eigen;
    eigen.computeDirect(J.transpose() * J, Eigen::EigenvaluesOnly);
    const double low = eigen.eigenvalues()(0), high = eigen.eigenvalues()(Dim - 1);
    q.distortion(p) = low > 0 ? std::sqrt(high / low) : std::numeric_limits<double>::infinity();
    foldovers += q.detJ(p) <= 0;
  }
  q.foldovers = foldovers;
  q.undefined = undefined;
}

}  // namespace

PointQuantities pointQuantities(const Eigen::MatrixXd& jacobians, int dim) {
  SOMICAGE_ASSERT(jacobians.cols() == dim * dim, "J rows of d*d entries");
  PointQuantities q;
  q.detJ.resize(jacobians.rows());
  q.distortion.resize(jacobians.rows());
  if (dim == 3)
    fillPointQuantities<3>(jacobians, q);
  else
    fillPointQuantities<2>(jacobians, q);
  return q;
}

FaceQuantities faceQuantities(const std::vector<std::vector<int>>& faces, const Eigen::MatrixXd& rest,
                              const Eigen::MatrixXd& deformed) {
  FaceQuantities q;
  const int numFaces = static_cast<int>(faces.size());
  q.areaRatio.resize(numFaces);
  q.edgeStretch.resize(numFaces);
  for (int f = 0; f < numFaces; ++f) {
    const std::vector<int>& face = faces[static_cast<std::size_t>(f)];
    const double restArea = faceArea(face, rest);
    q.areaRatio(f) = restArea != 0 ? faceArea(face, deformed) / restArea : kNaN;
    double stretch = 0;
    for (std::size_t k = 0; k < face.size(); ++k) {
      const int a = face[k], b = face[(k + 1) % face.size()];
      const double restLength = (rest.row(b) - rest.row(a)).norm();
      stretch = restLength > 0 ? std::max(stretch, (deformed.row(b) - deformed.row(a)).norm() / restLength) : kNaN;
      if (std::isnan(stretch)) break;
    }
    q.edgeStretch(f) = stretch;
  }
  return q;
}

namespace {

// The directed edges (from, to) of the faces, sorted, each with its number of uses: sorted vectors rather than a map,
// since the editor measures every pose of a 76,000-face mesh with them.
using DirectedEdges = std::vector<std::pair<std::pair<int, int>, int>>;

DirectedEdges directedEdgeUses(const std::vector<std::vector<int>>& faces) {
  std::vector<std::pair<int, int>> edges;
  for (const std::vector<int>& face : faces)
    for (std::size_t k = 0; k < face.size(); ++k) edges.emplace_back(face[k], face[(k + 1) % face.size()]);
  std::sort(edges.begin(), edges.end());
  DirectedEdges directed;
  for (const auto& e : edges) {
    if (directed.empty() || directed.back().first != e)
      directed.push_back({e, 1});
    else
      ++directed.back().second;
  }
  return directed;
}

int usesOf(const DirectedEdges& directed, const std::pair<int, int>& edge) {
  auto it = std::lower_bound(directed.begin(), directed.end(), edge,
                             [](const auto& entry, const std::pair<int, int>& e) { return entry.first < e; });
  return it != directed.end() && it->first == edge ? it->second : 0;
}

bool isClosed(const DirectedEdges& directed) {
  if (directed.empty()) return false;
  for (const auto& [edge, uses] : directed)
    if (uses != 1 || usesOf(directed, {edge.second, edge.first}) != 1) return false;
  return true;
}

std::vector<int> boundaryOf(const DirectedEdges& directed) {
  std::vector<int> boundary;
  for (const auto& [edge, uses] : directed)
    if (usesOf(directed, {edge.second, edge.first}) == 0) boundary.push_back(edge.first);
  std::sort(boundary.begin(), boundary.end());
  boundary.erase(std::unique(boundary.begin(), boundary.end()), boundary.end());
  return boundary;
}

Eigen::RowVectorXd centroidOf(const std::vector<int>& vertices, const Eigen::MatrixXd& V) {
  Eigen::RowVectorXd c = Eigen::RowVectorXd::Zero(V.cols());
  for (int i : vertices) c += V.row(i);
  return c / static_cast<double>(std::max<std::size_t>(1, vertices.size()));
}

}  // namespace

bool isClosedMesh(const std::vector<std::vector<int>>& faces) { return isClosed(directedEdgeUses(faces)); }

std::vector<int> boundaryVertices(const std::vector<std::vector<int>>& faces) {
  return boundaryOf(directedEdgeUses(faces));
}

double signedMeshMeasure(const std::vector<std::vector<int>>& faces, const Eigen::MatrixXd& V,
                         const Eigen::RowVectorXd& origin) {
  if (V.cols() == 2) {
    double area = 0;
    for (const std::vector<int>& face : faces) area += faceArea(face, V);
    return area;
  }
  const Eigen::Vector3d o = origin.size() == 3 ? Eigen::Vector3d(origin.transpose()) : Eigen::Vector3d::Zero();
  double volume = 0;
  for (const std::vector<int>& face : faces)
    forEachFanTriangle(face, [&](int a, int b, int c) {
      volume += signedTetrahedronVolume(o, V.row(a).transpose(), V.row(b).transpose(), V.row(c).transpose());
    });
  return volume;
}

EnclosedMeasure enclosedMeasure(const std::vector<std::vector<int>>& faces, const Eigen::MatrixXd& rest,
                                const Eigen::MatrixXd& deformed) {
  EnclosedMeasure m;
  if (rest.cols() == 2) {
    m.closed = !faces.empty();
    m.rest = signedMeshMeasure(faces, rest, Eigen::RowVectorXd());
    m.deformed = signedMeshMeasure(faces, deformed, Eigen::RowVectorXd());
    return m;
  }
  // From a point near the mesh (little cancellation); for an open mesh the cone apex of the caps, whose own
  // triangles then contribute nothing.
  const DirectedEdges directed = directedEdgeUses(faces);
  const std::vector<int> boundary = boundaryOf(directed);
  m.closed = !faces.empty() && boundary.empty() && isClosed(directed);
  std::vector<int> all;
  if (boundary.empty())
    for (const std::vector<int>& face : faces) all.insert(all.end(), face.begin(), face.end());
  const std::vector<int>& apexVertices = boundary.empty() ? all : boundary;
  m.rest = signedMeshMeasure(faces, rest, centroidOf(apexVertices, rest));
  m.deformed = signedMeshMeasure(faces, deformed, centroidOf(apexVertices, deformed));
  return m;
}

double gradientJump(const Eigen::Ref<const Eigen::RowVectorXd>& a, const Eigen::Ref<const Eigen::RowVectorXd>& b) {
  const double scale = 0.5 * (a.norm() + b.norm());
  if (!a.allFinite() || !b.allFinite() || !(scale > 0)) return std::numeric_limits<double>::quiet_NaN();
  return (a - b).norm() / scale;
}

double quantile(const Eigen::VectorXd& values, double q) {
  std::vector<double> finite;
  finite.reserve(static_cast<std::size_t>(values.size()));
  for (Eigen::Index i = 0; i < values.size(); ++i)
    if (std::isfinite(values(i))) finite.push_back(values(i));
  if (finite.empty()) return kNaN;
  const double position = std::clamp(q, 0.0, 1.0) * static_cast<double>(finite.size() - 1);
  const std::size_t below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, finite.size() - 1);
  std::nth_element(finite.begin(), finite.begin() + static_cast<std::ptrdiff_t>(below), finite.end());
  const double low = finite[below];
  if (above == below) return low;
  const double high = *std::min_element(finite.begin() + static_cast<std::ptrdiff_t>(above), finite.end());
  return low + (position - static_cast<double>(below)) * (high - low);
}

Eigen::VectorXd pointDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double diameter) {
  SOMICAGE_ASSERT(a.rows() == b.rows() && a.cols() == b.cols(), "two deformations of the same points");
  return (a - b).rowwise().norm() / diameter;
}

}  // namespace somicage
