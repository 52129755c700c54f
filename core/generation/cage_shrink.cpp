#include "generation/cage_shrink.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/errors.h"
#include "generation/cage_geometry.h"

namespace somicage {

namespace {

using cage_geometry::Kernel;
using cage_geometry::minAngle;
using cage_geometry::Point;
using cage_geometry::SoupTree;
using cage_geometry::Triangles;
using cage_geometry::trianglesCross;

Point point(const Eigen::MatrixXd& vertices, int i) { return Point(vertices(i, 0), vertices(i, 1), vertices(i, 2)); }

class Shrinker {
 public:
  Shrinker(Cage& cage, const SoupTree& mesh, const ShrinkOptions& options)
      : cage_(cage), mesh_(mesh), options_(options), facesOf_(cage.numVertices()) {
    for (int j = 0; j < cage.numFaces(); ++j)
      for (int k = 0; k < 3; ++k) facesOf_[cage.faces(j, k)].push_back(j);
  }

  // Tries to bring vertex v toward its closest mesh point, as far as it can go (full step, then halves).
  bool move(int v) {
    const Point p = point(cage_.vertices, v);
    const Point closest = mesh_.closest_point(p);
    const double distance = std::sqrt(CGAL::squared_distance(p, closest));
    const double travel = distance - options_.clearance;
    if (!(travel > 1e-3 * options_.clearance)) return false;
    // Straight to the mesh, else inward along the normal (where the straight way is blocked by a neighbour).
    for (const Kernel::Vector_3& direction : {(closest - p) / distance, inwardNormal(v, p)})
      for (double step = travel; step > 0.05 * travel; step *= 0.5) {
        const Point q = p + step * direction;
        if (!(std::sqrt(mesh_.squared_distance(q)) >= options_.clearance)) continue;  // another part is nearer
        if (!acceptable(v, p, q)) continue;
        cage_.vertices.row(v) << q.x(), q.y(), q.z();
        return true;
      }
    return false;
  }

  // Flips the convex edges whose two triangles get a larger smallest angle by it (the surface only moves inward),
  // when exact tests prove that the flip
  // keeps the enclosure (the tetrahedron of the four corners, which the surface sweeps through, and the new faces
  // meet no mesh triangle; the new faces cross no other cage face; no fold). Returns the number of flips.
  int flipEdges() {
    int flips = 0;
    for (int f = 0; f < cage_.numFaces(); ++f)
      for (int k = 0; k < 3; ++k) flips += flip(f, cage_.faces(f, k), cage_.faces(f, (k + 1) % 3));
    return flips;
  }

 private:
  // The other face with the directed edge w -> u, or -1.
  int opposite(int f, int u, int w) const {
    for (int g : facesOf_[u])
      if (g != f)
        for (int k = 0; k < 3; ++k)
          if (cage_.faces(g, k) == w && cage_.faces(g, (k + 1) % 3) == u) return g;
    return -1;
  }

  // Face f = (u, w, x) and g = (w, u, y) become (u, y, x) and (y, w, x).
  bool flip(int f, int u, int w) {
    const int g = opposite(f, u, w);
    if (g < 0) return false;
    const int x = rotated(f, u)[2], y = rotated(g, w)[2];
    if (x == y) return false;
    for (int h : facesOf_[x])  // the edge x - y exists already: the flip would make it non-manifold
      if (cage_.faces(h, 0) == y || cage_.faces(h, 1) == y || cage_.faces(h, 2) == y) return false;
    const Point pu = point(cage_.vertices, u), pw = point(cage_.vertices, w), px = point(cage_.vertices, x),
                py = point(cage_.vertices, y);
    if (!(std::min(minAngle(pu, py, px), minAngle(py, pw, px)) >
          1.05 * std::min(minAngle(pu, pw, px), minAngle(pw, pu, py))))
      return false;
    const Kernel::Vector_3 normal = CGAL::cross_product(pw - pu, px - pu) + CGAL::cross_product(pu - pw, py - pw);
    if (!(CGAL::cross_product(py - pu, px - pu) * normal > 0 && CGAL::cross_product(pw - py, px - py) * normal > 0))
      return false;  // would fold
    const Kernel::Triangle_3 first(pu, py, px), second(py, pw, px);
    if (mesh_.do_intersect(first) || mesh_.do_intersect(second)) return false;
    const CGAL::Orientation side = CGAL::orientation(pu, pw, px, py);
    if (side == CGAL::POSITIVE) return false;  // a reflex edge: the flip would move the surface outward
    if (side == CGAL::NEGATIVE && mesh_.do_intersect(Kernel::Tetrahedron_3(pu, pw, px, py))) return false;
    if (crossesFaces(first, {f, g}) || crossesFaces(second, {f, g})) return false;
    cage_.faces.row(f) << u, y, x;
    cage_.faces.row(g) << y, w, x;
    removeFace(u, g), removeFace(w, f);
    facesOf_[y].push_back(f), facesOf_[x].push_back(g);
    return true;
  }

  void removeFace(int v, int f) {
    std::vector<int>& faces = facesOf_[v];
    faces.erase(std::find(faces.begin(), faces.end(), f));
  }

  // Minus the area-weighted normal of the faces around v, unit length.
  Kernel::Vector_3 inwardNormal(int v, const Point& p) const {
    Kernel::Vector_3 sum(0, 0, 0);
    for (int f : facesOf_[v]) {
      const std::array<int, 3> c = rotated(f, v);
      sum = sum + CGAL::cross_product(point(cage_.vertices, c[1]) - p, point(cage_.vertices, c[2]) - p);
    }
    const double length = std::sqrt(sum.squared_length());
    return length > 0 ? -sum / length : sum;
  }

  // The corners of face f with vertex v first, in the face's order.
  std::array<int, 3> rotated(int f, int v) const {
    int k = 0;
    while (cage_.faces(f, k) != v) ++k;
    return {v, cage_.faces(f, (k + 1) % 3), cage_.faces(f, (k + 2) % 3)};
  }

  bool acceptable(int v, const Point& p, const Point& q) const {
    const double minAngleRadians = options_.minAngleDegrees * M_PI / 180.0;
    std::vector<std::array<Point, 3>> made;
    for (int f : facesOf_[v]) {
      const std::array<int, 3> c = rotated(f, v);
      const Point a = point(cage_.vertices, c[1]), b = point(cage_.vertices, c[2]);
      if (!(CGAL::cross_product(a - p, b - p) * CGAL::cross_product(a - q, b - q) > 0)) return false;  // flips
      if (minAngle(q, a, b) < std::min(minAngleRadians, minAngle(p, a, b))) return false;
      const Kernel::Triangle_3 triangle(q, a, b);
      if (mesh_.do_intersect(triangle)) return false;
      if (CGAL::orientation(p, q, a, b) != CGAL::COPLANAR && mesh_.do_intersect(Kernel::Tetrahedron_3(p, q, a, b)))
        return false;  // the face would sweep over part of the mesh
      for (const std::array<Point, 3>& other : made)
        if (trianglesCross(triangle, other)) return false;
      if (crossesOtherFaces(v, triangle)) return false;
      made.push_back({q, a, b});
    }
    return true;
  }

  bool crossesOtherFaces(int v, const Kernel::Triangle_3& triangle) const {
    return crossesFaces(triangle, facesOf_[v]);
  }

  // Whether the triangle crosses a cage face other than `skip` (other than at shared corners).
  bool crossesFaces(const Kernel::Triangle_3& triangle, const std::vector<int>& skip) const {
    const CGAL::Bbox_3 box = triangle.bbox();
    for (int g = 0; g < cage_.numFaces(); ++g) {
      if (std::find(skip.begin(), skip.end(), g) != skip.end()) continue;
      const std::array<Point, 3> corners = {point(cage_.vertices, cage_.faces(g, 0)),
                                            point(cage_.vertices, cage_.faces(g, 1)),
                                            point(cage_.vertices, cage_.faces(g, 2))};
      if (!CGAL::do_overlap(box, corners[0].bbox() + corners[1].bbox() + corners[2].bbox())) continue;
      if (trianglesCross(triangle, corners)) return true;
    }
    return false;
  }

  Cage& cage_;
  const SoupTree& mesh_;
  const ShrinkOptions& options_;
  std::vector<std::vector<int>> facesOf_;
};

}  // namespace

int shrinkTowardMesh(Cage& cage, const Eigen::MatrixXd& meshVertices, const Eigen::MatrixXi& meshTriangles,
                     const ShrinkOptions& options, const ProgressCallback& progress) {
  const Triangles triangles = cage_geometry::triangleSoup(meshVertices, meshTriangles);
  SoupTree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  Shrinker shrinker(cage, tree, options);
  int moves = 0;
  for (int round = 0; round < options.rounds; ++round) {
    int moved = 0;
    for (int v = 0; v < cage.numVertices(); ++v) {
      moved += shrinker.move(v);
      if (!progress((round + double(v + 1) / cage.numVertices()) / options.rounds)) throw Cancelled();
    }
    moved += shrinker.flipEdges();  // better angles let the vertices move on
    moves += moved;
    if (moved == 0) break;
  }
  return moves;
}

}  // namespace somicage
