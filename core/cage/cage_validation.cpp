#include "cage/cage_validation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

#include "base/errors.h"

namespace somicage {

namespace {

// ---------------------------------------------------------------------------------------------------------------
// Ridges: sort the (face, ridge) incidences by ridge and look at each group
// ---------------------------------------------------------------------------------------------------------------

struct Incidence {
  int a, b;  // the ridge key: sorted edge (3D) or (vertex, -1) (2D)
  int face;
  int direction;  // 3D: +1 when the face runs a -> b; 2D: +1 when the edge starts at the vertex
};

void classifyRidges(const Cage& cage, CageReport& report) {
  std::vector<Incidence> incidences;
  incidences.reserve(static_cast<size_t>(cage.numFaces()) * cage.dim());
  for (int j = 0; j < cage.numFaces(); ++j) {
    if (cage.dim() == 3) {
      for (int k = 0; k < 3; ++k) {
        const int u = cage.faces(j, k), v = cage.faces(j, (k + 1) % 3);
        if (u != v) incidences.push_back({std::min(u, v), std::max(u, v), j, u < v ? 1 : -1});
      }
    } else if (cage.faces(j, 0) != cage.faces(j, 1)) {
      incidences.push_back({cage.faces(j, 0), -1, j, 1});
      incidences.push_back({cage.faces(j, 1), -1, j, -1});
    }
  }
  std::sort(incidences.begin(), incidences.end(), [](const Incidence& x, const Incidence& y) {
    return std::tie(x.a, x.b, x.face) < std::tie(y.a, y.b, y.face);
  });
  for (size_t start = 0; start < incidences.size();) {
    size_t end = start;
    CageReport::Ridge ridge{incidences[start].a, incidences[start].b, {}};
    while (end < incidences.size() && incidences[end].a == ridge.a && incidences[end].b == ridge.b) {
      ridge.faces.push_back(incidences[end].face);
      ++end;
    }
    const size_t count = end - start;
    if (count == 1) {
      report.boundaryRidges.push_back(std::move(ridge));
    } else if (count > 2) {
      report.nonManifoldRidges.push_back(std::move(ridge));
    } else if (incidences[start].direction == incidences[start + 1].direction) {
      report.misorientedRidges.push_back(std::move(ridge));
    }
    start = end;
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Connectivity and unused vertices
// ---------------------------------------------------------------------------------------------------------------

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

void countComponents(const Cage& cage, CageReport& report) {
  std::vector<int> parent(cage.numVertices());
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> used(cage.numVertices(), 0);
  for (int j = 0; j < cage.numFaces(); ++j) {
    const int first = findRoot(parent, cage.faces(j, 0));
    used[cage.faces(j, 0)] = 1;
    for (int k = 1; k < cage.faces.cols(); ++k) {
      used[cage.faces(j, k)] = 1;
      parent[findRoot(parent, cage.faces(j, k))] = first;
    }
  }
  report.components = 0;
  for (int i = 0; i < cage.numVertices(); ++i) {
    if (!used[i])
      report.unreferencedVertices.push_back(i);
    else if (findRoot(parent, i) == i)
      ++report.components;
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Geometry: volume, degenerate faces, duplicate vertices
// ---------------------------------------------------------------------------------------------------------------

void measureGeometry(const Cage& cage, CageReport& report) {
  const Eigen::MatrixXd& V = cage.vertices;
  const Eigen::RowVectorXd centre = V.colwise().mean();  // relative coordinates: less cancellation in the sum
  const double diameter = report.diameter;
  const double minMeasure = cage.dim() == 3 ? CageReport::kDegenerateTolerance * diameter * diameter
                                            : CageReport::kDegenerateTolerance * diameter;
  const Eigen::VectorXd areas = faceAreas(cage, V);  // lengths in 2D
  double volume = 0.0;
  for (int j = 0; j < cage.numFaces(); ++j) {
    bool repeated = false;
    for (int k = 0; k < cage.faces.cols(); ++k) {
      for (int l = k + 1; l < cage.faces.cols(); ++l) repeated = repeated || cage.faces(j, k) == cage.faces(j, l);
    }
    volume += signedFaceMeasure(cage, j, centre);
    if (repeated || !(areas(j) > minMeasure) || isDegenerateFace(cage, j)) report.degenerateFaces.push_back(j);
  }
  report.signedVolume = volume;

  // Duplicates: bucket the vertices in a grid of cells as wide as the tolerance; a pair closer than the tolerance
  // lies in the same or in neighbouring cells. O(V log V), whatever the layout (axis-aligned slices included).
  const double tolerance = CageReport::kDuplicateTolerance * diameter;
  const double cell = tolerance > 0.0 ? tolerance : 1.0;  // diameter 0: every vertex is in one cell
  using Key = std::array<long long, 3>;
  std::map<Key, std::vector<int>> grid;
  // Cells counted from the lowest corner: at most diameter / cell = 1 / kDuplicateTolerance of them per axis, so
  // the cast is in range however far from the origin the cage is (NaN only when the extent overflows: one cell).
  const Eigen::RowVectorXd lowest =
      V.rows() > 0 ? Eigen::RowVectorXd(V.colwise().minCoeff()) : Eigen::RowVectorXd::Zero(V.cols());
  const auto keyOf = [&](int i) {
    Key key{0, 0, 0};
    for (int k = 0; k < cage.dim(); ++k) {
      const double index = std::floor((V(i, k) - lowest(k)) / cell);
      key[k] = index < 1e15 ? static_cast<long long>(index) : 0;
    }
    return key;
  };
  for (int i = 0; i < cage.numVertices(); ++i) {
    const Key key = keyOf(i);
    const int reach = cage.dim() == 3 ? 1 : 0;
    for (long long dx = -1; dx <= 1; ++dx) {
      for (long long dy = -1; dy <= 1; ++dy) {
        for (long long dz = -reach; dz <= reach; ++dz) {
          const auto found = grid.find({key[0] + dx, key[1] + dy, key[2] + dz});
          if (found == grid.end()) continue;
          for (const int j : found->second) {
            if ((V.row(i) - V.row(j)).norm() <= tolerance) report.duplicateVertices.push_back({j, i});
          }
        }
      }
    }
    grid[key].push_back(i);
  }
  std::sort(report.duplicateVertices.begin(), report.duplicateVertices.end());
}

// ---------------------------------------------------------------------------------------------------------------
// 2D: is the polygon simple? Edge pairs whose bounding boxes overlap, with orientation tests
// ---------------------------------------------------------------------------------------------------------------

struct Segment {
  Eigen::Vector2d p, q;  // p before q in (x, y) order
  int u, v;              // the vertex indices of the edge
};

bool lexLess(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

double orient(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

bool onSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {  // c on ab, collinear
  return std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= c.y() &&
         c.y() <= std::max(a.y(), b.y());
}

bool segmentsMeet(const Segment& s, const Segment& t) {
  const double d1 = orient(s.p, s.q, t.p), d2 = orient(s.p, s.q, t.q);
  const double d3 = orient(t.p, t.q, s.p), d4 = orient(t.p, t.q, s.q);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return (d1 == 0 && onSegment(s.p, s.q, t.p)) || (d2 == 0 && onSegment(s.p, s.q, t.q)) ||
         (d3 == 0 && onSegment(t.p, t.q, s.p)) || (d4 == 0 && onSegment(t.p, t.q, s.q));
}

// Edges that share a vertex may only meet there; they overlap (fold back) when collinear and on the same side.
bool illegalMeeting(const Segment& s, const Segment& t) {
  int shared = -1, sOther = -1, tOther = -1;
  if (s.u == t.u || s.u == t.v) shared = s.u, sOther = s.v, tOther = (t.u == s.u ? t.v : t.u);
  if (s.v == t.u || s.v == t.v) {
    if (shared >= 0) return false;  // both ends shared (a 2-gon): reported as degenerate elsewhere
    shared = s.v, sOther = s.u, tOther = (t.u == s.v ? t.v : t.u);
  }
  if (shared < 0) return segmentsMeet(s, t);
  // Positions of the shared vertex and the two far ends.
  const auto position = [](const Segment& seg, int vertex) { return seg.u == vertex ? seg.p : seg.q; };
  const Eigen::Vector2d o = position(s, shared), a = position(s, sOther), b = position(t, tOther);
  return orient(o, a, b) == 0.0 && (a - o).dot(b - o) > 0.0;
}

// Visits each pair of faces whose bounding boxes overlap, sweeping their boxes along the cage's longest axis, until
// visit(i, j) returns true. No ordered container of segments: its comparator would have to stay a strict weak order
// on self-intersecting input, which rounded orientation tests cannot promise (a Shamos-Hoey sweep corrupted its
// std::set on polygons with coincident vertices).
template <int Dim, typename Visit>
void visitOverlappingFaces(const Cage& cage, const std::vector<char>& skip, Visit visit) {
  using Box = Eigen::AlignedBox<double, Dim>;
  const Eigen::MatrixXd& V = cage.vertices;
  std::vector<Box> boxes(cage.numFaces());
  for (int j = 0; j < cage.numFaces(); ++j) {
    for (int k = 0; k < Dim; ++k) boxes[j].extend(V.row(cage.faces(j, k)).transpose());
  }
  if (cage.numFaces() == 0) return;  // also no vertices maybe: no extent to sort along
  int axis = 0;
  (V.colwise().maxCoeff() - V.colwise().minCoeff()).maxCoeff(&axis);
  std::vector<int> order;
  for (int j = 0; j < cage.numFaces(); ++j)
    if (!skip[j]) order.push_back(j);
  std::sort(order.begin(), order.end(), [&](int x, int y) {
    return std::make_pair(boxes[x].min()[axis], x) < std::make_pair(boxes[y].min()[axis], y);
  });
  std::vector<int> active;  // faces whose box may still overlap the next one along the axis
  for (const int j : order) {
    const double start = boxes[j].min()[axis];
    active.erase(std::remove_if(active.begin(), active.end(), [&](int i) { return boxes[i].max()[axis] < start; }),
                 active.end());
    for (const int i : active) {
      if (boxes[i].intersects(boxes[j]) && visit(std::min(i, j), std::max(i, j))) return;
    }
    active.push_back(j);
  }
}

// 2D: the polygon is simple when no two edges meet except at shared ends; one offending pair is enough to say so.
void findIntersection(const Cage& cage, CageReport& report) {
  const int n = cage.numFaces();
  std::vector<Segment> segments(n);
  for (int j = 0; j < n; ++j) {
    Segment& s = segments[j];
    s.u = cage.faces(j, 0), s.v = cage.faces(j, 1);
    s.p = cage.vertices.row(s.u).transpose(), s.q = cage.vertices.row(s.v).transpose();
    if (lexLess(s.q, s.p)) std::swap(s.p, s.q), std::swap(s.u, s.v);
  }
  visitOverlappingFaces<2>(cage, std::vector<char>(n, 0), [&](int i, int j) {
    if (!illegalMeeting(segments[i], segments[j])) return false;
    report.intersectingFaces.push_back({i, j});
    return true;
  });
}

// ---------------------------------------------------------------------------------------------------------------
// 3D: faces that meet other than at what they share. Bounding boxes swept along the longest axis, then orientation
// tests: two triangles meet iff an edge of one meets the other (closed sets, coplanar included).
// ---------------------------------------------------------------------------------------------------------------

using Point3 = Eigen::Vector3d;

// The side of plane abc that d lies on: 0 within a relative 1e-12 of the plane, where the rounding of the
// determinant could give either sign (an edge lying in a face's plane would otherwise seem to cross it).
int orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const Point3 u = b - a, v = c - a, w = d - a;
  const double volume = u.dot(v.cross(w)), scale = u.norm() * v.norm() * w.norm();
  return std::abs(volume) <= 1e-12 * scale ? 0 : (volume > 0.0) - (volume < 0.0);
}

// Segment pq against the closed triangle abc lying in the same plane: 2D tests in the plane of the larger normal
// components.
bool coplanarSegmentMeetsTriangle(const Point3& p, const Point3& q, const Point3 (&t)[3]) {
  const Point3 normal = (t[1] - t[0]).cross(t[2] - t[0]).cwiseAbs();
  int drop = 0;
  normal.maxCoeff(&drop);
  const auto flat = [drop](const Point3& x) { return Eigen::Vector2d(x[(drop + 1) % 3], x[(drop + 2) % 3]); };
  const Eigen::Vector2d a = flat(t[0]), b = flat(t[1]), c = flat(t[2]);
  const double turn = orient(a, b, c);
  const auto inside = [&](const Eigen::Vector2d& x) {
    const double s0 = orient(a, b, x) * turn, s1 = orient(b, c, x) * turn, s2 = orient(c, a, x) * turn;
    return s0 >= 0.0 && s1 >= 0.0 && s2 >= 0.0;
  };
  Segment s{flat(p), flat(q), 0, 1};
  if (inside(s.p) || inside(s.q)) return true;
  const Eigen::Vector2d corners[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    if (segmentsMeet(s, Segment{corners[k], corners[(k + 1) % 3], 2, 3})) return true;
  }
  return false;
}

// Segment pq against the closed triangle t.
bool segmentMeetsTriangle(const Point3& p, const Point3& q, const Point3 (&t)[3]) {
  const int sp = orient3d(t[0], t[1], t[2], p), sq = orient3d(t[0], t[1], t[2], q);
  if (sp == 0 && sq == 0) return coplanarSegmentMeetsTriangle(p, q, t);
  if (sp == sq) return false;
  // The line pq crosses the plane: inside the triangle iff it passes each edge on the same side (or on it).
  const int s0 = orient3d(p, q, t[0], t[1]), s1 = orient3d(p, q, t[1], t[2]), s2 = orient3d(p, q, t[2], t[0]);
  return !((s0 > 0 || s1 > 0 || s2 > 0) && (s0 < 0 || s1 < 0 || s2 < 0));
}

// Faces i and j (non-degenerate, distinct) meet other than along the vertices they share.
bool facesIntersect(const Cage& cage, int i, int j) {
  const auto corner = [&](int face, int k) -> Point3 { return cage.vertices.row(cage.faces(face, k)).transpose(); };
  int sharedI[3], sharedJ[3], shared = 0;
  for (int k = 0; k < 3; ++k) {
    for (int l = 0; l < 3; ++l) {
      if (cage.faces(i, k) == cage.faces(j, l)) sharedI[shared] = k, sharedJ[shared] = l, ++shared;
    }
  }
  const Point3 ti[3] = {corner(i, 0), corner(i, 1), corner(i, 2)}, tj[3] = {corner(j, 0), corner(j, 1), corner(j, 2)};
  if (shared == 0) {  // any contact counts
    for (int k = 0; k < 3; ++k) {
      if (segmentMeetsTriangle(ti[k], ti[(k + 1) % 3], tj) || segmentMeetsTriangle(tj[k], tj[(k + 1) % 3], ti))
        return true;
    }
    return false;
  }
  if (shared == 1) {
    // Both intersections with the other plane start at the shared vertex; they overlap beyond it iff the edge
    // opposite to it in one triangle meets the other triangle.
    const int k = sharedI[0], l = sharedJ[0];
    return segmentMeetsTriangle(ti[(k + 1) % 3], ti[(k + 2) % 3], tj) ||
           segmentMeetsTriangle(tj[(l + 1) % 3], tj[(l + 2) % 3], ti);
  }
  if (shared == 2) {
    // Across the shared edge the faces overlap only when folded flat onto each other: the far corners on the
    // same side of the edge, at an opening angle below kFoldTolerance.
    const Point3 o = ti[sharedI[0]], e = (ti[sharedI[1]] - o).normalized();
    const Point3 a = ti[3 - sharedI[0] - sharedI[1]] - o, b = tj[3 - sharedJ[0] - sharedJ[1]] - o;
    const Point3 pa = a - a.dot(e) * e, pb = b - b.dot(e) * e;
    return std::atan2(pa.cross(pb).norm(), pa.dot(pb)) <= CageReport::kFoldTolerance;
  }
  return false;  // the same three vertices: a non-manifold duplicate, reported as such
}

void findIntersections3d(const Cage& cage, CageReport& report) {
  std::vector<char> skip(cage.numFaces(), 0);
  for (const int j : report.degenerateFaces) skip[j] = 1;  // no plane to test against
  visitOverlappingFaces<3>(cage, skip, [&](int i, int j) {
    if (facesIntersect(cage, i, j)) report.intersectingFaces.push_back({i, j});
    return false;
  });
  std::sort(report.intersectingFaces.begin(), report.intersectingFaces.end());
}

// ---------------------------------------------------------------------------------------------------------------
// Messages
// ---------------------------------------------------------------------------------------------------------------

constexpr size_t kListedElements = 5;

template <typename T, typename Describe>
std::string listSome(const std::vector<T>& items, Describe describe) {
  std::ostringstream out;
  for (size_t k = 0; k < items.size() && k < kListedElements; ++k) out << (k ? ", " : "") << describe(items[k]);
  if (items.size() > kListedElements) out << " and " << items.size() - kListedElements << " more";
  return out.str();
}

std::string joinFaces(const std::vector<int>& faces) {
  std::ostringstream out;
  for (size_t k = 0; k < faces.size(); ++k) out << (k ? (k + 1 == faces.size() ? " and " : ", ") : "") << faces[k];
  return out.str();
}

std::string ridgeName(const CageReport& report, const CageReport::Ridge& ridge) {
  return report.dim == 3 ? "edge (" + std::to_string(ridge.a) + ", " + std::to_string(ridge.b) + ")"
                         : "vertex " + std::to_string(ridge.a);
}

std::string count(size_t n, const std::string& singular, const std::string& plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

}  // namespace

bool CageReport::valid() const {
  return numFaces > 0 && indicesValid() && closed() && manifold() && consistentlyOriented() && outward() && simple() &&
         degenerateFaces.empty() && duplicateVertices.empty() && unreferencedVertices.empty();
}

CageReport validateCage(const Cage& cage) {
  SOMICAGE_ASSERT(cage.dim() == 2 || cage.dim() == 3, "a cage is 2D or 3D");
  SOMICAGE_ASSERT(cage.faces.cols() == cage.dim(), "3D faces are triangles, 2D faces are edges");
  CageReport report;
  report.dim = cage.dim();
  report.numVertices = cage.numVertices();
  report.numFaces = cage.numFaces();
  report.diameter = cageDiameter(cage.vertices);
  for (int j = 0; j < cage.numFaces(); ++j) {
    const bool inRange =
        (cage.faces.row(j).array() >= 0).all() && (cage.faces.row(j).array() < cage.numVertices()).all();
    if (!inRange) report.invalidFaces.push_back(j);
  }
  if (!report.invalidFaces.empty()) return report;

  classifyRidges(cage, report);
  countComponents(cage, report);
  measureGeometry(cage, report);
  if (cage.dim() == 2) {
    findIntersection(cage, report);
  } else {
    findIntersections3d(cage, report);
  }
  return report;
}

std::vector<std::string> describeCageProblems(const CageReport& report) {
  std::vector<std::string> problems;
  const bool is3d = report.dim == 3;
  const std::string face = is3d ? "face" : "edge";
  if (!report.invalidFaces.empty()) {
    problems.push_back(listSome(report.invalidFaces, [&](int j) { return face + " " + std::to_string(j); }) +
                       " refer to vertices that do not exist (the cage has " + std::to_string(report.numVertices) +
                       " vertices): fix the vertex indices");
    return problems;
  }
  if (report.numFaces == 0) {
    problems.push_back(is3d ? "the cage has no faces: give a closed triangle mesh"
                            : "the polygon has no edges: give at least 3 vertices in order");
    return problems;
  }
  const auto ridgeWithFaces = [&](const CageReport::Ridge& r) {
    return ridgeName(report, r) + " (" + face + (r.faces.size() > 1 ? "s " : " ") + joinFaces(r.faces) + ")";
  };
  // A non-manifold edge first: a fin or a doubled face also leaves edges with one face, which are its symptom.
  if (!report.nonManifoldRidges.empty()) {
    problems.push_back(
        is3d ? "the cage is not edge-manifold: " + listSome(report.nonManifoldRidges, ridgeWithFaces) +
                   " belong to more than two faces; change the cage so that every edge has exactly two faces"
             : "the polygon is not simple: " + listSome(report.nonManifoldRidges, ridgeWithFaces) +
                   " joins more than two edges; every vertex of a polygon joins exactly two edges");
  }
  if (!report.boundaryRidges.empty()) {
    problems.push_back(
        is3d ? "the cage is not closed: " + count(report.boundaryRidges.size(), "edge has", "edges have") +
                   " only one face: " + listSome(report.boundaryRidges, ridgeWithFaces) +
                   "; fill the holes so that every edge has exactly two faces"
             : "the polygon is not closed: " + listSome(report.boundaryRidges, ridgeWithFaces) +
                   " ends an open chain; join the edges into one loop");
  }
  if (!report.misorientedRidges.empty()) {
    problems.push_back(
        is3d ? "the faces are not consistently oriented: " + listSome(report.misorientedRidges, ridgeWithFaces) +
                   " run through their common edge in the same direction; reverse the vertex order of one of them"
             : "the edges do not follow each other: at " + listSome(report.misorientedRidges, ridgeWithFaces) +
                   " two edges both start or both end; make every edge start where the previous one ends");
  }
  if (!is3d && report.components > 1) {
    problems.push_back("the polygon has " + std::to_string(report.components) +
                       " separate loops: a 2D cage is one simple polygon");
  }
  if (!is3d && !report.intersectingFaces.empty()) {
    problems.push_back("the polygon intersects itself: " +
                       listSome(report.intersectingFaces,
                                [](const std::array<int, 2>& p) {
                                  return "edges " + std::to_string(p[0]) + " and " + std::to_string(p[1]);
                                }) +
                       " cross, touch or overlap; move vertices so that no two edges meet except at shared ends");
  }
  if (!report.degenerateFaces.empty()) {
    problems.push_back(count(report.degenerateFaces.size(), face, face + "s") + " " +
                       (is3d ? "have (nearly) zero area" : "have (nearly) zero length") + ": " +
                       listSome(report.degenerateFaces, [&](int j) { return face + " " + std::to_string(j); }) +
                       "; remove them or move their vertices apart");
  }
  if (report.closed() && report.manifold() && report.consistentlyOriented() && !report.outward()) {
    std::ostringstream value, diameter;
    value << report.signedVolume;
    diameter << report.diameter;
    const std::string what = is3d ? "signed volume " : "signed area ";
    if (report.signedVolume < 0.0) {
      problems.push_back(
          is3d ? "the faces point inward (" + what + value.str() + "): reverse the vertex order of every face"
               : "the polygon is clockwise (" + what + value.str() + "): reverse the order of its vertices");
    } else {
      problems.push_back("the cage encloses (nearly) no " + std::string(is3d ? "volume" : "area") + " (" + what +
                         value.str() + " for a diameter of " + diameter.str() + "): " +
                         (is3d ? "its faces must bound a solid, with normals pointing out"
                               : "its vertices must go counter-clockwise around an area"));
    }
  }
  if (!report.duplicateVertices.empty()) {
    problems.push_back(count(report.duplicateVertices.size(), "pair", "pairs") + " of vertices at the same position: " +
                       listSome(report.duplicateVertices,
                                [](const std::array<int, 2>& p) {
                                  return "vertices " + std::to_string(p[0]) + " and " + std::to_string(p[1]);
                                }) +
                       "; merge them (the cage must not touch itself)");
  }
  if (!report.unreferencedVertices.empty()) {
    problems.push_back(count(report.unreferencedVertices.size(), "vertex is", "vertices are") + " not used by any " +
                       face + ": " +
                       listSome(report.unreferencedVertices, [](int i) { return "vertex " + std::to_string(i); }) +
                       "; remove them (a pose must then drop them too)");
  }
  return problems;
}

void requireValidCage(const CageReport& report, const std::string& source) {
  if (report.valid()) return;
  const std::vector<std::string> problems = describeCageProblems(report);
  const std::string more =
      problems.size() > 2   ? " (and " + std::to_string(problems.size() - 1) + " more problems)"
      : problems.size() > 1 ? " (and 1 more problem)"
                            : "";
  throw InputError(source, -1, "the cage cannot be used: " + problems.front() + more,
                   "run 'somicage check --cage " + source + "' for the full report");
}

std::vector<std::string> describeCageWarnings(const CageReport& report) {
  std::vector<std::string> warnings;
  if (report.dim == 3 && !report.intersectingFaces.empty()) {
    warnings.push_back("the cage intersects itself: " +
                       count(report.intersectingFaces.size(), "pair of faces meets", "pairs of faces meet") +
                       " away from their shared edges and vertices (" +
                       listSome(report.intersectingFaces,
                                [](const std::array<int, 2>& p) {
                                  return "faces " + std::to_string(p[0]) + " and " + std::to_string(p[1]);
                                }) +
                       "); points in the overlap count as inside twice and deform poorly: move the vertices apart");
  }
  return warnings;
}

}  // namespace somicage
