#include "cage/cage_repair.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

namespace somicage {

namespace {

constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------------------------------------------
// Face adjacency: two faces are neighbours across a ridge (3D: an edge, 2D: a vertex) that only they contain
// ---------------------------------------------------------------------------------------------------------------

struct Neighbour {
  int face;
  bool sameDirection;  // both faces run through the ridge the same way: one of them must be reversed
};

// False when some ridge does not have exactly two faces, or a face repeats a vertex (no repair then).
bool faceNeighbours(const Cage& cage, std::vector<std::vector<Neighbour>>& neighbours) {
  struct Incidence {
    int a, b, face, direction;  // ridge key (sorted edge, or (vertex, -1)); +1 when the face runs a -> b / starts at a
  };
  std::vector<Incidence> incidences;
  for (int j = 0; j < cage.numFaces(); ++j) {
    for (int k = 0; k < cage.dim(); ++k) {
      const int u = cage.faces(j, k), v = cage.faces(j, (k + 1) % cage.dim());
      if (u == v) return false;
      if (cage.dim() == 3) {
        incidences.push_back({std::min(u, v), std::max(u, v), j, u < v ? 1 : -1});
      } else {
        incidences.push_back({u, -1, j, k == 0 ? 1 : -1});
      }
    }
  }
  std::sort(incidences.begin(), incidences.end(), [](const Incidence& x, const Incidence& y) {
    return std::tie(x.a, x.b, x.face) < std::tie(y.a, y.b, y.face);
  });
  neighbours.assign(cage.numFaces(), {});
  for (size_t start = 0; start < incidences.size(); start += 2) {
    const Incidence &x = incidences[start], &y = incidences[start + 1 < incidences.size() ? start + 1 : start];
    const bool pair = start + 1 < incidences.size() && x.a == y.a && x.b == y.b;
    const bool third =
        start + 2 < incidences.size() && incidences[start + 2].a == x.a && incidences[start + 2].b == x.b;
    if (!pair || third) return false;  // a boundary or non-manifold ridge
    const bool same = x.direction == y.direction;
    neighbours[x.face].push_back({y.face, same});
    neighbours[y.face].push_back({x.face, same});
  }
  return true;
}

// ---------------------------------------------------------------------------------------------------------------
// Geometry of one component: signed volume (area) and the winding number of a point
// ---------------------------------------------------------------------------------------------------------------

double signedMeasure(const Cage& cage, const std::vector<int>& faces, const Eigen::RowVectorXd& origin) {
  double sum = 0.0;
  for (const int j : faces) sum += signedFaceMeasure(cage, j, origin);
  return sum;
}

// Signed solid angles (Van Oosterom & Strackee) over 4 pi, or signed angles over 2 pi: +-1 inside, 0 outside.
double windingNumber(const Cage& cage, const std::vector<int>& faces, const Eigen::RowVectorXd& p) {
  double sum = 0.0;
  for (const int j : faces) {
    if (cage.dim() == 3) {
      const Eigen::Vector3d a = cage.vertices.row(cage.faces(j, 0)) - p;
      const Eigen::Vector3d b = cage.vertices.row(cage.faces(j, 1)) - p;
      const Eigen::Vector3d c = cage.vertices.row(cage.faces(j, 2)) - p;
      const double la = a.norm(), lb = b.norm(), lc = c.norm();
      sum += 2.0 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
    } else {
      const Eigen::Vector2d a = cage.vertices.row(cage.faces(j, 0)) - p;
      const Eigen::Vector2d b = cage.vertices.row(cage.faces(j, 1)) - p;
      sum += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
  }
  return sum / (cage.dim() == 3 ? 4.0 * kPi : 2.0 * kPi);
}

Eigen::AlignedBox<double, Eigen::Dynamic> bounds(const Cage& cage, const std::vector<int>& faces) {
  Eigen::AlignedBox<double, Eigen::Dynamic> box(cage.dim());
  for (const int j : faces) {
    for (int k = 0; k < cage.dim(); ++k) box.extend(cage.vertices.row(cage.faces(j, k)).transpose());
  }
  return box;
}

// Every corner of `inner` is inside `outer` (winding number +-1). Components that cross each other are not nested,
// whatever their overlap: each then needs outward normals of its own.
bool nestedIn(const Cage& cage, const std::vector<int>& inner, const std::vector<int>& outer) {
  if (!bounds(cage, outer).contains(bounds(cage, inner))) return false;
  for (const int j : inner) {
    for (int k = 0; k < cage.dim(); ++k) {
      if (std::abs(windingNumber(cage, outer, cage.vertices.row(cage.faces(j, k)))) < 0.5) return false;
    }
  }
  return true;
}

void reverseFace(Cage& cage, int j) { cage.faces.row(j) = cage.faces.row(j).reverse().eval(); }

// ---------------------------------------------------------------------------------------------------------------
// Messages
// ---------------------------------------------------------------------------------------------------------------

constexpr size_t kListedFaces = 5;

// "12, 40, 41" or "0, 1, 2, 3, 4 and 7 more".
std::string someFaces(const std::vector<int>& faces) {
  std::string text;
  for (size_t k = 0; k < faces.size() && k < kListedFaces; ++k) text += (k ? ", " : "") + std::to_string(faces[k]);
  if (faces.size() > kListedFaces) text += " and " + std::to_string(faces.size() - kListedFaces) + " more";
  return text;
}

std::string count(size_t n, const std::string& singular, const std::string& plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace

CageRepair repairCage(const Cage& cage) {
  CageRepair repair{cage, {}};
  const int n = cage.numFaces();
  if (n == 0 || (cage.dim() != 2 && cage.dim() != 3) || cage.faces.cols() != cage.dim()) return repair;
  if ((cage.faces.array() < 0).any() || (cage.faces.array() >= cage.numVertices()).any()) return repair;
  std::vector<std::vector<Neighbour>> neighbours;
  if (!faceNeighbours(cage, neighbours)) return repair;
  const bool is3d = cage.dim() == 3;
  const std::string face = is3d ? "face" : "edge", faces = is3d ? "faces" : "edges";

  // ---- Consistent orientation: breadth-first over the ridges, the majority of each component wins ----
  std::vector<int> flip(n, -1);  // 1: reverse this face
  std::vector<std::vector<int>> components;
  for (int seed = 0; seed < n; ++seed) {
    if (flip[seed] >= 0) continue;
    std::vector<int> component{seed};
    flip[seed] = 0;
    for (size_t next = 0; next < component.size(); ++next) {
      const int f = component[next];
      for (const Neighbour& g : neighbours[f]) {
        const int wanted = flip[f] ^ static_cast<int>(g.sameDirection);
        if (flip[g.face] < 0) {
          flip[g.face] = wanted;
          component.push_back(g.face);
        } else if (flip[g.face] != wanted) {
          return repair;  // not orientable: validation reports the misoriented ridges
        }
      }
    }
    size_t ones = 0;
    for (const int f : component) ones += flip[f];
    if (2 * ones > component.size()) {
      for (const int f : component) flip[f] ^= 1;
    }
    std::sort(component.begin(), component.end());
    components.push_back(std::move(component));
  }
  std::vector<int> matched;
  for (int j = 0; j < n; ++j) {
    if (flip[j] == 1) reverseFace(repair.cage, j), matched.push_back(j);
  }
  if (!matched.empty()) {
    repair.fixes.push_back((is3d ? "flipped " : "reversed ") + count(matched.size(), face, faces) + " (" +
                           someFaces(matched) + ") to match " + (matched.size() == 1 ? "its" : "their") +
                           " neighbours' orientation");
  }

  // ---- Outward normals: a component nested inside an odd number of others bounds a cavity ----
  const Eigen::RowVectorXd origin = cage.vertices.colwise().mean();  // relative coordinates: less cancellation
  for (size_t c = 0; c < components.size(); ++c) {
    const std::vector<int>& component = components[c];
    const double measure = signedMeasure(repair.cage, component, origin);
    int depth = 0;
    for (size_t d = 0; d < components.size() && components.size() > 1; ++d) {
      if (d != c && nestedIn(repair.cage, component, components[d])) ++depth;
    }
    const bool cavity = depth % 2 == 1;
    if (measure == 0.0 || (measure > 0.0) != cavity) continue;
    for (const int j : component) reverseFace(repair.cage, j);
    const std::string what = (is3d ? "signed volume " : "signed area ") + formatNumber(measure);
    if (components.size() == 1) {
      repair.fixes.push_back(is3d ? "the cage's normals pointed inward (" + what + "): flipped all " +
                                        count(component.size(), face, faces)
                                  : "the polygon was clockwise (" + what + "): reversed it (all " +
                                        count(component.size(), face, faces) + ")");
    } else {
      const std::string wrong =
          is3d ? (cavity ? "pointed into the solid around it (it bounds a cavity)" : "pointed inward")
               : (cavity ? "was counter-clockwise (it bounds a hole)" : "was clockwise");
      repair.fixes.push_back("the closed part of the cage made of " + faces + " " + someFaces(component) + " (" + what +
                             ") " + wrong + ": " + (is3d ? "flipped its " : "reversed its ") +
                             count(component.size(), face, faces));
    }
  }
  return repair;
}

}  // namespace somicage
