#include "geometry/volume_mesh.h"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

#include "base/errors.h"
#include "geometry/cage_proximity.h"

namespace somicage {

namespace {

// Vertex-to-cage and boundary-to-cage distances allowed, in cage diameters (docs/engine.md, "Phong").
constexpr double kOnCage = 1e-9;
// A simplex whose measure is at most this times its longest edge to the d is degenerate (no deformation gradient).
constexpr double kDegenerateSimplex = 1e-12;

std::string format(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

double factorial(int d) { return d == 3 ? 6.0 : 2.0; }

Eigen::MatrixXd edgeMatrix(const VolumeMesh& mesh, int s) {
  const int d = mesh.dim();
  Eigen::MatrixXd D(d, d);
  for (int k = 0; k < d; ++k)
    D.col(k) = (mesh.vertices.row(mesh.simplices(s, k + 1)) - mesh.vertices.row(mesh.simplices(s, 0))).transpose();
  return D;
}

double longestEdge(const VolumeMesh& mesh, int s) {
  double longest = 0;
  for (int a = 0; a <= mesh.dim(); ++a)
    for (int b = a + 1; b <= mesh.dim(); ++b)
      longest =
          std::max(longest, (mesh.vertices.row(mesh.simplices(s, a)) - mesh.vertices.row(mesh.simplices(s, b))).norm());
  return longest;
}

std::string simplexName(int dim) { return dim == 3 ? "tetrahedron" : "triangle"; }

}  // namespace

double signedSimplexMeasure(const VolumeMesh& mesh, int s) {
  const Eigen::MatrixXd D = edgeMatrix(mesh, s);
  return D.determinant() / factorial(mesh.dim());
}

Eigen::MatrixXi volumeMeshEdges(const VolumeMesh& mesh) {
  std::vector<std::array<int, 2>> edges;
  for (int s = 0; s < mesh.numSimplices(); ++s)
    for (int a = 0; a <= mesh.dim(); ++a)
      for (int b = a + 1; b <= mesh.dim(); ++b) {
        const int u = mesh.simplices(s, a), v = mesh.simplices(s, b);
        edges.push_back({std::min(u, v), std::max(u, v)});
      }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  Eigen::MatrixXi out(static_cast<Eigen::Index>(edges.size()), 2);
  for (std::size_t e = 0; e < edges.size(); ++e)
    out.row(static_cast<Eigen::Index>(e)) << edges[e][0], edges[e][1];
  return out;
}

std::vector<Eigen::MatrixXd> barycentricGradients(const VolumeMesh& mesh) {
  const int d = mesh.dim();
  std::vector<Eigen::MatrixXd> out(static_cast<std::size_t>(mesh.numSimplices()));
  for (int s = 0; s < mesh.numSimplices(); ++s) {
    Eigen::MatrixXd& g = out[static_cast<std::size_t>(s)];
    g.resize(d + 1, d);
    g.bottomRows(d) = edgeMatrix(mesh, s).inverse();
    g.row(0) = -g.bottomRows(d).colwise().sum();
  }
  return out;
}

std::vector<BoundaryFace> boundaryFaces(const VolumeMesh& mesh, int* overShared) {
  struct Use {
    BoundaryFace face;
    int count;
  };
  std::map<std::vector<int>, Use> faces;
  if (overShared) *overShared = -1;
  for (int s = 0; s < mesh.numSimplices(); ++s) {
    for (int k = 0; k <= mesh.dim(); ++k) {
      std::vector<int> key;
      for (int m = 0; m <= mesh.dim(); ++m)
        if (m != k) key.push_back(mesh.simplices(s, m));
      std::sort(key.begin(), key.end());
      Use& use = faces.try_emplace(key, Use{{s, k}, 0}).first->second;
      if (++use.count > 2 && overShared && *overShared < 0) *overShared = s;
    }
  }
  std::vector<BoundaryFace> out;
  for (const auto& entry : faces)
    if (entry.second.count == 1) out.push_back(entry.second.face);
  return out;
}

int checkVolumeMesh(VolumeMesh& mesh, const Cage& cage, const VolumeMeshSource& source) {
  const int d = cage.dim(), n = cage.numVertices();
  const double diameter = cageDiameter(cage.vertices);
  const auto vertexLine = [&](int v) {
    return v < static_cast<int>(source.vertexLines.size()) ? source.vertexLines[v] : -1L;
  };
  const auto simplexLine = [&](int s) {
    return s < static_cast<int>(source.simplexLines.size()) ? source.simplexLines[s] : -1L;
  };
  const std::string element = simplexName(d);
  if (mesh.dim() != d || mesh.simplices.cols() != d + 1)
    throw InputError(source.name, -1,
                     "the mesh is " + std::to_string(mesh.dim()) + "D but the cage is " + std::to_string(d) + "D",
                     "give a volume mesh of this cage");
  if (mesh.numVertices() < n)
    throw InputError(
        source.name, -1,
        "the mesh has " + std::to_string(mesh.numVertices()) + " vertices, fewer than the cage's " + std::to_string(n),
        "its first " + std::to_string(n) + " vertices must be the cage's, in the cage file's order");
  for (int i = 0; i < n; ++i) {
    const double distance = (mesh.vertices.row(i) - cage.vertices.row(i)).norm() / diameter;
    if (!(distance <= kOnCage))
      throw InputError(source.name, vertexLine(i),
                       "vertex " + std::to_string(i + 1) + " is " + format(distance) +
                           " cage diameters from cage vertex " + std::to_string(i + 1),
                       "the first " + std::to_string(n) +
                           " vertices must be the cage's vertices in the cage file's "
                           "order (to 1e-9 cage diameters)");
  }
  for (int s = 0; s < mesh.numSimplices(); ++s)
    for (int k = 0; k <= d; ++k)
      if (mesh.simplices(s, k) < 0 || mesh.simplices(s, k) >= mesh.numVertices())
        throw InputError(source.name, simplexLine(s),
                         element + " " + std::to_string(s + 1) + " uses a vertex that does not exist",
                         "indices are 1-based and at most the vertex count");
  int reoriented = 0;
  for (int s = 0; s < mesh.numSimplices(); ++s) {
    const double measure = signedSimplexMeasure(mesh, s);
    if (!(std::abs(measure) > kDegenerateSimplex * std::pow(longestEdge(mesh, s), d)))
      throw InputError(source.name, simplexLine(s), element + " " + std::to_string(s + 1) + " is degenerate (flat)",
                       "remove it, or mesh the cage again");
    if (measure < 0) {
      std::swap(mesh.simplices(s, 0), mesh.simplices(s, 1));
      ++reoriented;
    }
  }
  // The boundary: faces used by one simplex. Each must lie on the cage and face outward as the cage's face does;
  // together they must cover the cage (equal measure). Then the simplices, all positive, fill the cage exactly once.
  int overShared = -1;
  const std::vector<BoundaryFace> boundary = boundaryFaces(mesh, &overShared);
  if (overShared >= 0)
    throw InputError(source.name, simplexLine(overShared),
                     element + " " + std::to_string(overShared + 1) + " shares a face with two other " + element + "s",
                     "the mesh must not overlap itself");
  const CageProximity proximity(cage);
  double boundaryMeasure = 0;
  for (const BoundaryFace& use : boundary) {
    Eigen::MatrixXd corners(d, d);
    for (int m = 0, k = 0; m <= d; ++m)
      if (m != use.opposite) corners.row(k++) = mesh.vertices.row(mesh.simplices(use.simplex, m));
    Eigen::VectorXd normal(d);  // the face's normal, outward from its simplex, with the face's measure as length
    const Eigen::RowVectorXd e = corners.row(1) - corners.row(0);
    if (d == 3) {
      const Eigen::RowVectorXd f = corners.row(2) - corners.row(0);
      normal << e(1) * f(2) - e(2) * f(1), e(2) * f(0) - e(0) * f(2), e(0) * f(1) - e(1) * f(0);
      normal /= 2;
    } else {
      normal << e(1), -e(0);
    }
    const Eigen::RowVectorXd opposite = mesh.vertices.row(mesh.simplices(use.simplex, use.opposite));
    if (normal.dot((corners.row(0) - opposite).transpose()) < 0) normal = -normal;
    boundaryMeasure += normal.norm();
    const Eigen::VectorXd centroid = corners.colwise().mean().transpose();
    double distance = proximity.closest(centroid).distance;
    for (int m = 0; m < d; ++m) distance = std::max(distance, proximity.closest(corners.row(m).transpose()).distance);
    if (!(distance <= kOnCage * diameter))
      throw InputError(source.name, simplexLine(use.simplex),
                       element + " " + std::to_string(use.simplex + 1) + " has a boundary face " +
                           format(distance / diameter) +
                           " cage diameters off the cage: the mesh has a hole, or reaches "
                           "outside the cage",
                       "mesh the cage's interior with the cage's faces as its boundary (or give no mesh: somicage "
                       "tetrahedralizes the cage itself)");
    if (normal.dot(proximity.closest(centroid).normal) <= 0)
      throw InputError(
          source.name, simplexLine(use.simplex),
          element + " " + std::to_string(use.simplex + 1) + " lies outside the cage, against one of its faces",
          "mesh the cage's interior only");
  }
  const double cageMeasure = faceAreas(cage, cage.vertices).sum();
  if (!(std::abs(boundaryMeasure - cageMeasure) <= 1e-9 * cageMeasure))
    throw InputError(source.name, -1,
                     "the mesh's boundary covers " + format(boundaryMeasure / cageMeasure) +
                         " times the cage's surface: some of the cage is not meshed, or meshed twice",
                     "mesh the whole interior of the cage, once");
  return reoriented;
}

int parseTetLevel(const MethodOptions& options) {
  const auto it = options.find("tet-level");
  if (it == options.end()) return kDefaultTetLevel;
  const std::string& text = it->second;
  if (text.size() != 1 || text[0] < '0' || text[0] >= '0' + kTetLevels)
    throw InputError("--tet-level", -1, "'" + text + "' is not a tetrahedral mesh level",
                     "use a whole number from 0 (coarse) to " + std::to_string(kTetLevels - 1));
  return text[0] - '0';
}

std::unique_ptr<VolumeMesh> starVolumeMesh(const Cage& cage) {
  const int d = cage.dim(), n = cage.numVertices();
  const Eigen::RowVectorXd origin = cage.vertices.colwise().mean();
  Eigen::RowVectorXd centroid = Eigen::RowVectorXd::Zero(d);
  double total = 0;
  for (int j = 0; j < cage.numFaces(); ++j) {
    const double measure = signedFaceMeasure(cage, j, origin);
    Eigen::RowVectorXd sum = origin;
    for (int k = 0; k < d; ++k) sum += cage.vertices.row(cage.faces(j, k));
    centroid += measure * sum / (d + 1);
    total += measure;
  }
  if (!(total > 0)) return nullptr;
  centroid /= total;
  auto mesh = std::make_unique<VolumeMesh>();
  mesh->vertices.resize(n + 1, d);
  mesh->vertices << cage.vertices, centroid;
  mesh->simplices.resize(cage.numFaces(), d + 1);
  for (int j = 0; j < cage.numFaces(); ++j) {
    mesh->simplices(j, 0) = n;
    for (int k = 0; k < d; ++k) mesh->simplices(j, k + 1) = cage.faces(j, k);
    // Star-shaped from the centroid: every face sees it from inside, at more than a sliver's distance.
    if (!(signedSimplexMeasure(*mesh, j) > 1e-6 * std::pow(longestEdge(*mesh, j), d))) return nullptr;
  }
  return mesh;
}

}  // namespace somicage
